#include "cppnodeanalyzer.h"

#include "analysiscache.h"
#include "cpperrorrecovery.h"
#include "cppfactscodec.h"
#include "cppfileextractor.h"
#include "cppmacroindex.h"
#include "cppnodelinker.h"
#include "cppsyntax.h"
#include "sourcereader.h"
#include "syntaxtree.h"

#include <QMutex>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentMap>

namespace rosarch {

namespace {

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

LanguageAnalysis CppNodeAnalyzer::analyze(const StageControl &control) const
{
    QList<const SourceFile *> sources;
    for (const SourceFile &file : m_workspace.files)
        if (file.language == SourceFile::Language::Cpp)
            sources.append(&file);

    // Phase 1: per-file facts, in parallel. Trees are dropped as soon as a file is done.
    const SourceReader reader(m_workspace.root);
    // Before any file is parsed: the macros the packages and the workspace headers define, so
    // that conditional compilation is decided as the build decides it.
    const CppMacroIndex macroIndex(m_workspace, reader, control);
    if (control.isCanceled())
        return {};
    AnalysisCache &cache = control.cache ? *control.cache : AnalysisCache::shared();
    const int total = int(sources.size());
    int done = 0;
    QMutex reportMutex;
    auto extract = [&](const SourceFile *file) {
        CppFileFacts facts;
        facts.path = file->path;
        facts.package = file->package;
        if (control.isCanceled())
            return facts;
        const FileWork work(control, file->path);
        QByteArray bytes;
        if (!work.skip(&facts.diagnostics) && reader.read(file->path, &bytes, &facts.diagnostics)) {
            try {
                CppPreprocessor::Result preprocessed = CppPreprocessor::run(
                    &bytes, file->path, macroIndex.initialMacros(file->package),
                    macroIndex.lookup(file->path));
                // The facts depend on the text the preprocessor leaves and the macros in
                // effect at its end, so those (and where the file is) are the key.
                const QByteArray key =
                    AnalysisCache::key({"cpp", file->path.toUtf8(), file->package.toUtf8(), bytes,
                                        CppFactsCodec::digest(preprocessed.macros)});
                const std::optional<QByteArray> cached = cache.load(QStringLiteral("cpp"), key);
                if (!cached || !CppFactsCodec::decode(*cached, &facts)) {
                    cppsyntax::blankExportMacros(&bytes);
                    cppsyntax::blankQtKeywords(&bytes);
                    cppsyntax::blankGrammarGaps(&bytes);
                    QList<Diagnostic> isolated;
                    const SyntaxTree tree =
                        CppErrorRecovery::parse(std::move(bytes), file->path, &isolated);
                    facts = CppFileExtractor::extract(tree, file->package, preprocessed.macros);
                    facts.diagnostics = isolated + facts.diagnostics;
                    cache.store(QStringLiteral("cpp"), key, CppFactsCodec::encode(facts));
                }
                facts.diagnostics = preprocessed.diagnostics + facts.diagnostics;
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
    QList<CppFileFacts> files = QtConcurrent::blockingMapped<QList<CppFileFacts>>(
        sources, std::function<CppFileFacts(const SourceFile *)>(extract));
    if (control.isCanceled())
        return {};

    // Phase 2: link across files (out-of-line members, base classes, helpers).
    LanguageAnalysis analysis = CppNodeLinker(files).link();
    for (const CppFileFacts &facts : std::as_const(files))
        analysis.diagnostics += facts.diagnostics;
    // Freeing every file's facts takes tens of milliseconds on a large workspace (nav2: ~20 ms,
    // serial): a pool thread does it while the caller goes on with the next stage.
    QThreadPool::globalInstance()->start([facts = std::move(files)]() mutable { facts.clear(); });
    return analysis;
}

} // namespace rosarch
