#include "nodes/nodeanalyzer.h"
#include "cache/analysiscache.h"
#include "cache/stagememo.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "nodes/generatedparameters.h"
#include "nodes/python/pythonnodeanalyzer.h"
#include "syntax/cppsyntax.h"
#include "workspace/workspacescanner.h"

#include <QHash>
#include <QSet>

#include <algorithm>

namespace rosarch {

namespace {

QString lastSegment(const QString &qualified)
{
    QString s = qualified;
    const qsizetype cpp = s.lastIndexOf(QLatin1String("::"));
    if (cpp >= 0)
        s = s.mid(cpp + 2);
    const qsizetype py = s.lastIndexOf(QLatin1Char('.'));
    if (py >= 0)
        s = s.mid(py + 1);
    return s;
}

QString stripGlobal(QString s)
{
    if (s.startsWith(QLatin1String("::")))
        s.remove(0, 2);
    return s;
}

void appendUnique(QStringList *list, const QString &value)
{
    if (!value.isEmpty() && !list->contains(value))
        list->append(value);
}

/// Links nodes to the build-file executables and plugins that start them.
class Linker
{
public:
    Linker(const Workspace &ws, QList<AtomicNode> *nodes, const QList<EntryPoint> &entryPoints,
           QList<Diagnostic> *diagnostics)
        : m_ws(ws), m_nodes(nodes), m_diagnostics(diagnostics)
    {
        for (const EntryPoint &e : entryPoints)
            m_entryPoints.insert(e.file, e);
        // The node classes by name, in the nodes' order (the linker changes no name).
        for (qsizetype i = 0; i < nodes->size(); ++i) {
            const AtomicNode &n = nodes->at(i);
            if (n.isPlugin())
                continue; // a pluginlib plugin is loaded by a node, never started itself
            m_byQualifiedName[stripGlobal(n.qualifiedName)].append(i);
            m_byClassName[n.className].append(i);
        }
    }

    void linkRegistration(const ComponentRegistration &r)
    {
        for (AtomicNode *n : byQualifiedName(r.pluginClass, QString()))
            appendUnique(&n->plugins, stripGlobal(r.pluginClass));
    }

    void link(const RosPackage &pkg, const Executable &exe)
    {
        QList<AtomicNode *> targets;
        QList<std::pair<AtomicNode *, NodeConstruction>> constructions;
        switch (exe.kind) {
        case Executable::Kind::ConsoleScript:
            targets = consoleScriptNodes(pkg, exe, &constructions);
            break;
        case Executable::Kind::CMakeExecutable:
            targets = nodesStartedFrom(pkg.name, exe.sources, QString(), &constructions);
            break;
        case Executable::Kind::ComponentPlugin:
            targets = byQualifiedName(exe.plugin, pkg.name);
            for (AtomicNode *n : std::as_const(targets))
                appendUnique(&n->plugins, stripGlobal(exe.plugin));
            break;
        }
        if (exe.kind == Executable::Kind::ComponentPlugin && exe.name.isEmpty())
            return;
        for (AtomicNode *n : std::as_const(targets))
            appendUnique(&n->executables, exe.name);
        for (auto &[n, k] : constructions) {
            k.executable = exe.name;
            n->constructions.append(k);
        }
        if (targets.isEmpty() && exe.kind != Executable::Kind::ComponentPlugin) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Info;
            d.code = QStringLiteral("executable-without-node");
            d.message =
                QStringLiteral(
                    "Executable '%1' of package %2 starts no node class found in the workspace.")
                    .arg(exe.name, pkg.name);
            d.evidence = exe.evidence;
            m_diagnostics->append(d);
        }
    }

private:
    QList<AtomicNode *> byQualifiedName(const QString &qualified, const QString &preferredPackage)
    {
        const QString wanted = stripGlobal(qualified);
        // Those named exactly, else those whose class has the name's last segment.
        QList<qsizetype> indices = m_byQualifiedName.value(wanted);
        if (indices.isEmpty())
            indices = m_byClassName.value(lastSegment(wanted));
        QList<AtomicNode *> found;
        for (const qsizetype i : std::as_const(indices))
            found.append(&(*m_nodes)[i]);
        if (found.size() > 1 && !preferredPackage.isEmpty()) {
            QList<AtomicNode *> same;
            for (AtomicNode *n : std::as_const(found))
                if (n->packageName == preferredPackage)
                    same.append(n);
            if (!same.isEmpty())
                found = same;
        }
        return found;
    }

