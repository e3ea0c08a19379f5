#pragma once

#include "nodes/cpp/cppfacts.h"
#include "syntax/cppmacro.h"

#include <QByteArray>

namespace rosarch {

/// The binary form of one C++ file's facts in the analysis cache.
class CppFactsCodec
{
public:
    static QByteArray encode(const CppFileFacts &facts);
    /// False when `bytes` are not a whole, well-formed entry (then `facts` is unspecified).
    static bool decode(const QByteArray &bytes, CppFileFacts *facts);
    /// A hash of `macros` that does not depend on their order in the hash table.
    static QByteArray digest(const CppMacros &macros);
};

} // namespace rosarch
