#pragma once

#include <QString>

namespace rosarch {

/// Where a recovered element comes from: a file relative to the workspace root and a
/// 1-based line/column range (columns count UTF-8 bytes, end is exclusive).
struct Evidence
{
    QString file;
    int line = 0;
    int column = 0;
    int endLine = 0;
    int endColumn = 0;

    /// The start of `file` (line 1, column 1): for what concerns a file as a whole.
    static Evidence startOf(const QString &file) { return {file, 1, 1, 1, 1}; }

    bool isValid() const { return !file.isEmpty() && line > 0; }
    /// True when the 1-based line lies within this range.
    bool containsLine(int l) const { return isValid() && l >= line && l <= endLine; }
    bool operator==(const Evidence &) const = default;
};

/// Source order: by file, then line, then column.
inline bool evidenceLess(const Evidence &a, const Evidence &b)
{
    if (a.file != b.file)
        return a.file < b.file;
    if (a.line != b.line)
        return a.line < b.line;
    return a.column < b.column;
}

} // namespace rosarch