    /// Node classes an entry point in `file` instantiates, else those defined in it. The
    /// entry points' constructions of them are added to `constructions`, with their class.
    QList<AtomicNode *>
    nodesStartedFrom(const QString &pkg, const QStringList &files, const QString &function,
                     QList<std::pair<AtomicNode *, NodeConstruction>> *constructions = nullptr)
    {
        QList<AtomicNode *> out;
        for (const QString &file : files) {
            for (auto it = m_entryPoints.constFind(file);
                 it != m_entryPoints.cend() && it.key() == file; ++it) {
                if (!function.isEmpty() && it->function != function)
                    continue;
                for (const QString &cls : it->instantiatedClasses)
                    for (AtomicNode *n : classesOf(cls, pkg, files))
                        if (!out.contains(n))
                            out.append(n);
                for (const NodeConstruction &k : it->constructions)
                    if (constructions)
                        for (AtomicNode *n : classesOf(k.className, pkg, files))
                            constructions->append({n, k});
            }
        }
        if (!out.isEmpty())
            return out;
        for (AtomicNode &n : *m_nodes) {
            if (n.isPlugin())
                continue; // a pluginlib plugin is loaded by a node, never started itself
            for (const QString &file : files) {
                if (n.sourceFiles.contains(file) && (!n.procedural || function.isEmpty()) &&
                    !out.contains(&n))
                    out.append(&n);
            }
        }
        return out;
    }

    /// The classes of that name an executable built from `files` starts: of several classes of
    /// one name in a package (one per example program, as ros2/examples writes them), those
    /// defined in the executable's own sources, else those a header defines (a class defined
    /// in another program's source file is not visible here).
    QList<AtomicNode *> classesOf(const QString &qualified, const QString &pkg,
                                  const QStringList &files)
    {
        const QList<AtomicNode *> found = byQualifiedName(qualified, pkg);
        const auto pick = [&](const QList<AtomicNode *> &candidates) {
            QList<AtomicNode *> own, visible;
            for (AtomicNode *n : candidates) {
                if (files.contains(n->evidence.file))
                    own.append(n);
                else if (cppsyntax::isHeaderPath(n->evidence.file))
                    visible.append(n);
            }
            return !own.isEmpty() ? own : visible;
        };
        if (QList<AtomicNode *> chosen = pick(found); !chosen.isEmpty())
            return chosen;
        // Named without its namespace (`using ns::Beacon;`): a class of that name in a header
        // of the package, rather than one another program's source file defines.
        QList<AtomicNode *> sameName;
        for (const qsizetype i : m_byClassName.value(lastSegment(stripGlobal(qualified))))
            if ((*m_nodes)[i].packageName == pkg)
                sameName.append(&(*m_nodes)[i]);
        if (QList<AtomicNode *> chosen = pick(sameName); !chosen.isEmpty())
            return chosen;
        return found;
    }

    QList<AtomicNode *>
    consoleScriptNodes(const RosPackage &pkg, const Executable &exe,
                       QList<std::pair<AtomicNode *, NodeConstruction>> *constructions)
    {
        const qsizetype colon = exe.target.indexOf(QLatin1Char(':'));
        const QString module = exe.target.left(colon);
        const QString function = exe.target.mid(colon + 1);
        const QString modulePath = QString(module).replace(QLatin1Char('.'), QLatin1Char('/'));
        const QString prefix = pkg.path.isEmpty() ? QString() : pkg.path + QLatin1Char('/');
        QStringList files;
        for (const SourceFile &f : m_ws.files) {
            if (f.language != SourceFile::Language::Python || !f.path.startsWith(prefix))
                continue;
            const QString rel = f.path.mid(prefix.size());
            if (rel == modulePath + QStringLiteral(".py") ||
                rel.endsWith(QLatin1Char('/') + modulePath + QStringLiteral(".py")) ||
                rel == modulePath + QStringLiteral("/__init__.py"))
                files.append(f.path);
        }
        return nodesStartedFrom(pkg.name, files, function, constructions);
    }

