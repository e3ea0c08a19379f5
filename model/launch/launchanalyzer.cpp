#include "launch/launchanalyzer.h"
#include "cache/analysiscache.h"
#include "cache/evidenceshift.h"
#include "cache/stagememo.h"
#include "interfaces/interfacemodel.h"
#include "launch/classifierruns.h"
#include "launch/executablesystems.h"
#include "launch/launchexecutor.h"
#include "launch/launchfileindex.h"
#include "launch/launchreadahead.h"
#include "launch/python/pythonlaunchreader.h"
#include "launch/xmlyaml/xmllaunchreader.h"
#include "launch/xmlyaml/yamllaunchreader.h"
#include "workspace/sourcereader.h"
#include "workspace/workspacescanner.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <map>

namespace rosarch {

namespace {

/// Each launch file of the system analysed on its own, with its declared defaults, in the
/// classifier scope: what its CCD shows (blueprint §1), in the order the system reaches them.
void runClassifiers(ClassifierRuns &runs, const LaunchExecutor &system, LaunchDependencies *out)
{
    QStringList files;
    QSet<QString> done;
    for (const LaunchFileInstance &i : std::as_const(out->instances))
        if (!i.file.isEmpty() && !done.contains(i.file)) {
            done.insert(i.file);
            files.append(i.file);
        }
    runs.finish(files, out, &system);
}

/// What the workspace's RViz configurations display, read the way rviz2's interface model
/// reads the configuration its `-d` names; names as written (relative ones are relative to
/// wherever rviz2 runs).
QList<Port> viewedTopics(const Workspace &workspace, QList<Diagnostic> *diagnostics)
{
    QList<Port> out;
    const InterfaceModel *rviz =
        InterfaceModels::builtIn().executable(QStringLiteral("rviz2"), QStringLiteral("rviz2"));
    if (!rviz)
        return out;
    const SourceReader reader(workspace.root);
    for (const SourceFile &f : workspace.files) {
        if (!f.path.endsWith(QLatin1String(".rviz")))
            continue;
        QByteArray content;
        if (!reader.read(f.path, &content, diagnostics))
            continue;
        const QList<Port> read = rviz->portsFromConfig(content, f.path, 1);
        if (read.size() >= InterfaceModel::kMaxConfigPorts) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            d.code = QStringLiteral("launch-evaluation-limit");
            d.message = QStringLiteral("%1 names more than %2 topics; the first %2 are taken as "
                                       "displayed (observability outputs), the rest are not.")
                            .arg(f.path)
                            .arg(InterfaceModel::kMaxConfigPorts);
            d.evidence = Evidence::startOf(f.path);
            diagnostics->append(d);
        }
        for (const Port &p : read)
            if (p.kind == PortKind::Subscriber && !p.name.startsWith(QLatin1Char('~')))
                out.append(p);
    }
    return out;
}

/// The index of the launch files, from what `readAhead` read when it did.
/// The finding for a namespace that the files an action includes push again, for each of
/// the values it pushes (one per robot, say), at the first push: that is where the namespace
/// is pushed and also passed down, as a rule.
Diagnostic doubledNamespaceFinding(const QList<const LaunchExecutor::DoubledNamespace *> &all)
{
    QStringList pushed, result;
    QList<Evidence> again;
    for (const LaunchExecutor::DoubledNamespace *dn : all) {
        if (!result.contains(dn->result)) {
            pushed << dn->pushed;
            result << dn->result;
        }
        if (!again.contains(dn->evidence))
            again << dn->evidence;
    }
    std::sort(again.begin(), again.end(), [](const Evidence &a, const Evidence &b) {
        return std::tie(a.file, a.line) < std::tie(b.file, b.line);
    });
    const Evidence &site = again.front();
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("namespace-doubled");
    d.message =
        QStringLiteral("The namespace %1 pushed here is pushed again by %2:%3%4, a file "
                       "this one includes, so its nodes run in %5: ROS 2 nests pushed "
                       "namespaces. Push it once: drop this push, or stop passing the "
                       "namespace down as an argument.")
            .arg(pushed.join(QStringLiteral(" or ")), site.file)
            .arg(site.line)
            .arg(again.size() > 1 ? QStringLiteral(" (and %1 more places)").arg(again.size() - 1)
                                  : QString())
            .arg(result.join(QStringLiteral(" or ")));
    d.evidence = all.front()->first;
    for (const Evidence &e : std::as_const(again))
        d.related.append({QStringLiteral("pushes %1 again").arg(pushed.front()), e});
    return d;
}

LaunchFileIndex indexOf(const Workspace &workspace, const StageControl &control,
                        LaunchReadAhead *readAhead, QList<Diagnostic> *diagnostics)
{
    if (readAhead)
        if (std::optional<QList<LaunchFileRead>> reads = readAhead->take())
            return LaunchFileIndex(workspace, std::move(*reads), control, diagnostics);
    return LaunchFileIndex(workspace, control, diagnostics);
}

LaunchDependencies analyse(const Workspace &workspace, const AtomicNodeList &nodes,
                           const LaunchOptions &options, const StageControl &control,
                           LaunchReadAhead *readAhead)
{
    LaunchDependencies out;
    const LaunchFileIndex index = indexOf(workspace, control, readAhead, &out.diagnostics);
    if (control.isCanceled()) {
        out.canceled = true;
        return out;
    }
    AnalysisCache &cache = AnalysisCache::of(control);
    if (const std::optional<Diagnostic> problem = cache.takeProblem())
        out.diagnostics.append(*problem);
    out.launchFiles = index.files();
    const ExecutableSystems executables(workspace, nodes);
    const LaunchExecutor::Loader loader = [&](const QString &f) {
        const LaunchFileDescription *d = index.find(f);
        return d ? d : executables.find(f);
    };
    LaunchExecutor executor(workspace, nodes, loader, &out);
    // The files' own runs begin after the system's, from its executor: begun on the pool during
    // them, with cold caches, they read the same parameter files and resolve the same includes
    // again, and took the system's runs longer on two cores than they saved (nav2).
    ClassifierRuns classifiers(workspace, nodes, loader, control);

    QStringList roots;
    if (!options.rootFile.isEmpty()) {
        if (index.find(options.rootFile)) {
            roots << options.rootFile;
            out.entryPoints << options.rootFile;
        } else {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Error;
            d.code = QStringLiteral("no-such-launch-file");
            d.message =
                QStringLiteral(
                    "The chosen root launch file %1 is not a launch file of this workspace.")
                    .arg(options.rootFile);
            out.diagnostics.append(d);
        }
    } else {
        // Top-level launch files: those no other launch file includes with its defaults. Of
        // these, the entry points are those no file includes under any condition either.
        QSet<QString> included, conditional;
        for (const QString &f : std::as_const(out.launchFiles)) {
            QStringList underCondition;
            for (const QString &inc : executor.directIncludes(f, &underCondition))
                if (inc != f)
                    included.insert(inc);
            for (const QString &inc : std::as_const(underCondition))
                if (inc != f)
                    conditional.insert(inc);
        }
        for (const QString &f : std::as_const(out.launchFiles))
            if (!included.contains(f)) {
                roots << f;
                if (!conditional.contains(f))
                    out.entryPoints << f;
            }
    }
    for (const QString &root : std::as_const(roots)) {
        if (control.isCanceled()) {
            out.canceled = true;
            return out;
        }
        const FileWork work(control, root);
        if (!work.skip(&out.diagnostics))
            executor.runRoot(root, options.arguments);
    }
    if (options.rootFile.isEmpty()) {
        // Files only reachable through a cycle have no top-level includer: run them as roots too.
        QSet<QString> reached;
        for (const LaunchFileInstance &i : std::as_const(out.instances))
            reached.insert(i.file);
        for (const QString &f : std::as_const(out.launchFiles))
            if (!reached.contains(f)) {
                if (control.isCanceled()) {
                    out.canceled = true;
                    return out;
                }
                const FileWork work(control, f);
                if (!work.skip(&out.diagnostics))
                    executor.runRoot(f, options.arguments);
                for (const LaunchFileInstance &i : std::as_const(out.instances))
                    reached.insert(i.file);
            }
    }
    if (options.rootFile.isEmpty()) {
        // Executables that build their nodes in their own code are systems too.
        for (const QString &f : executables.files()) {
            if (control.isCanceled()) {
                out.canceled = true;
                return out;
            }
            executor.runRoot(f, options.arguments);
            out.entryPoints << f;
        }
        out.entryPoints.sort();
    }
    runClassifiers(classifiers, executor, &out);
    executables.mark(&out.instances);
    executables.mark(&out.classifierInstances);
    out.viewedTopics = viewedTopics(workspace, &out.diagnostics);
    out.externals = options.externals;
    // Canceled while the files ran on their own: their lists are incomplete, so the result
    // is not one to keep (nor to store as stage 2's memo).
    if (control.isCanceled()) {
        out.canceled = true;
        return out;
    }
    // The same problem met through two include chains is one diagnostic.
    Diagnostic::removeDuplicates(&out.diagnostics);
    // Findings about an include site: one per site however many systems reach it (a file
    // included by 46 roots is one finding with 46 contexts, as stage 3's checks do it).
    QHash<QString, const LaunchFileInstance *> byId;
    for (const LaunchFileInstance &i : std::as_const(out.instances))
        byId.insert(i.id, &i);
    QHash<QString, qsizetype> seen;
    const auto rootOf = [&](const LaunchFileInstance &i) {
        const LaunchFileInstance *root = &i;
        // Bounded: parent ids form a tree, but a broken one must not loop.
        for (qsizetype up = 0; up < out.instances.size() && !root->parentId.isEmpty(); ++up) {
            const LaunchFileInstance *parent = byId.value(root->parentId);
            if (!parent)
                break;
            root = parent;
        }
        return root;
    };
    auto addAtSite = [&](Diagnostic d, const LaunchFileInstance &i) {
        const LaunchFileInstance *root = rootOf(i);
        const QString system = root->file.isEmpty() ? root->type : root->file;
        const QString key = d.key() + QLatin1Char('\n') + QString::number(d.evidence.line);
        if (const auto it = seen.constFind(key); it != seen.cend()) {
            QStringList &contexts = out.diagnostics[*it].contexts;
            if (!contexts.contains(system))
                contexts.append(system);
            return;
        }
        d.contexts = {system};
        seen.insert(key, out.diagnostics.size());
        out.diagnostics.append(d);
    };
    // An include that names no launch file of the workspace (and no package outside it) is
    // said: its nodes are missing from the system.
    for (const LaunchFileInstance &i : std::as_const(out.instances))
        if (!i.external && i.file.isEmpty() && !i.parentId.isEmpty() && i.active) {
            QString written = i.type;
            for (const Unresolved &u : i.unresolved)
                if (!u.expression.isEmpty())
                    written = u.expression;
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            d.code = QStringLiteral("no-such-launch-file");
            d.message =
                QStringLiteral("The included launch file %1 was not found in the workspace; "
                               "the nodes it would start are missing.")
                    .arg(written);
            d.evidence = i.evidence;
            addAtSite(d, i);
        }
    // External includes are listed too, so a headless run shows what was not followed.
    for (const LaunchFileInstance &i : std::as_const(out.instances))
        if (i.external) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Info;
            d.code = QStringLiteral("external-include");
            d.message =
                QStringLiteral("Include of %1 from package %2, which is not in the workspace.")
                    .arg(i.type, i.package);
            if (!i.interfaceModel.isEmpty())
                d.message += QStringLiteral(" The interface model %1 gives the ports of its nodes.")
                                 .arg(i.interfaceModel);
            d.evidence = i.evidence;
            addAtSite(d, i);
        }
    // A namespace pushed twice, in the systems the checks judge (blueprint §1, "Checks run on
    // entry points"): one finding per site, with the systems that reach it.
    // One finding per first push, for all its values (one per robot of a loop) and for all
    // the places that push them again.
    QMap<QString, QList<const LaunchExecutor::DoubledNamespace *>> doubledAt;
    QHash<QString, const LaunchFileInstance *> doubledIn;
    for (const LaunchExecutor::DoubledNamespace &dn : executor.doubledNamespaces())
        if (const LaunchFileInstance *i = byId.value(dn.launchFileInstance))
            if (out.entryPoints.isEmpty() || out.entryPoints.contains(rootOf(*i)->file)) {
                const QString key = QStringLiteral("%1:%2").arg(dn.first.file).arg(dn.first.line);
                doubledAt[key].append(&dn);
                doubledIn.insert(key + QLatin1Char('\n') + rootOf(*i)->file, i);
            }
    for (auto it = doubledIn.cbegin(); it != doubledIn.cend(); ++it)
        addAtSite(doubledNamespaceFinding(doubledAt.value(it.key().section(u'\n', 0, 0))),
                  *it.value());
    return out;
}

