#pragma once

#include <QByteArray>

#include <string_view>

// Macros the grammar cannot read where they stand, rewritten for the parser
// (cppsyntax::blankGrammarGaps). Offsets are byte offsets into the source.
namespace rosarch::cppsyntax::macros {

/// A name in capitals with an underscore, four characters or more: `RCPPUTILS_TSA_REQUIRES`.
bool isMacroWord(std::string_view word);
/// True when the code before `i` ends a statement or a member: `;`, `{`, `}`, or an access
/// specifier's `:`.
bool atStatementStart(const QByteArray &code, qsizetype i);

/// Rewrites, in `data` (the source `code` was made from by codeOnly, same offsets) and in
/// `code` alike:
/// - a macro constant between string literals, `"/ns/" TOPIC "/x"`: the single spaces around
///   it become `+`, an expression with the name in it; after a number (`0.01f METERS`) the unit
///   macro is blanked;
/// - a macro call with a `;` where only declarations stand (a class, a namespace, the file):
///   `FRIEND_TEST(T, 3_wheels);`, `MOCK_METHOD(int, f, (), (const, override));`;
/// - an annotation after a declarator, before its `;` or body:
///   `x_ RCPPUTILS_TSA_GUARDED_BY(m);`, `void f() const RCPPUTILS_TSA_REQUIRES(m);`;
/// - an attribute macro before a declaration, `TF2SIMD_FORCE_INLINE T & f()`, and
///   `ATTRIBUTE_ALIGNED16(class) Q` (which keeps its `class`).
/// The registration macros the analysis reads from the text stay.
void rewriteMacroGaps(QByteArray *code, char *data);

} // namespace rosarch::cppsyntax::macros