    const Workspace &m_ws;
    QList<AtomicNode> *m_nodes;
    QList<Diagnostic> *m_diagnostics;
    QMultiHash<QString, EntryPoint> m_entryPoints;
    QHash<QString, QList<qsizetype>> m_byQualifiedName; ///< without a leading "::"
    QHash<QString, QList<qsizetype>> m_byClassName;
};

/// A construction keeps the ports its arguments name differently from the class, each with
/// the id of the class's port made at the same call. One that decides nothing the class does
/// not (its name, its ports) is dropped, unless its executable builds the class more than once:
/// then each construction is an instance.
void nameConstructedPorts(AtomicNode *n)
{
    QHash<QString, int> perExecutable;
    for (const NodeConstruction &k : std::as_const(n->constructions))
        ++perExecutable[k.executable];
    for (NodeConstruction &k : n->constructions) {
        QList<Port> named;
        for (Port p : std::as_const(k.ports)) {
            const auto same = std::find_if(n->ports.cbegin(), n->ports.cend(), [&](const Port &c) {
                // one call may make two ports: a camera's image and its info; a class
                // template's port is typed where it is built (`MessageT` in the class)
                return c.kind == p.kind && c.evidence == p.evidence &&
                       (c.type == p.type || !c.type.contains(u'/'));
            });
            if (same == n->ports.cend() || !p.isResolved() ||
                (same->name == p.name && same->nameOrigin == p.nameOrigin && same->type == p.type))
                continue;
            p.id = same->id;
            p.via = same->via;
            p.viaEvidence = same->viaEvidence;
            named.append(p);
        }
        k.ports = named;
    }
    n->constructions.removeIf([&](const NodeConstruction &k) {
        return k.ports.isEmpty() && (k.nodeName.isEmpty() || k.nodeName == n->nodeName) &&
               k.guard.isEmpty() && perExecutable.value(k.executable) < 2;
    });
}

bool diagnosticLess(const Diagnostic &a, const Diagnostic &b)
{
    return std::tie(a.evidence.file, a.evidence.line, a.code) <
           std::tie(b.evidence.file, b.evidence.line, b.code);
}

/// One port per kind, name, type and place: a procedural node that reaches a helper object twice
/// (two objects of one class in main) would list the helper's ports once per object, the same
/// ports (a model invariant). The first is kept.
void removeRepeatedPorts(QList<Port> *ports)
{
    QSet<QString> seen;
    ports->removeIf([&](const Port &p) {
        const QString key = QStringLiteral("%1\n%2\n%3\n%4\n%5:%6:%7")
                                .arg(int(p.kind))
                                .arg(p.name, p.nameExpression, p.type, p.evidence.file)
                                .arg(p.evidence.line)
                                .arg(p.evidence.column);
        if (seen.contains(key))
            return true;
        seen.insert(key);
        return false;
    });
}

bool portLess(const Port &a, const Port &b)
{
    return std::tie(a.evidence.file, a.evidence.line, a.evidence.column) <
           std::tie(b.evidence.file, b.evidence.line, b.evidence.column);
}

AtomicNodeList analyse(const Workspace &workspace, const StageControl &control)
{
    AtomicNodeList list;
    list.workspaceRoot = workspace.root;
    list.packages = workspace.packages;
    list.diagnostics = workspace.diagnostics;

    // One progression for the stage: the Python files, then the C++ files after them.
    int pythonFiles = 0;
    int cppFiles = 0;
    for (const SourceFile &f : workspace.files) {
        pythonFiles += f.language == SourceFile::Language::Python;
        cppFiles += f.language == SourceFile::Language::Cpp;
    }
    // The C++ macro index is built while the Python files are analysed.
    CppNodeAnalyzer cpp(workspace);
    const StageControl cppPart = control.part(pythonFiles, pythonFiles + cppFiles);
    cpp.prepare(cppPart);
    LanguageAnalysis analyses[] = {
        PythonNodeAnalyzer(workspace).analyze(control.part(0, pythonFiles + cppFiles)),
        cpp.analyze(cppPart)};
    QList<EntryPoint> entryPoints;
    QList<ComponentRegistration> registrations;
    for (LanguageAnalysis &a : analyses) {
        list.nodes.append(a.nodes);
        entryPoints.append(a.entryPoints);
        registrations.append(a.registrations);
        list.diagnostics.append(a.diagnostics);
        list.helperParameters.append(a.helperParameters);
    }
    if (control.isCanceled()) {
        list.canceled = true;
        return list;
    }
    Linker linker(workspace, &list.nodes, entryPoints, &list.diagnostics);
    for (const ComponentRegistration &r : std::as_const(registrations))
        linker.linkRegistration(r);
    for (const RosPackage &pkg : workspace.packages)
        for (const Executable &exe : pkg.executables)
            linker.link(pkg, exe);
    GeneratedParameters::apply(workspace, &list);

    std::sort(list.nodes.begin(), list.nodes.end(), [](const AtomicNode &a, const AtomicNode &b) {
        return std::tie(a.packageName, a.className, a.qualifiedName, a.evidence.file) <
               std::tie(b.packageName, b.className, b.qualifiedName, b.evidence.file);
    });
    int nextId = 1;
    for (AtomicNode &n : list.nodes) {
        n.id = QStringLiteral("arc_%1").arg(nextId++);
        std::sort(n.executables.begin(), n.executables.end());
        std::sort(n.plugins.begin(), n.plugins.end());
        std::stable_sort(n.ports.begin(), n.ports.end(), portLess);
        removeRepeatedPorts(&n.ports);
        QHash<PortKind, int> counters;
        for (Port &p : n.ports)
            p.id = portIdPrefix(p.kind) + QString::number(++counters[p.kind]);
        nameConstructedPorts(&n);
    }
    std::stable_sort(list.diagnostics.begin(), list.diagnostics.end(), diagnosticLess);
    return list;
}

/// The key of stage 1's result: the scan, and every file of it with its content (the stage
/// reads the C++ and Python files, and the headers and CMakeLists.txt files for macros; all of
/// them are there, so a change to any file of the workspace is a new key).
QByteArray memoKey(const Workspace &workspace, const StageControl &control, AnalysisCache &cache)
{
    QStringList paths;
    paths.reserve(workspace.files.size());
    for (const SourceFile &f : workspace.files)
        paths.append(f.path);
    return AnalysisCache::key({"stage1", stagememo::workspacePart(workspace, control, true),
                               cache.digests().digestAll(workspace.root, paths)});
}

} // namespace

