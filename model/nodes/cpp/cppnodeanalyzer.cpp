#include "cppnodeanalyzer.h"

#include "cppfileextractor.h"
#include "cppnodelinker.h"
#include "cppsyntax.h"
#include "sourcereader.h"
#include "syntaxtree.h"

#include <QMutex>
#include <QtConcurrent/QtConcurrentMap>

namespace rosarch {

CppNodeAnalyzer::CppNodeAnalyzer(const Workspace &workspace) : m_workspace(workspace) {}

LanguageAnalysis CppNodeAnalyzer::analyze(const StageControl &control) const
{
    QList<const SourceFile *> sources;
    for (const SourceFile &file : m_workspace.files)
        if (file.language == SourceFile::Language::Cpp)
            sources.append(&file);

    // Phase 1: per-file facts, in parallel. Trees are dropped as soon as a file is done.
    const SourceReader reader(m_workspace.root);
    const int total = int(sources.size());
    int done = 0;
    QMutex reportMutex;
    auto extract = [&](const SourceFile *file) {
        CppFileFacts facts;
        facts.path = file->path;
        facts.package = file->package;
        if (control.isCanceled())
            return facts;
        QByteArray bytes;
        if (reader.read(file->path, &bytes, &facts.diagnostics)) {
            cppsyntax::blankExportMacros(&bytes);
            const SyntaxTree tree =
                SyntaxTree::parse(SyntaxTree::Grammar::Cpp, std::move(bytes), file->path);
            facts = CppFileExtractor::extract(tree, file->package);
        }
        QMutexLocker lock(&reportMutex); // reports stay in order and never overlap
        control.report(++done, total, file->path);
        return facts;
    };
    const QList<CppFileFacts> files = QtConcurrent::blockingMapped<QList<CppFileFacts>>(
        sources, std::function<CppFileFacts(const SourceFile *)>(extract));
    if (control.isCanceled())
        return {};

    // Phase 2: link across files (out-of-line members, base classes, helpers).
    LanguageAnalysis analysis = CppNodeLinker(files).link();
    for (const CppFileFacts &facts : files)
        analysis.diagnostics += facts.diagnostics;
    return analysis;
}

} // namespace rosarch
