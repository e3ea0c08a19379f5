#include "nodes/cpp/cpplinkmemo.h"

#include "cache/analysiscache.h"
#include "cache/evidenceshift.h"
#include "nodes/cpp/cppfactsfields.h"
#include "nodes/cpp/cppnodelinker.h"

#include <QThreadPool>

#include <memory>

namespace rosarch {

namespace {

using Memo = CppLinkMemo::Memo;

/// The same facts without a look inside: every part the linker reads shares its data with the
/// other's (both are copies of one decoded entry, as an unchanged file's are run after run).
bool shared(const CppFileFacts &a, const CppFileFacts &b)
{
    return a.path == b.path && a.package == b.package && a.isHeader == b.isHeader &&
           a.classes.isSharedWith(b.classes) && a.functions.isSharedWith(b.functions) &&
           a.aliases.isSharedWith(b.aliases) && a.usingNamespaces.isSharedWith(b.usingNamespaces) &&
           a.constants.isSharedWith(b.constants) && a.registrations.isSharedWith(b.registrations) &&
           a.pluginExports.isSharedWith(b.pluginExports);
}

/// A file's facts as the linker reads them: without their diagnostics, which it never reads.
CppFileFacts linked(const CppFileFacts &facts)
{
    CppFileFacts out = facts;
    out.diagnostics.clear();
    return out;
}

} // namespace

std::optional<LanguageAnalysis> CppLinkMemo::reuse(const QList<CppFileFacts> &old,
                                                   LanguageAnalysis before,
                                                   const QList<CppFileFacts> &files)
{
    if (old.size() != files.size())
        return std::nullopt;
    // Files whose facts share their data are the same; the others are compared apart from
    // their locations, twice (the moved locations, then every other in their files).
    QList<qsizetype> compared;
    EvidenceShift shift;
    for (qsizetype i = 0; i < files.size(); ++i) {
        if (shared(old.at(i), files.at(i)))
            continue;
        if (old.at(i).path != files.at(i).path ||
            !shift.compare(linked(old.at(i)), linked(files.at(i))))
            return std::nullopt;
        compared.append(i);
    }
    for (const qsizetype i : std::as_const(compared))
        shift.compareUnmoved(linked(old.at(i)), linked(files.at(i)));
    // A location of the link in a moved file that none of the compared facts holds (one of a
    // file not compared) fails apply(): then the link is made again.
    if (!shift.settle() || !shift.apply(before))
        return std::nullopt;
    return before;
}

LanguageAnalysis CppLinkMemo::link(const QList<CppFileFacts> &files, const QString &root,
                                   AnalysisCache &cache)
{
    const QString kind = CppLinkMemo::kind();
    const QByteArray key = CppLinkMemo::key();
    std::optional<LanguageAnalysis> out;
    std::shared_ptr<const void> kept = cache.recent(kind, key);
    if (kept) {
        const Memo &memo = *static_cast<const Memo *>(kept.get());
        if (memo.root == root)
            out = reuse(memo.files, memo.analysis, files);
    }
    if (!out)
        out = CppNodeLinker(files).link();
    if (cache.isEnabled()) {
        cache.keepRecent(kind, key, std::make_shared<const Memo>(Memo{root, files, *out}));
        // The memo replaced is freed on a pool thread: the part of it not shared with the new
        // one (a whole link when this one was made anew) takes milliseconds to free.
        if (kept)
            QThreadPool::globalInstance()->start(
                [kept = std::move(kept)]() mutable { kept.reset(); });
    }
    return std::move(*out);
}

} // namespace rosarch
