#include "launch/executablesystems.h"
#include "launch/nodeclasses.h"

namespace rosarch {

namespace {

/// The file `ros2 run` starts the executable from: a CMake target's first source (its main),
/// a console script's module; "" when neither is known.
QString mainFile(const Workspace &workspace, const RosPackage &package, const Executable &exe)
{
    if (exe.kind == Executable::Kind::CMakeExecutable)
        return exe.sources.value(0);
    if (exe.kind != Executable::Kind::ConsoleScript)
        return {};
    const QString module = exe.target.left(exe.target.indexOf(QLatin1Char(':')));
    const QString modulePath =
        QString(module).replace(QLatin1Char('.'), QLatin1Char('/')) + QStringLiteral(".py");
    const QString prefix = package.path.isEmpty() ? QString() : package.path + QLatin1Char('/');
    for (const SourceFile &f : workspace.files)
        if (f.language == SourceFile::Language::Python && f.path.startsWith(prefix) &&
            (f.path == prefix + modulePath || f.path.endsWith(QLatin1Char('/') + modulePath)))
            return f.path;
    return {};
}

} // namespace

ExecutableSystems::ExecutableSystems(const Workspace &workspace, const AtomicNodeList &nodes)
{
    const NodeClasses classes(nodes);
    for (const RosPackage &package : workspace.packages)
        for (const Executable &exe : package.executables) {
            if (exe.kind == Executable::Kind::ComponentPlugin)
                continue;
            // nodes, not classes: a class built twice is two
            if (NodeClasses::starts(classes.started(package.name, exe.name, false), exe.name)
                    .size() < 2)
                continue;
            const QString file = mainFile(workspace, package, exe);
            if (file.isEmpty() || m_systems.contains(file))
                continue; // two executables of one main: the first names the system
            LaunchAction node;
            node.kind = LaunchAction::Kind::Node;
            node.package = Substitution::literal(package.name);
            node.executable = Substitution::literal(exe.name);
            node.evidence = exe.evidence;
            System s{package.name, exe.name, {}};
            s.description.file = file;
            s.description.actions.append(node);
            m_systems.insert(file, s);
            m_files.append(file);
        }
}

const LaunchFileDescription *ExecutableSystems::find(const QString &file) const
{
    const auto it = m_systems.constFind(file);
    return it == m_systems.cend() ? nullptr : &it->description;
}

void ExecutableSystems::mark(QList<LaunchFileInstance> *instances) const
{
    for (LaunchFileInstance &i : *instances)
        if (const auto it = m_systems.constFind(i.file); it != m_systems.cend()) {
            i.format = QStringLiteral("executable");
            i.type = it->executable;
            i.package = it->package;
        }
}

} // namespace rosarch
