#include "syntax/cppcodescan.h"

#include <QRegularExpression>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace rosarch::cppsyntax::scan {

namespace {

// The end of the line at `i`, a backslash-continued line included.
qsizetype endOfLogicalLine(const char *s, qsizetype n, qsizetype i)
{
    while (i < n) {
        if (s[i] == '\n') {
            const bool continued =
                (i > 0 && s[i - 1] == '\\') || (i > 1 && s[i - 1] == '\r' && s[i - 2] == '\\');
            if (!continued)
                return i;
        }
        ++i;
    }
    return n;
}

} // namespace

QByteArray codeOnly(const QByteArray &source)
{
    QByteArray out = source;
    const char *s = source.constData();
    char *o = out.data();
    const qsizetype n = source.size();
    auto blank = [&](qsizetype from, qsizetype to) {
        for (qsizetype i = from; i < std::min(to, n); ++i)
            if (s[i] != '\n' && s[i] != '\r')
                o[i] = ' ';
    };
    bool lineStart = true;
    qsizetype wordStart = -1;
    qsizetype wordEnd = -1;
    for (qsizetype i = 0; i < n;) {
        const char c = s[i];
        const char next = i + 1 < n ? s[i + 1] : '\0';
        if (c == '\n') {
            lineStart = true;
            ++i;
            continue;
        }
        if (lineStart && (c == ' ' || c == '\t' || c == '\r')) {
            ++i;
            continue;
        }
        if (lineStart && c == '#') {
            const qsizetype end = endOfLogicalLine(s, n, i);
            blank(i, end);
            i = end;
            continue;
        }
        lineStart = false;
        if (c == '/' && next == '/') {
            const qsizetype end = endOfLogicalLine(s, n, i);
            blank(i, end);
            i = end;
            continue;
        }
        if (c == '/' && next == '*') {
            const qsizetype close = source.indexOf("*/", i + 2);
            const qsizetype end = close < 0 ? n : close + 2;
            blank(i, end);
            i = end;
            continue;
        }
        if (c == '"') {
            // A raw string's prefix is the identifier right before the quote.
            const std::string_view prefix =
                wordEnd == i ? std::string_view(s + wordStart, size_t(i - wordStart))
                             : std::string_view();
            const bool raw = prefix == "R" || prefix == "u8R" || prefix == "uR" || prefix == "UR" ||
                             prefix == "LR";
            if (raw) {
                qsizetype open = i + 1; // the delimiter has at most 16 characters
                while (open < std::min(n, i + 18) && s[open] != '(' && s[open] != '\n')
                    ++open;
                if (open < n && s[open] == '(') {
                    const QByteArray close = ')' + source.mid(i + 1, open - i - 1) + '"';
                    const qsizetype at = source.indexOf(close, open + 1);
                    const qsizetype end = at < 0 ? n : at + close.size();
                    blank(i + 1, end - 1);
                    i = end;
                    continue;
                }
            }
            qsizetype j = i + 1;
            while (j < n && s[j] != '"' && s[j] != '\n')
                j += s[j] == '\\' ? 2 : 1;
            blank(i + 1, j);
            i = j + 1;
            continue;
        }
        if (c == '\'') { // a character literal: digit separators are consumed with their number
            qsizetype j = i + 1;
            while (j < n && s[j] != '\'' && s[j] != '\n')
                j += s[j] == '\\' ? 2 : 1;
            blank(i + 1, j);
            i = j + 1;
            continue;
        }
        if (std::isdigit(uchar(c)) || (c == '.' && std::isdigit(uchar(next)))) {
            qsizetype j = i + 1;
            while (j < n &&
                   (isIdentifierChar(s[j]) || s[j] == '.' || s[j] == '\'' ||
                    ((s[j] == '+' || s[j] == '-') && std::strchr("eEpP", s[j - 1]) != nullptr)))
                ++j;
            i = j;
            continue;
        }
        if (isIdentifierChar(c)) {
            wordStart = i;
            while (i < n && isIdentifierChar(s[i]))
                ++i;
            wordEnd = i;
            continue;
        }
        ++i;
    }
    return out;
}

qsizetype previousCode(const QByteArray &code, qsizetype i)
{
    --i;
    while (i >= 0 && std::isspace(uchar(code.at(i))))
        --i;
    return i;
}

qsizetype nextCode(const QByteArray &code, qsizetype i)
{
    while (i < code.size() && std::isspace(uchar(code.at(i))))
        ++i;
    return i;
}

bool isWordAt(const QByteArray &code, qsizetype i, std::string_view word)
{
    const qsizetype end = i + qsizetype(word.size());
    return i >= 0 && end <= code.size() &&
           std::string_view(code.constData() + i, word.size()) == word &&
           (i == 0 || !isIdentifierChar(code.at(i - 1))) &&
           (end == code.size() || !isIdentifierChar(code.at(end)));
}

int nesting(char c)
{
    return (c == '(' || c == '[' || c == '{') ? 1 : (c == ')' || c == ']' || c == '}') ? -1 : 0;
}

qsizetype closingParen(const QByteArray &code, qsizetype open, qsizetype limit)
{
    limit = std::min(limit, code.size());
    for (qsizetype i = open, depth = 0; i < limit; ++i) {
        const char c = code.at(i);
        if (c == '(' || c == '[' || c == '{')
            ++depth;
        else if ((c == ')' || c == ']' || c == '}') && --depth == 0)
            return c == ')' ? i : -1;
    }
    return -1;
}

std::string_view wordEndingAt(const QByteArray &code, qsizetype end)
{
    qsizetype start = end;
    while (start > 0 && isIdentifierChar(code.at(start - 1)))
        --start;
    return {code.constData() + start, size_t(end - start)};
}

std::vector<std::pair<qsizetype, qsizetype>> builtinTypeArguments(const QByteArray &code,
                                                                  qsizetype open, qsizetype close)
{
    static const QRegularExpression builtin(
        QStringLiteral("^\\s*(?:(?:const|unsigned|signed|short|long|int|char|float|double|bool|"
                       "void|wchar_t|char8_t|char16_t|char32_t|size_t|u?int(?:8|16|32|64)_t)\\b"
                       "\\s*)+[*&\\s]*$"));
    std::vector<std::pair<qsizetype, qsizetype>> found;
    qsizetype from = open + 1;
    for (qsizetype i = open + 1, depth = 0; i <= close; ++i) {
        const char c = code.at(i);
        if (depth == 0 && (c == ',' || i == close)) {
            if (builtin.match(QString::fromLatin1(code.mid(from, i - from))).hasMatch())
                found.emplace_back(from, i);
            from = i + 1;
        }
        depth += nesting(c);
    }
    return found;
}

bool contains(const QByteArray &code, std::string_view text)
{
    return memmem(code.constData(), size_t(code.size()), text.data(), text.size()) != nullptr;
}

std::string_view nextWord(const QByteArray &code, qsizetype *i)
{
    const qsizetype n = code.size();
    while (*i < n && !isIdentifierChar(code.at(*i)))
        ++*i;
    const qsizetype start = *i;
    while (*i < n && isIdentifierChar(code.at(*i)))
        ++*i;
    return {code.constData() + start, size_t(*i - start)};
}

} // namespace rosarch::cppsyntax::scan
