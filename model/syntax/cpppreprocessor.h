#pragma once

#include "core/diagnostic.h"
#include "syntax/cppmacro.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <functional>

namespace rosarch {

/// The part of the C preprocessor that the parser needs: conditional compilation. Evaluates
/// `#if`, `#ifdef`, `#ifndef`, `#elif`, `#else`, `#endif` with the macros known and overwrites
/// the inactive branches and the conditional directives themselves with spaces, keeping every
/// newline, so lines and columns of the rest stay as written. `#define`, `#undef` and
/// `#include` in active code update the macros. Nothing is expanded in the code itself.
///
/// A condition that cannot be decided (a function-like macro such as
/// `RCLCPP_VERSION_GTE(28, 0, 0)` or `__has_include(<x>)`) is taken as true: its branch is
/// kept and the later `#elif` / `#else` branches are dropped, with a `preprocessor-guess`
/// note naming the condition. Unbalanced directives give `preprocessor-malformed`.
class CppPreprocessor
{
public:
    /// The macros a workspace header defines (its exports), for an `#include` as written
    /// ("pkg/x.hpp", angled or not); null when the header is not one of the workspace's.
    using IncludeLookup = std::function<const CppMacros *(const QByteArray &written, bool angled)>;

    struct Result
    {
        CppMacros macros;   ///< in effect at the end of the file, the initial ones included
        CppMacros exported; ///< defined by the file or the headers it includes, without its guard
        QList<Diagnostic> diagnostics;
    };

    /// Conditionals nested deeper than this are not evaluated: their first branch is kept.
    static constexpr int kMaxDepth = 64;
    /// Notes about undecidable conditions per file; the rest are counted in one more note.
    static constexpr int kMaxGuessNotes = 10;

    /// Blanks the inactive parts of `source` (the text of `file`), starting from `initial`.
    static Result run(QByteArray *source, const QString &file, const CppMacros &initial,
                      const IncludeLookup &lookup = {});

    /// The string a macro body stands for when it is string literals and `macros` standing for
    /// strings ("a" B "c" -> "abc"), or its text when it is a number; null otherwise.
    static QString constantValue(const QByteArray &body, const CppMacros &macros = {});

    /// The string a function-like macro call stands for when its body, with the arguments (as
    /// written) put in for the parameters and `#param` made a string, is a constant as above:
    /// `#define TOPIC(x) "robot/" x`, `TOPIC("scan")` -> "robot/scan". Null otherwise, and for
    /// token pasting (`##`) or a wrong number of arguments.
    static QString expandedValue(const CppMacro &macro, const QList<QByteArray> &arguments,
                                 const CppMacros &macros = {});
};

} // namespace rosarch
