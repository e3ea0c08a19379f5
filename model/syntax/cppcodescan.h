#pragma once

#include <QByteArray>

#include <string_view>
#include <utility>
#include <vector>

// Scanning C++ source text byte by byte, for the rewrites of code the grammar cannot read
// (cppgrammargaps.cpp). Offsets are byte offsets into the source.
namespace rosarch::cppsyntax::scan {

/// ASCII letters, digits and `_` (inline, without the locale: it runs on every byte of a file).
inline bool isIdentifierChar(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// The source with comments, preprocessor lines and the contents of string and character
/// literals overwritten by spaces (newlines kept), so that a rewrite only ever sees code: a
/// pattern inside a string or a comment stays as written. One pass, linear.
QByteArray codeOnly(const QByteArray &source);

/// The last non-blank offset before `i`, -1 when none.
qsizetype previousCode(const QByteArray &code, qsizetype i);
/// The first non-blank offset at or after `i`, the size when none.
qsizetype nextCode(const QByteArray &code, qsizetype i);
/// True when `word` stands at `i` as a whole identifier.
bool isWordAt(const QByteArray &code, qsizetype i, std::string_view word);
/// +1 for an opening bracket, -1 for a closing one, else 0.
int nesting(char c);
/// The offset of the `)` closing the `(` at `open`, -1 when it does not close before `limit`.
qsizetype closingParen(const QByteArray &code, qsizetype open, qsizetype limit);
/// The identifier ending at `end` (exclusive), empty when `end` ends none.
std::string_view wordEndingAt(const QByteArray &code, qsizetype end);

/// The arguments in the parentheses at [open, close] that are a built-in type (`int`,
/// `unsigned char`, `const char *`), as [from, to) offsets: no function takes one, only a macro.
std::vector<std::pair<qsizetype, qsizetype>> builtinTypeArguments(const QByteArray &code,
                                                                  qsizetype open, qsizetype close);

/// True when `text` occurs in `code` (glibc's memmem: several times faster than
/// QByteArray::contains on the short needles the rewrites gate on).
bool contains(const QByteArray &code, std::string_view text);
/// The next identifier at or after `*i`, empty at the end of `code`; `*i` moves past it.
std::string_view nextWord(const QByteArray &code, qsizetype *i);

} // namespace rosarch::cppsyntax::scan