/// Exactly what the launch executor uses of stage 1's result (NodeClasses,
/// LaunchExecutor::executeNode, effectiveParameters): each class's id, name, package,
/// executables, plugins, lifecycle, compile type, node name, child nodes, and the ports whose
/// parameters give defaults, with the files of their evidence; the evidence itself goes to
/// `locations`, in order. No other source location: an edit that moves lines of a node's file and
/// changes none of this leaves stage 2's result as it was but for these locations (EvidenceShift).
QByteArray nodesPart(const AtomicNodeList &nodes, QList<Evidence> *locations)
{
    QByteArray bytes;
    QDataStream s(&bytes, QIODevice::WriteOnly);
    s.setVersion(QDataStream::Qt_6_4);
    s << quint32(nodes.nodes.size());
    for (const AtomicNode &n : nodes.nodes) {
        s << n.id << n.className << n.qualifiedName << n.packageName << n.executables << n.plugins
          << n.lifecycle << qint32(n.compileType) << n.nodeName << n.procedural
          << n.pluginInterface;
        for (const ChildNode &c : n.children) { // a child instance cites its construction
            s << quint8(3) << c.className << c.nodeName << c.nameSpace << c.evidence.file;
            locations->append(c.evidence);
        }
        for (const NodeConstruction &k : n.constructions) { // an instance per construction
            s << quint8(4) << k.executable << k.nodeName << k.guard << k.evidence.file;
            locations->append(k.evidence);
            for (const Port &p : k.ports)
                s << p.id << p.name << qint32(p.nameOrigin) << p.parameter;
        }
        for (const Port &p : n.ports) {
            if (p.nameOrigin == NameOrigin::Parameter && !p.parameter.isEmpty()) {
                s << quint8(1) << p.parameter << p.name << p.evidence.file;
                locations->append(p.evidence);
            }
            if (!p.guardParameter.isEmpty()) {
                s << quint8(2) << p.guardParameter << p.guardDefault << p.evidence.file;
                locations->append(p.evidence);
            }
        }
        s << quint8(0);
    }
    return bytes;
}

