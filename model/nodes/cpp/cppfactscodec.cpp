#include "nodes/cpp/cppfactscodec.h"
#include "cache/sha1.h"

#include "cache/cachecodec.h"
#include "nodes/cpp/cppfactsfields.h"

#include <algorithm>

// The facts are serialised through their field lists (cppfactsfields.h).

namespace rosarch {

QByteArray CppFactsCodec::encode(const CppFileFacts &facts)
{
    return cachecodec::encode(facts);
}

bool CppFactsCodec::decode(const QByteArray &bytes, CppFileFacts *facts)
{
    return cachecodec::decode(bytes, facts);
}

QByteArray CppFactsCodec::digest(const CppMacros &macros)
{
    QList<QByteArray> names = macros.keys();
    std::sort(names.begin(), names.end());
    Sha1 hash;
    for (const QByteArray &name : std::as_const(names)) {
        const CppMacro &m = *macros.constFind(name);
        // Separators that cannot occur in a name, a body or a parameter.
        hash.addData(name);
        hash.addData(QByteArrayView("\0", 1));
        hash.addData(m.body);
        hash.addData(QByteArrayView(m.functionLike ? "\1(" : "\1", m.functionLike ? 2 : 1));
        for (const QByteArray &p : m.parameters) {
            hash.addData(p);
            hash.addData(QByteArrayView("\2", 1));
        }
        hash.addData(QByteArrayView("\3", 1));
    }
    return hash.result();
}

} // namespace rosarch
