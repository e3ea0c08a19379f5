#pragma once

#include "core/suggestion.h"
#include "pipeline/recovery.h"
#include "suggestions/suggestionitem.h"

#include <QHash>
#include <QMutex>
#include <QSet>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Checks a suggestion against the recovered architecture and the workspace files: it may
/// only refer to elements that exist, and cite lines that exist and contain the quoted text.
class SuggestionChecker
{
public:
    SuggestionChecker(const QString &workspaceRoot, const Recovery &recovery);

    /// True when the suggestion may be shown; otherwise `reason` is a short code
    /// ("unknown-target", "evidence-file-missing", "evidence-line-out-of-range",
    /// "evidence-does-not-say", ...) and `detail` says what exactly failed.
    bool check(const Suggestion &suggestion, QString *reason, QString *detail) const;
    /// The root launch-file instance ids and the node instances below each.
    QStringList subtreeNodes(const QString &rootId) const;
    /// The launch files (workspace-relative) of a root's subtree.
    QSet<QString> subtreeFiles(const QString &rootId) const;

private:
    bool checkCitation(const Suggestion::Citation &c, QString *reason, QString *detail) const;
    /// The lines of a workspace file, or false when it is not a file inside the workspace.
    bool fileLines(const QString &relative, QStringList *lines) const;

    QString m_root;
    const Recovery &m_recovery;
    QHash<QString, SuggestionItem> m_items;
    mutable QMutex m_mutex;
    mutable QHash<QString, QStringList> m_files; ///< cache; guarded by m_mutex
};

} // namespace rosarch
