#include "launchanalyzer.h"
#include "analysiscache.h"
#include "launchexecutor.h"
#include "launchfileindex.h"
#include "pythonlaunchreader.h"
#include "rosnames.h"
#include "sourcereader.h"
#include "workspacescanner.h"
#include "xmllaunchreader.h"
#include "yamllaunchreader.h"

#include <QHash>
#include <QSet>

#include <map>

namespace rosarch {

namespace {

/// Each launch file of the system analysed on its own, with its declared defaults, in the
/// classifier scope: what its CCD shows (blueprint §1). What these runs find was found by the
/// system's runs already, so their diagnostics are dropped; a budget bounds their size.
void runClassifiers(const Workspace &workspace, const AtomicNodeList &nodes,
                    const LaunchFileIndex &index, const StageControl &control,
                    LaunchDependencies *out)
{
    constexpr qsizetype kBudget = 100000; // instances over all runs
    LaunchDependencies alone;
    LaunchExecutor executor(
        workspace, nodes, [&](const QString &f) { return index.find(f); }, &alone);
    executor.setIdPrefix(QStringLiteral("c"));
    QSet<QString> done;
    for (const LaunchFileInstance &i : std::as_const(out->instances)) {
        if (i.file.isEmpty() || done.contains(i.file))
            continue;
        done.insert(i.file);
        if (control.isCanceled())
            return;
        if (alone.instances.size() + alone.nodes.size() > kBudget) {
            Diagnostic d;
            d.code = QStringLiteral("launch-evaluation-limit");
            d.message = QStringLiteral("Analysing each launch file on its own for its diagram "
                                       "stopped after %1 instances; the diagrams of %2 and later "
                                       "files show them as included by the system.")
                            .arg(kBudget)
                            .arg(i.file);
            d.evidence = Evidence::startOf(i.file);
            out->diagnostics.append(d);
            break;
        }
        const FileWork work(control, i.file);
        if (!work.skip(&alone.diagnostics))
            executor.runRoot(i.file, {}, QLatin1String(RosNames::kClassifierScope));
    }
    out->classifierInstances = std::move(alone.instances);
    out->classifierNodes = std::move(alone.nodes);
}

} // namespace

LaunchDependencies LaunchAnalyzer::run(const Workspace &workspace, const AtomicNodeList &nodes,
                                       const LaunchOptions &options, const StageControl &control)
{
    LaunchDependencies out;
    const LaunchFileIndex index(workspace, control, &out.diagnostics);
    if (control.isCanceled()) {
        out.canceled = true;
        return out;
    }
    AnalysisCache &cache = control.cache ? *control.cache : AnalysisCache::shared();
    if (const std::optional<Diagnostic> problem = cache.takeProblem())
        out.diagnostics.append(*problem);
    cache.trim();
    out.launchFiles = index.files();
    LaunchExecutor executor(
        workspace, nodes, [&](const QString &f) { return index.find(f); }, &out);

    QStringList roots;
    if (!options.rootFile.isEmpty()) {
        if (index.find(options.rootFile)) {
            roots << options.rootFile;
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
        // Top-level launch files: those no other launch file includes.
        QSet<QString> included;
        for (const QString &f : std::as_const(out.launchFiles))
            for (const QString &inc : executor.directIncludes(f))
                if (inc != f)
                    included.insert(inc);
        for (const QString &f : std::as_const(out.launchFiles))
            if (!included.contains(f))
                roots << f;
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
                const FileWork work(control, f);
                if (!work.skip(&out.diagnostics))
                    executor.runRoot(f, options.arguments);
                for (const LaunchFileInstance &i : std::as_const(out.instances))
                    reached.insert(i.file);
            }
    }
    runClassifiers(workspace, nodes, index, control, &out);
    // The same problem met through two include chains is one diagnostic.
    QList<Diagnostic> unique;
    for (const Diagnostic &d : std::as_const(out.diagnostics))
        if (!unique.contains(d))
            unique.append(d);
    out.diagnostics = unique;
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
            out.diagnostics.append(d);
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
            d.evidence = i.evidence;
            out.diagnostics.append(d);
        }
    return out;
}

std::optional<LaunchFileDescription> LaunchAnalyzer::read(const SourceFile &f,
                                                          const QByteArray &content)
{
    if (f.language == SourceFile::Language::Python && PythonLaunchReader::isLaunchFile(content))
        return PythonLaunchReader::read(content, f.path);
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
