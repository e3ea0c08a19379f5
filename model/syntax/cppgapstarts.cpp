#include "syntax/cppgapstarts.h"

#include "syntax/cppcodescan.h"

#include <cstring>
#include <string_view>

namespace rosarch::cppsyntax::scan {

namespace {

qsizetype lastBeforeRegexSpaces(const QByteArray &code, qsizetype i)
{
    --i;
    while (i >= 0 && isRegexSpace(code.at(i)))
        --i;
    return i;
}

// True when `& name (` starts at `at`, the part of the reference pattern every match has.
bool isReferenceCall(const QByteArray &code, qsizetype at)
{
    qsizetype i = skipRegexSpaces(code, at + 1);
    const char first = i < code.size() ? code.at(i) : '\0';
    if (!((first >= 'a' && first <= 'z') || (first >= 'A' && first <= 'Z') || first == '_'))
        return false;
    while (i < code.size() && isIdentifierChar(code.at(i)))
        ++i;
    i = skipRegexSpaces(code, i);
    return i < code.size() && code.at(i) == '(';
}

} // namespace

GapStarts findGapStarts(const QByteArray &code)
{
    GapStarts starts;
    const qsizetype n = code.size();
    const char *s = code.constData();
    qsizetype delimiter = 0; // the last `;`, `{` or `}` before the offset scanned, or 0
    for (qsizetype i = 0; i < n;) {
        const char c = s[i];
        if (!isIdentifierChar(c)) {
            if (c == ';' || c == '{' || c == '}')
                delimiter = i;
            else if (c == '*' && i >= 2 &&
                     ((s[i - 1] == ':' && s[i - 2] == ':') ||
                      (s[i - 1] == '>' && s[i - 2] == '-') ||
                      (s[i - 1] == '.' &&
                       (isIdentifierChar(s[i - 2]) || s[i - 2] == ')' || s[i - 2] == ']'))))
                starts.pointerToMember = true;
            else if (c == '&' && isReferenceCall(code, i) &&
                     (starts.references.empty() || starts.references.back() != delimiter))
                starts.references.push_back(delimiter);
            ++i;
            continue;
        }
        const qsizetype start = i;
        while (i < n && isIdentifierChar(s[i]))
            ++i;
        const std::string_view word(s + start, size_t(i - start));
        if (word.size() < 2 || (word.front() >= '0' && word.front() <= '9'))
            continue;
        if (word.size() > 8) {
            if (word == "returntypename")
                starts.typenames.push_back(start + 6);
            else if (!starts.macroArguments &&
                     (word.starts_with("EXPECT_") || word.starts_with("ASSERT_")) &&
                     word.ends_with("_THROW"))
                starts.macroArguments = true;
            continue;
        }
        if (word == "new") {
            starts.news.push_back(start);
        } else if (word == "template") {
            starts.templates.push_back(start);
            const qsizetype before = lastBeforeRegexSpaces(code, start);
            if (before >= 0 && s[before] == '.')
                starts.members.push_back(before);
            else if (before > 0 && s[before] == '>' && s[before - 1] == '-')
                starts.members.push_back(before - 1);
        } else if (word == "decltype") {
            starts.decltypes.push_back(start);
        } else if (word == "typename") {
            starts.typenames.push_back(start);
        } else if (word == "SIGNAL" || word == "SLOT") {
            starts.macroArguments = true;
        } else if (word == "operator") {
            starts.operators.push_back(start);
        } else if (word == "using") {
            starts.usings.push_back(start);
        } else if (word == "typeid") {
            starts.typeids.push_back(start);
        } else if (word == "for" || word == "while" || word == "if") {
            const qsizetype open = skipRegexSpaces(code, i);
            if (open < n && s[open] == '(')
                starts.heads.push_back(open);
        }
    }
    return starts;
}

std::vector<qsizetype> typenameStarts(const QByteArray &code,
                                      const std::vector<qsizetype> &typenames)
{
    std::vector<qsizetype> out;
    for (const qsizetype at : typenames) {
        const qsizetype before = lastBeforeRegexSpaces(code, at);
        if (before < 0)
            continue;
        if (std::strchr("=(,", code.at(before)) && code.at(before) != '\0')
            out.push_back(before);
        else if (before >= 5 && std::string_view(code.constData() + before - 5, 6) == "return" &&
                 (before == 5 || !isIdentifierChar(code.at(before - 6))))
            out.push_back(before - 5); // `\breturn`, spaces before `typename` or not
    }
    return out;
}

} // namespace rosarch::cppsyntax::scan
