#pragma once

#include <QHash>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Reads workspace files for suggestions: their lines (cached) and numbered excerpts for prompts.
class SuggestionSource
{
public:
    explicit SuggestionSource(const QString &workspaceRoot);

    /// The lines of a workspace-relative file (empty when it cannot be read).
    QStringList lines(const QString &file) const;
    /// {"file", "first_line", "lines": ["12| text", ...]} for lines first..last (1-based,
    /// clamped to the file, at most `maxLines`).
    QJsonObject excerpt(const QString &file, int first, int last, int maxLines = 60) const;

private:
    QString m_root;
    mutable QHash<QString, QStringList> m_cache;
};

} // namespace rosarch
