#pragma once

#include "core/languageanalysis.h"
#include "nodes/cpp/cppfacts.h"

#include <QString>

#include <optional>

namespace rosarch {

class AnalysisCache;

/// Phase 2 of the C++ analysis with the previous link of this process reused: when every file's
/// facts are those of the previous run but for moved lines (an edit that added or removed a
/// comment, a blank line, ...), the link is the previous one with those locations moved
/// (EvidenceShift), since the linker decides nothing by a location but the order of those of a
/// file, which such a move keeps. Any other difference links again. Kept in `cache`'s memory
/// only (one link, the last one), so nothing is kept when the cache is off.
class CppLinkMemo
{
public:
    /// What is kept of the last link (AnalysisCache::recent(kind(), key())).
    struct Memo
    {
        QString root;
        QList<CppFileFacts> files;
        LanguageAnalysis analysis;
    };
    static QString kind() { return QStringLiteral("cpplink"); }
    static QByteArray key() { return QByteArrayLiteral("last"); }

    /// The link of `files` (in the analyzer's order) of the workspace at `root`.
    static LanguageAnalysis link(const QList<CppFileFacts> &files, const QString &root,
                                 AnalysisCache &cache);

    /// The previous link `before` of the facts `old` made a link of `files` by moving its
    /// locations; none when the facts differ in more than locations (exposed for tests).
    static std::optional<LanguageAnalysis> reuse(const QList<CppFileFacts> &old,
                                                 LanguageAnalysis before,
                                                 const QList<CppFileFacts> &files);
};

} // namespace rosarch
