#pragma once

#include "core/diagnostic.h"
#include "workspace/workspace.h"

#include <QByteArray>
#include <QList>

namespace rosarch {

/// Reads a workspace file for analysis, refusing what cannot be analysed (too large, binary,
/// unreadable) with a diagnostic instead of content.
class SourceReader
{
public:
    static constexpr qint64 kDefaultMaxBytes = 4 * 1024 * 1024;

    explicit SourceReader(QString root, qint64 maxBytes = kDefaultMaxBytes);

    /// Returns false and appends a diagnostic when the file cannot be analysed. Content that
    /// is not UTF-8 is read as Latin-1 and converted, with an info diagnostic appended.
    bool read(const QString &relativePath, QByteArray *content,
              QList<Diagnostic> *diagnostics) const;

private:
    QString m_root;
    qint64 m_maxBytes;
};

} // namespace rosarch
