#include "executablesystems.h"
#include "classifierruns.h"
#include "launchexecutor.h"
#include "nodeclasses.h"
#include "rosnames.h"

#include <QHash>

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

void addExecutableSystems(const Workspace &workspace, const AtomicNodeList &nodes,
                          LaunchDependencies *out)
{
    const NodeClasses classes(nodes);
    QHash<QString, LaunchFileDescription> descriptions;
    struct System
    {
        QString file;
        QString package;
        QString executable;
    };
    QList<System> systems;
    for (const RosPackage &package : workspace.packages)
        for (const Executable &exe : package.executables) {
            if (exe.kind == Executable::Kind::ComponentPlugin ||
                classes.started(package.name, exe.name, false).size() < 2)
                continue;
            const QString file = mainFile(workspace, package, exe);
            if (file.isEmpty() || descriptions.contains(file))
                continue; // two executables of one main: the first names the system
            LaunchAction node;
            node.kind = LaunchAction::Kind::Node;
            node.package = Substitution::literal(package.name);
            node.executable = Substitution::literal(exe.name);
            node.evidence = exe.evidence;
            LaunchFileDescription d;
            d.file = file;
            d.actions.append(node);
            descriptions.insert(file, d);
            systems.append({file, package.name, exe.name});
        }
    if (systems.isEmpty())
        return;
    LaunchDependencies made;
    LaunchExecutor executor(
        workspace, nodes,
        [&descriptions](const QString &file) -> const LaunchFileDescription * {
            const auto it = descriptions.constFind(file);
            return it == descriptions.cend() ? nullptr : &*it;
        },
        &made);
    executor.setIdPrefix(QStringLiteral("c"));
    for (const System &s : std::as_const(systems)) {
        const qsizetype first = made.instances.size();
        executor.runRoot(s.file, {}, QLatin1String(RosNames::kClassifierScope));
        for (qsizetype i = first; i < made.instances.size(); ++i) {
            made.instances[i].format = QStringLiteral("executable");
            made.instances[i].type = s.executable;
            made.instances[i].package = s.package;
        }
    }
    ClassifierRuns::append(out, std::move(made));
}

} // namespace rosarch
