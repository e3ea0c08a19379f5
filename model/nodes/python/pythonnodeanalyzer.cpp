#include "nodes/python/pythonnodeanalyzer.h"

#include "cache/analysiscache.h"
#include "cache/filedigests.h"
#include "cache/stagememo.h"
#include "nodes/python/pythonfactscodec.h"
#include "nodes/python/pythonmodulereader.h"
#include "nodes/python/pythonnodelinker.h"
#include "syntax/parsehandoff.h"
#include "syntax/pythonerrorrecovery.h"
#include "syntax/syntaxtree.h"
#include "workspace/largestfirst.h"
#include "workspace/sourcereader.h"

#include <QMutex>
#include <QSet>

namespace rosarch {

namespace {
/// The dotted module path of a file: its stem, prefixed by the enclosing folders that are
/// Python packages (hold an __init__.py). A loose script is named by its path inside its ROS
/// package, so that same-named scripts in different folders stay apart.
QString modulePath(const QString &file, const QString &packagePath,
                   const QSet<QString> &pythonFiles)
{
    QStringList parts;
    QString dir = file.section(QLatin1Char('/'), 0, -2);
    QString stem = file.section(QLatin1Char('/'), -1);
    stem.chop(3); // ".py"
    if (stem != QLatin1String("__init__"))
        parts.append(stem);
    if (!dir.isEmpty() && !pythonFiles.contains(dir + QStringLiteral("/__init__.py"))) {
        QString inPackage = file;
        if (!packagePath.isEmpty() && file.startsWith(packagePath + QLatin1Char('/')))
            inPackage = file.mid(packagePath.size() + 1);
        inPackage.chop(3);
        return inPackage.replace(QLatin1Char('/'), QLatin1Char('.'));
    }
    while (!dir.isEmpty() && pythonFiles.contains(dir + QStringLiteral("/__init__.py"))) {
        parts.prepend(dir.section(QLatin1Char('/'), -1));
        dir = dir.section(QLatin1Char('/'), 0, -2);
    }
    return parts.isEmpty() ? stem : parts.join(QLatin1Char('.'));
}

/// The last analysis of this process, for the next: when every file's cache key is the same
/// (so is every file's result, which the key determines), so is the analysis.
struct PythonMemo
{
    QString root;
    QList<QByteArray> keys; ///< of the files, in order
    LanguageAnalysis result;
};
} // namespace

PythonNodeAnalyzer::PythonNodeAnalyzer(const Workspace &workspace) : m_workspace(workspace) {}

LanguageAnalysis PythonNodeAnalyzer::analyze(const StageControl &control) const
{
    LanguageAnalysis result;
    QList<const SourceFile *> files;
    QSet<QString> pythonFiles;
    for (const SourceFile &f : m_workspace.files) {
        if (f.language != SourceFile::Language::Python)
            continue;
        files.append(&f);
        pythonFiles.insert(f.path);
    }

    // Each file on its own, in parallel (largest first); the results keep the files' order.
    const SourceReader reader(m_workspace.root);
    AnalysisCache &cache = AnalysisCache::of(control);
    const int total = int(files.size());
    const auto moduleOf = [&](const SourceFile *file) {
        const RosPackage *package = m_workspace.package(file->package);
        return modulePath(file->path, package ? package->path : QString(), pythonFiles);
    };
    const auto keyOf = [&](const SourceFile *file, const QString &module,
                           const QByteArray &digest) {
        return AnalysisCache::key(
            {"python", file->path.toUtf8(), file->package.toUtf8(), module.toUtf8(), digest});
    };

    // Every file's key from its digest, taken before it is read (a change after that is seen by
    // the next run); none when a file cannot be read or is skipped.
    QList<QByteArray> keys;
    if (cache.isEnabled()) {
        for (const SourceFile *file : std::as_const(files)) {
            const QByteArray digest =
                control.skipped.contains(file->path)
                    ? QByteArray()
                    : cache.digests().digest(m_workspace.absolutePath(file->path));
            if (digest.isEmpty()) {
                keys.clear();
                break;
            }
            keys.append(keyOf(file, moduleOf(file), digest));
        }
    }
    const QString memoKind = QStringLiteral("pythonrun");
    const QByteArray memoKey("last");
    if (!keys.isEmpty() && !control.isCanceled())
        if (const std::shared_ptr<const void> kept = cache.recent(memoKind, memoKey)) {
            const PythonMemo &memo = *static_cast<const PythonMemo *>(kept.get());
            if (memo.root == m_workspace.root && memo.keys == keys) {
                control.report(total, total, QString());
                return memo.result;
            }
        }

    int done = 0;
    QMutex reportMutex;
    auto analyzeFile = [&](const SourceFile *file) {
        PythonFileResult r;
        if (control.isCanceled())
            return r;
        {
            QMutexLocker lock(&reportMutex);
            control.report(done++, total, file->path);
        }
        // Said to the supervisor only when the file is read: a cache hit cannot crash it.
        FileWork work(control, file->path, FileWork::Start::Later);
        if (work.skip(&r.diagnostics))
            return r;
        const QString module = moduleOf(file);
        const auto fromCache = [&](const QByteArray &key) {
            if (std::optional<PythonFileResult> cached = stagememo::loadWith<PythonFileResult>(
                    cache, QStringLiteral("python"), key, &PythonFactsCodec::decode)) {
                r.module = std::move(cached->module);
                r.diagnostics += cached->diagnostics;
                return true;
            }
            return false;
        };
        // A file unchanged since it was last hashed is found without reading it.
        QByteArray known;
        if (cache.isEnabled())
            known = cache.digests().digest(m_workspace.absolutePath(file->path));
        if (!known.isEmpty() && fromCache(keyOf(file, module, known)))
            return r;
        work.start();
        QByteArray content;
        QList<Diagnostic> read; // what reading says of the file (not UTF-8, ...), kept with it
        if (!reader.read(file->path, &content, &read)) {
            r.diagnostics += read;
            return r;
        }
        const QByteArray key = keyOf(file, module, FileDigests::digestOf(content));
        if (key != keyOf(file, module, known) && fromCache(key)) // changed since it was hashed
            return r;
        PythonFileResult analysed = analyzeContent(content, file->path, file->package, module);
        analysed.diagnostics = read + analysed.diagnostics;
        cache.store(QStringLiteral("python"), key, PythonFactsCodec::encode(analysed));
        r.module = analysed.module;
        r.diagnostics += analysed.diagnostics;
        return r;
    };
    const QList<PythonFileResult> analysed = mapLargestFirst<PythonFileResult>(files, analyzeFile);
    if (control.isCanceled())
        return result;
    control.report(total, total, QString());
    QList<PythonModuleFacts> modules;
    modules.reserve(analysed.size());
    for (const PythonFileResult &r : analysed) {
        result.diagnostics.append(r.diagnostics);
        if (r.module)
            modules.append(*r.module);
    }
    PythonNodeLinker(modules).link(&result);
    if (!keys.isEmpty())
        cache.keepRecent(
            memoKind, memoKey,
            std::make_shared<const PythonMemo>(PythonMemo{m_workspace.root, keys, result}));
    return result;
}

PythonFileResult PythonNodeAnalyzer::analyzeContent(const QByteArray &content, const QString &file,
                                                    const QString &package, const QString &module)
{
    PythonFileResult r;
    // A launch file is parsed once for both stages: by whichever reads it first.
    const bool shared = ParseHandoff::wanted(content);
    bool parsedHere = true;
    SyntaxTree tree = shared ? ParseHandoff::takeOrParse(file, content, &parsedHere)
                             : SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file);
    bool repaired = false;
    if (!ts::isNull(tree.root()) && ts_node_has_error(tree.root())) {
        QList<Diagnostic> isolated;
        const QByteArray text = PythonErrorRecovery::isolate(content, file, &isolated);
        if (!isolated.isEmpty()) {
            r.diagnostics.append(isolated);
            if (shared && parsedHere)
                ParseHandoff::offer(std::move(tree)); // the text as written, for stage 2
            tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, text, file);
            repaired = true;
        }
    }
    r.diagnostics.append(tree.syntaxErrors());
    if (!ts::isNull(tree.root()))
        r.module = PythonModuleReader(tree, module).read(package);
    if (shared && parsedHere && !repaired)
        ParseHandoff::offer(std::move(tree));
    return r;
}

} // namespace rosarch
