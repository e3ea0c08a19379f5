#pragma once

#include "core/diagnostic.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace rosarch {

/// Keeps one syntax error from hiding a whole Python file: tree-sitter may fold everything after
/// a broken statement into one ERROR node. The top-level blocks that do not parse on their own
/// are blanked (same byte positions, so evidence stays exact) and reported.
class PythonErrorRecovery
{
public:
    /// Returns `source` with the broken top-level blocks replaced by spaces, and appends one
    /// diagnostic per syntax error found in them. Unchanged when every block parses.
    static QByteArray isolate(const QByteArray &source, const QString &file,
                              QList<Diagnostic> *diagnostics);
};

} // namespace rosarch
