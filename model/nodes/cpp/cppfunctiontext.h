#pragma once
// Small text and node checks shared by the parts of CppFunctionExtractor.
#include "syntax/syntaxtree.h"

#include <QString>

#include <algorithm>

namespace rosarch::cppfunctiontext {

inline bool nodesEqual(TSNode a, TSNode b)
{
    return !ts::isNull(a) && !ts::isNull(b) && ts_node_eq(a, b);
}

inline bool isAscii(const QString &s)
{
    return std::all_of(s.cbegin(), s.cend(), [](QChar c) { return c.unicode() < 0x80; });
}

inline bool hasLowerCase(const QString &ascii)
{
    return std::any_of(ascii.cbegin(), ascii.cend(),
                       [](QChar c) { return c.unicode() >= 'a' && c.unicode() <= 'z'; });
}

} // namespace rosarch::cppfunctiontext
