#include "launch/launchfileindex.h"

#include "cache/analysiscache.h"
#include "cache/stagememo.h"
#include "launch/launchanalyzer.h"
#include "launch/launchfilecodec.h"
#include "syntax/pythonsyntax.h"
#include "workspace/sourcereader.h"

#include <QMutex>
#include <QtConcurrent/QtConcurrentMap>

namespace rosarch {

namespace {

bool isCandidate(const SourceFile &f)
{
    return f.language == SourceFile::Language::Python || f.language == SourceFile::Language::Xml ||
           f.language == SourceFile::Language::Yaml;
}

} // namespace

QList<const SourceFile *> LaunchFileIndex::candidates(const Workspace &ws)
{
    QList<const SourceFile *> out;
    for (const SourceFile &f : ws.files)
        if (isCandidate(f))
            out.append(&f);
    return out;
}

LaunchFileRead LaunchFileIndex::read(const SourceFile &f, const SourceReader &reader,
                                     const StageControl &control, AnalysisCache &cache)
{
    LaunchFileRead r;
    if (control.isCanceled())
        return r;
    const FileWork work(control, f.path);
    QByteArray content;
    if (work.skip(&r.readProblems) || !reader.read(f.path, &content, &r.readProblems))
        return r;
    r.readable = true;
    // Only a Python file that names the launch function can be one; the test is cheap.
    if (f.language == SourceFile::Language::Python && !py::namesLaunchFunction(content))
        return r;
    const QByteArray key = AnalysisCache::key(
        {"launch", f.path.toUtf8(), QByteArray::number(int(f.language)), content});
    using Description = std::optional<LaunchFileDescription>;
    if (std::optional<Description> cached = stagememo::loadWith<Description>(
            cache, QStringLiteral("launch"), key, &LaunchFileCodec::decode)) {
        r.description = std::move(*cached);
        return r;
    }
    r.description = LaunchAnalyzer::read(f, content);
    cache.store(QStringLiteral("launch"), key, LaunchFileCodec::encode(r.description));
    return r;
}

LaunchFileIndex::LaunchFileIndex(const Workspace &ws, const StageControl &control,
                                 QList<Diagnostic> *diagnostics)
    : LaunchFileIndex(
          ws,
          [&] {
              const SourceReader reader(ws.root);
              AnalysisCache &cache = AnalysisCache::of(control);
              return QtConcurrent::blockingMapped<QList<LaunchFileRead>>(
                  candidates(ws),
                  std::function<LaunchFileRead(const SourceFile *)>(
                      [&](const SourceFile *f) { return read(*f, reader, control, cache); }));
          }(),
          control, diagnostics)
{
}

LaunchFileIndex::LaunchFileIndex(const Workspace &ws, QList<LaunchFileRead> reads,
                                 const StageControl &control, QList<Diagnostic> *diagnostics)
{
    if (control.isCanceled())
        return;
    QList<int> positions; // in ws.files, for the progress reports
    for (qsizetype i = 0; i < ws.files.size(); ++i)
        if (isCandidate(ws.files.at(i)))
            positions.append(int(i + 1));
    const QList<const SourceFile *> files = candidates(ws);
    Q_ASSERT(reads.size() == files.size());
    for (qsizetype i = 0; i < files.size() && i < reads.size(); ++i) {
        const SourceFile &f = *files.at(i);
        LaunchFileRead &r = reads[i];
        const bool python = f.language == SourceFile::Language::Python;
        if (!r.readable) {
            if (!python)
                diagnostics->append(r.readProblems);
            continue;
        }
        if (!r.description)
            continue;
        if (!python)
            diagnostics->append(r.readProblems); // how it was read (an encoding note)
        LaunchFileDescription &d = *r.description;
        control.report(positions.at(i), int(ws.files.size()), f.path);
        if (!python)
            diagnostics->append(d.diagnostics);
        else // Python syntax errors come from stage 1
            for (const Diagnostic &diag : std::as_const(d.diagnostics))
                if (diag.code != QLatin1String("syntax-error"))
                    diagnostics->append(diag);
        m_files.emplace(f.path, std::move(d));
    }
}

const LaunchFileDescription *LaunchFileIndex::find(const QString &file) const
{
    const auto it = m_files.find(file);
    return it == m_files.end() ? nullptr : &it->second;
}

QStringList LaunchFileIndex::files() const
{
    QStringList out;
    for (const auto &[file, d] : m_files)
        out.append(file);
    return out; // std::map keeps them sorted
}

} // namespace rosarch