/// The files the result read that are not files of the scan (a parameter file of another
/// extension), each with its digest: checked before a memo is used.
using ExtraFiles = QList<std::pair<QString, QByteArray>>;

ExtraFiles extraFiles(const Workspace &workspace, const LaunchDependencies &out,
                      FileDigests &digests)
{
    QSet<QString> scanned;
    for (const SourceFile &f : workspace.files)
        scanned.insert(f.path);
    QSet<QString> seen;
    ExtraFiles extra;
    for (const QList<NodeInstance> *list : {&out.nodes, &out.classifierNodes})
        for (const NodeInstance &n : *list) {
            QStringList files{n.modelConfig}; // an interface model's configuration file
            for (const ParameterSetting &p : n.effectiveParameters)
                files << p.file;
            for (const QString &file : std::as_const(files))
                if (!file.isEmpty() && !scanned.contains(file) && !seen.contains(file)) {
                    seen.insert(file);
                    extra.append({file, digests.digest(workspace.absolutePath(file))});
                }
        }
    std::sort(extra.begin(), extra.end());
    return extra;
}

} // namespace

LaunchDependencies LaunchAnalyzer::run(const Workspace &workspace, const AtomicNodeList &nodes,
                                       const LaunchOptions &options, const StageControl &control,
                                       LaunchReadAhead *readAhead, QByteArray *resultKey)
{
    AnalysisCache &cache = AnalysisCache::of(control);
    // See NodeAnalyzer::run; a read-ahead began the run of the "launch" entries already.
    if (readAhead && readAhead->reading())
        cache.startRun({QStringLiteral("stage2")});
    else
        cache.startRun({QStringLiteral("stage2"), QStringLiteral("launch")});
    QByteArray key;
    QList<Evidence> locations; // of `nodes` that the result may hold
    if (cache.isEnabled()) {
        // Every file but C++ sources and headers, which stage 2 never reads (their facts reach
        // it through `nodes`).
        QStringList paths;
        for (const SourceFile &f : workspace.files)
            if (f.language != SourceFile::Language::Cpp)
                paths.append(f.path);
        QByteArray optionsPart;
        QDataStream s(&optionsPart, QIODevice::WriteOnly);
        s << options.rootFile << options.arguments;
        for (const ExpectedExternal &e : options.externals)
            s << e.name << e.output << e.reason;
        key = AnalysisCache::key({"stage2", stagememo::workspacePart(workspace, control, false),
                                  cache.digests().digestAll(workspace.root, paths), optionsPart,
                                  nodesPart(nodes, &locations)});
    }
    // The result with the locations of `nodes` it was computed from: when only they moved since,
    // the result is the memo's with them moved too.
    using Memo = std::pair<QList<Evidence>, std::pair<ExtraFiles, LaunchDependencies>>;
    const auto keyOfResult = [&](const ExtraFiles &extra) {
        if (resultKey && !key.isEmpty())
            *resultKey = AnalysisCache::key({"stage2 result", key, cachecodec::encode(extra)});
    };
    if (resultKey)
        resultKey->clear();
    if (!key.isEmpty())
        if (std::optional<Memo> memo = stagememo::load<Memo>(cache, QStringLiteral("stage2"), key);
            memo &&
            memo->second.first == extraFiles(workspace, memo->second.second, cache.digests())) {
            EvidenceShift shift;
            LaunchDependencies &reused = memo->second.second;
            if (shift.compare(memo->first, locations)) {
                shift.compareUnmoved(memo->first, locations);
                if (shift.settle() && shift.apply(reused)) {
                    keyOfResult(memo->second.first);
                    cache.flush();
                    if (const std::optional<Diagnostic> problem = cache.takeProblem())
                        reused.diagnostics.prepend(*problem);
                    return std::move(reused);
                }
            }
        }
    LaunchDependencies out = analyse(workspace, nodes, options, control, readAhead);
    if (!key.isEmpty() && !out.canceled && cache.isEnabled()) {
        ExtraFiles extra = extraFiles(workspace, out, cache.digests());
        keyOfResult(extra);
        // The shared cache writing its pack later (the worker's after its reply, an in-process
        // run's after the run): the memo is encoded on a pool thread while stage 3 runs.
        cache.storeLater([&cache, key, memo = Memo{locations, {std::move(extra), out}}] {
            cache.store(QStringLiteral("stage2"), key, cachecodec::encode(memo));
        });
    }
    cache.flush();
    if (const std::optional<Diagnostic> problem = cache.takeProblem())
        out.diagnostics.prepend(*problem);
    return out;
}

std::optional<LaunchFileDescription> LaunchAnalyzer::read(const SourceFile &f,
                                                          const QByteArray &content)
{
    if (f.language == SourceFile::Language::Python)
        return PythonLaunchReader::readIfLaunchFile(content, f.path);
    if (f.language == SourceFile::Language::Xml && XmlLaunchReader::isLaunchFile(content))
        return XmlLaunchReader::read(content, f.path);
    if (f.language == SourceFile::Language::Yaml && YamlLaunchReader::isLaunchFile(content))
        return YamlLaunchReader::read(content, f.path);
    return std::nullopt;
}

LaunchDependencies analyzeLaunchFiles(const QString &root, const AtomicNodeList &nodes,
                                      const LaunchOptions &options, const StageControl &control)
{
    const Workspace ws = WorkspaceScanner::scan(root, control);
    return LaunchAnalyzer::run(ws, nodes, options, control);
}

} // namespace rosarch
