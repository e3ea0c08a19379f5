#pragma once

#include <QByteArray>

#include <vector>

// Where the rewrites of cppsyntax::blankGrammarGaps can apply, found in one scan over the code.
namespace rosarch::cppsyntax::scan {

/// Where the regular expressions of the rewrites can match: each starts at a word found in
/// one scan over the code (or just before it), so that a pattern is tried at those offsets
/// only, not at every offset of the file. Offsets ascend.
struct GapStarts
{
    std::vector<qsizetype> news;      ///< `new`
    std::vector<qsizetype> templates; ///< `template`
    std::vector<qsizetype> members;   ///< `.template` / `->template`: the `.` or `-`
    std::vector<qsizetype> decltypes; ///< `decltype`
    std::vector<qsizetype> typenames; ///< `typename`, `returntypename`
    std::vector<qsizetype> operators; ///< `operator`
    std::vector<qsizetype> usings;    ///< `using`
    std::vector<qsizetype> typeids;   ///< `typeid`
    /// `for (`, `while (`, `if (`: the offset of the `(`
    std::vector<qsizetype> heads;
    /// `const T & name(`: the `;`, `{` or `}` before (or 0) of each `& name(`
    std::vector<qsizetype> references;
    bool macroArguments = false;  ///< SIGNAL, SLOT, EXPECT_..._THROW, ASSERT_..._THROW
    bool pointerToMember = false; ///< `::*`, `->*` or `.*`
};

/// The starts in `code` (the output of codeOnly).
GapStarts findGapStarts(const QByteArray &code);

/// Where the pattern of `= typename T::Goal()` can match for each of `typenames`: at the `=`,
/// `(`, `,` or `return` before it.
std::vector<qsizetype> typenameStarts(const QByteArray &code,
                                      const std::vector<qsizetype> &typenames);

/// PCRE's \s without Unicode properties, so that offsets are those the expressions match.
inline bool isRegexSpace(char c)
{
    return c == ' ' || (c >= '\t' && c <= '\r');
}

/// The first offset at or after `i` that is no regex space, the size when none.
inline qsizetype skipRegexSpaces(const QByteArray &code, qsizetype i)
{
    while (i < code.size() && isRegexSpace(code.at(i)))
        ++i;
    return i;
}

} // namespace rosarch::cppsyntax::scan
