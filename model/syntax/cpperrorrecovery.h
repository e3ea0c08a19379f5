#pragma once

#include "core/diagnostic.h"
#include "syntax/syntaxtree.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <vector>

namespace rosarch {

/// Keeps a syntax error in C++ from costing more than the declaration it is in. Tree-sitter
/// recovers from an error by guessing, and a wrong guess (a stray `}`, an unbalanced `(`)
/// can close a class early or fold the rest of it into an ERROR node, losing every member
/// after it. Instead, the smallest range around the first error whose blanking lets the file
/// parse cleanly up to that point is overwritten with spaces (newlines kept, so lines and
/// columns of the rest stay as written) and the file is parsed again, a bounded number of
/// times.
class CppErrorRecovery
{
public:
    /// Parses again at most this many times per file.
    static constexpr int kMaxReparses = 12;
    /// A candidate range longer than this many lines is not blanked.
    static constexpr int kMaxBlankedLines = 60;

    /// Parses `source` (the text of `file`), blanking broken declarations as needed; appends one
    /// `syntax-error` warning naming the lines that were left out. Errors that could not be
    /// isolated stay in the tree.
    static SyntaxTree parse(QByteArray source, const QString &file, QList<Diagnostic> *diagnostics);

    /// The ERROR and MISSING nodes that are not macro artifacts, in source order, outermost.
    static std::vector<TSNode> realErrors(const SyntaxTree &tree);

    /// True for an error the parser makes on code that compiles once its macros are expanded:
    /// a format macro after a string ("%" PRId64), an export macro before a declaration, a
    /// registration macro without a semicolon, an `extern "C"` split across #ifdef.
    static bool isMacroArtifact(const SyntaxTree &tree, TSNode n);
};

} // namespace rosarch
