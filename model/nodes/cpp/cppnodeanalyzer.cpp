#include "nodes/cpp/cppnodeanalyzer.h"

#include "cache/analysiscache.h"
#include "cache/filedigests.h"
#include "cache/stagememo.h"
#include "nodes/cpp/cppfactscodec.h"
#include "nodes/cpp/cppfileextractor.h"
#include "nodes/cpp/cpplinkmemo.h"
#include "nodes/cpp/cppmacroindex.h"
#include "syntax/cpperrorrecovery.h"
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"
#include "workspace/largestfirst.h"
#include "workspace/sourcereader.h"

#include <QMutex>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include <memory>

namespace rosarch {

namespace {

/// What a C++ file's preprocessing depended on besides its text and initial macros: each
/// `#include` it looked up with the digest of the exports it got (ccache's direct mode).
/// When every lookup gives the same again, the preprocessing would too: `key` is the key of
/// the file's facts, and `diagnostics` the preprocessor's, without preprocessing.
struct CppManifest
{
    QList<QByteArray> written;
    QList<bool> angled;
    QList<QByteArray> exports;
    QList<Diagnostic> diagnostics;
    QByteArray key;
};

} // namespace

namespace cachecodec {
template <class F> void cacheFields(Tag, CppMacro &v, F f)
{
    f(v.body, v.parameters, v.functionLike);
}
template <class F> void cacheFields(Tag, CppManifest &v, F f)
{
    f(v.written, v.angled, v.exports, v.diagnostics, v.key);
}
} // namespace cachecodec

namespace {

/// The macro index, from the cache when no header and no CMakeLists.txt changed.
std::unique_ptr<CppMacroIndex> macroIndexOf(const Workspace &ws, const SourceReader &reader,
                                            const StageControl &control, AnalysisCache &cache)
{
    if (!cache.isEnabled())
        return std::make_unique<CppMacroIndex>(ws, reader, control);
    QStringList read; // every file the index may read
    for (const SourceFile &f : ws.files)
        if (f.language == SourceFile::Language::Cpp && cppsyntax::isHeaderPath(f.path))
            read.append(f.path);
    for (const RosPackage &p : ws.packages)
        read.append(p.path.isEmpty() ? QStringLiteral("CMakeLists.txt")
                                     : p.path + QStringLiteral("/CMakeLists.txt"));
    const QByteArray key =
        AnalysisCache::key({"cppmacros", stagememo::workspacePart(ws, control, false),
                            cache.digests().digestAll(ws.root, read)});
    using Exports = QHash<QString, CppMacros>;
    if (std::optional<Exports> exports =
            stagememo::load<Exports>(cache, QStringLiteral("cppmacros"), key))
        return std::make_unique<CppMacroIndex>(ws, reader, std::move(*exports));
    auto index = std::make_unique<CppMacroIndex>(ws, reader, control);
    if (!control.isCanceled())
        cache.store(QStringLiteral("cppmacros"), key, cachecodec::encode(index->exports()));
    return index;
}

/// The facts of one preprocessed C++ file, from its parse.
CppFileFacts parsed(QByteArray bytes, const SourceFile &file, const CppMacros &macros)
{
    cppsyntax::blankExportMacros(&bytes);
    cppsyntax::blankQtKeywords(&bytes);
    cppsyntax::blankGrammarGaps(&bytes);
    QList<Diagnostic> isolated;
    const SyntaxTree tree = CppErrorRecovery::parse(std::move(bytes), file.path, &isolated);
    CppFileFacts facts = CppFileExtractor::extract(tree, file.package, macros);
    facts.diagnostics = isolated + facts.diagnostics;
    return facts;
}

Diagnostic analysisFailed(const QString &file, const std::exception &e)
{
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.code = QStringLiteral("parse-failed");
    d.message = QStringLiteral("%1 could not be analysed (%2); nothing in it was analysed.")
                    .arg(file, QString::fromLocal8Bit(e.what()));
    d.evidence = Evidence::startOf(file);
    return d;
}

} // namespace

CppNodeAnalyzer::CppNodeAnalyzer(const Workspace &workspace) : m_workspace(workspace) {}

CppNodeAnalyzer::~CppNodeAnalyzer()
{
    if (m_prepared.isValid()) // the task refers to this analyzer's workspace
        m_prepared.waitForFinished();
}

void CppNodeAnalyzer::prepare(const StageControl &control)
{
    // The task keeps a copy of the control: the caller's may be a temporary.
    m_prepared = QtConcurrent::run([this, control]() -> std::shared_ptr<const CppMacroIndex> {
        if (control.isCanceled()) // before the index, which reads every package's CMakeLists
            return nullptr;
        const SourceReader reader(m_workspace.root); // the index reads only while it is built
        AnalysisCache &cache = AnalysisCache::of(control);
        return macroIndexOf(m_workspace, reader, control, cache);
    });
}

LanguageAnalysis CppNodeAnalyzer::analyze(const StageControl &control) const
{
    if (control.isCanceled()) // before the macro index, which reads every package's CMakeLists
        return {};
    QList<const SourceFile *> sources;
    for (const SourceFile &file : m_workspace.files)
        if (file.language == SourceFile::Language::Cpp)
            sources.append(&file);

    // Phase 1: per-file facts, in parallel (largest first). Trees are dropped as soon as a file is
    // done.
    const SourceReader reader(m_workspace.root);
    // Before any file is parsed: the macros the packages and the workspace headers define, so
    // that conditional compilation is decided as the build decides it (prepare() may have
    // started on it already).
    AnalysisCache &cache = AnalysisCache::of(control);
    const std::shared_ptr<const CppMacroIndex> index =
        m_prepared.isValid() ? m_prepared.result()
                             : std::shared_ptr<const CppMacroIndex>(
                                   macroIndexOf(m_workspace, reader, control, cache));
    if (control.isCanceled() || !index)
        return {};
    const CppMacroIndex &macroIndex = *index;
    // Digests of each header's exports and of each package's initial macros, for the manifests.
    QHash<const CppMacros *, QByteArray> exportDigests;
    for (auto it = macroIndex.exports().cbegin(); it != macroIndex.exports().cend(); ++it)
        exportDigests.insert(&it.value(), CppFactsCodec::digest(it.value()));
    QHash<QString, QByteArray> initialDigests;
    for (const SourceFile *file : std::as_const(sources))
        if (!initialDigests.contains(file->package))
            initialDigests.insert(file->package,
                                  CppFactsCodec::digest(macroIndex.initialMacros(file->package)));
    auto digestOf = [&](const CppMacros *exports) {
        return exports ? exportDigests.value(exports) : QByteArray();
    };
    const int total = int(sources.size());
    int done = 0;
    QMutex reportMutex;
    // What the files parsed store in the cache, encoded once every file is done (storeLater):
    // while the files are parsed, both cores have better things to do.
    struct Store
    {
        QByteArray key;
        std::optional<CppFileFacts> facts; ///< none: the facts came from the cache
        QByteArray manifestKey;
        CppManifest manifest;
    };
    std::vector<Store> stores;
    QMutex storesMutex;
    auto extract = [&](const SourceFile *file) {
        CppFileFacts facts;
        facts.path = file->path;
        facts.package = file->package;
        if (control.isCanceled())
            return facts;
        // Said to the supervisor only when the file is read: a cache hit cannot crash it.
        FileWork work(control, file->path, FileWork::Start::Later);
        if (!work.skip(&facts.diagnostics)) {
            try {
                const CppPreprocessor::IncludeLookup lookup = macroIndex.lookup(file->path);
                const auto manifestKeyOf = [&](const QByteArray &digest) {
                    return AnalysisCache::key({"cppmanifest", file->path.toUtf8(),
                                               file->package.toUtf8(), digest,
                                               initialDigests.value(file->package)});
                };
                // The facts of a file whose text and included headers' exports are those of
                // the manifest's run: no preprocessing, no parsing.
                const auto fromManifest =
                    [&](const QByteArray &manifestKey) -> std::optional<CppFileFacts> {
                    const std::optional<CppManifest> manifest = stagememo::load<CppManifest>(
                        cache, QStringLiteral("cppmanifest"), manifestKey);
                    if (!manifest || manifest->written.size() != manifest->angled.size() ||
                        manifest->written.size() != manifest->exports.size())
                        return std::nullopt;
                    for (qsizetype i = 0; i < manifest->written.size(); ++i)
                        if (digestOf(lookup(manifest->written.at(i), manifest->angled.at(i))) !=
                            manifest->exports.at(i))
                            return std::nullopt;
                    std::optional<CppFileFacts> cached = stagememo::loadWith<CppFileFacts>(
                        cache, QStringLiteral("cpp"), manifest->key, &CppFactsCodec::decode);
                    if (cached)
                        cached->diagnostics = manifest->diagnostics + cached->diagnostics;
                    return cached;
                };
                // A file unchanged since it was last hashed is found without reading it.
                QByteArray known;
                if (cache.isEnabled())
                    known = cache.digests().digest(m_workspace.absolutePath(file->path));
                std::optional<CppFileFacts> hit;
                if (!known.isEmpty())
                    hit = fromManifest(manifestKeyOf(known));
                QByteArray bytes;
                QList<Diagnostic> read; // what reading says of the file (not UTF-8, ...)
                if (!hit)
                    work.start();
                // Without the cache, no key is worked out and nothing is encoded.
                const bool cached = cache.isEnabled();
                if (hit) {
                    facts = std::move(*hit);
                } else if (!reader.read(file->path, &bytes, &read)) {
                    facts.diagnostics += read;
                } else if (!cached) {
                    CppPreprocessor::Result preprocessed = CppPreprocessor::run(
                        &bytes, file->path, macroIndex.initialMacros(file->package), lookup);
                    facts = parsed(std::move(bytes), *file, preprocessed.macros);
                    facts.diagnostics = read + preprocessed.diagnostics + facts.diagnostics;
                } else if (const QByteArray manifestKey =
                               manifestKeyOf(FileDigests::digestOf(bytes));
                           manifestKey != manifestKeyOf(known) &&
                           (hit = fromManifest(manifestKey))) { // changed since it was hashed
                    facts = std::move(*hit);
                } else {
                    CppManifest manifest;
                    auto recording = [&](const QByteArray &written, bool angled) {
                        const CppMacros *exports = lookup(written, angled);
                        manifest.written.append(written);
                        manifest.angled.append(angled);
                        manifest.exports.append(digestOf(exports));
                        return exports;
                    };
                    CppPreprocessor::Result preprocessed = CppPreprocessor::run(
                        &bytes, file->path, macroIndex.initialMacros(file->package), recording);
                    // The facts depend on the text the preprocessor leaves and the macros in
                    // effect at its end, so those (and where the file is) are the key.
                    const QByteArray key =
                        AnalysisCache::key({"cpp", file->path.toUtf8(), file->package.toUtf8(),
                                            bytes, CppFactsCodec::digest(preprocessed.macros)});
                    Store store{key, std::nullopt, manifestKey, {}};
                    const std::optional<QByteArray> entry = cache.load(QStringLiteral("cpp"), key);
                    if (!entry || !CppFactsCodec::decode(*entry, &facts)) {
                        facts = parsed(std::move(bytes), *file, preprocessed.macros);
                        store.facts = facts; // shares the lists, which nothing changes
                    }
                    manifest.diagnostics = read + preprocessed.diagnostics;
                    manifest.key = key;
                    facts.diagnostics = manifest.diagnostics + facts.diagnostics;
                    store.manifest = std::move(manifest);
                    const QMutexLocker lock(&storesMutex);
                    stores.push_back(std::move(store));
                }
            } catch (const std::exception &e) { // out of memory: this file, not the run
                facts = CppFileFacts();
                facts.path = file->path;
                facts.package = file->package;
                facts.diagnostics.append(analysisFailed(file->path, e));
            }
        }
        QMutexLocker lock(&reportMutex); // reports stay in order and never overlap
        control.report(++done, total, file->path);
        return facts;
    };
    QList<CppFileFacts> files = mapLargestFirst<CppFileFacts>(sources, extract);
    if (!stores.empty()) {
        cache.storeLater([&cache, stores = std::move(stores)] {
            for (const Store &s : stores) {
                if (s.facts)
                    cache.store(QStringLiteral("cpp"), s.key, CppFactsCodec::encode(*s.facts));
                cache.store(QStringLiteral("cppmanifest"), s.manifestKey,
                            cachecodec::encode(s.manifest));
            }
        });
    }
    if (control.isCanceled())
        return {};

    // Phase 2: link across files (out-of-line members, base classes, helpers), or the previous
    // link when only lines moved.
    LanguageAnalysis analysis = CppLinkMemo::link(files, m_workspace.root, cache);
    for (const CppFileFacts &facts : std::as_const(files))
        analysis.diagnostics += facts.diagnostics;
    // Freeing every file's facts takes tens of milliseconds on a large workspace (nav2: ~20 ms,
    // serial): a pool thread does it while the caller goes on with the next stage.
    QThreadPool::globalInstance()->start([facts = std::move(files)]() mutable { facts.clear(); });
    return analysis;
}

} // namespace rosarch