AtomicNodeList NodeAnalyzer::run(const Workspace &workspace, const StageControl &control,
                                 const std::function<void()> &analysing, QByteArray *resultKey)
{
    AnalysisCache &cache = AnalysisCache::of(control);
    // What this process decoded in the last run of stage 1 stays for this one (the long-lived
    // worker's next run); what that run did not use is dropped.
    cache.startRun({QStringLiteral("stage1"), QStringLiteral("cppmacros"),
                    QStringLiteral("cppmanifest"), QStringLiteral("cpp"),
                    QStringLiteral("python")});
    const QByteArray key = cache.isEnabled() ? memoKey(workspace, control, cache) : QByteArray();
    std::optional<AtomicNodeList> list;
    if (!key.isEmpty())
        list = stagememo::load<AtomicNodeList>(cache, QStringLiteral("stage1"), key);
    if (!list) {
        if (analysing)
            analysing();
        list = analyse(workspace, control);
        if (!key.isEmpty() && !list->canceled)
            cache.store(QStringLiteral("stage1"), key, cachecodec::encode(*list));
    }
    if (resultKey)
        *resultKey = list->canceled ? QByteArray() : key;
    cache.flush();
    if (const std::optional<Diagnostic> problem = cache.takeProblem()) {
        list->diagnostics.append(*problem);
        std::stable_sort(list->diagnostics.begin(), list->diagnostics.end(), diagnosticLess);
    }
    return std::move(*list);
}

void NodeAnalyzer::warmUp(const Workspace &workspace, const StageControl &control)
{
    // The analysis without the stage's memo: what it loads stays in memory for the next run
    // (no startRun(), which would drop what the last run used). A file changed since that run
    // is analysed and stored as any run would.
    AnalysisCache &cache = AnalysisCache::of(control);
    if (cache.isEnabled() && !control.isCanceled())
        analyse(workspace, control);
}

AtomicNodeList recoverAtomicNodes(const QString &root, const StageControl &control)
{
    const Workspace ws = WorkspaceScanner::scan(root, control);
    return NodeAnalyzer::run(ws, control);
}

} // namespace rosarch
