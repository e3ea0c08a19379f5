#pragma once

#include <QByteArray>
#include <QHash>
#include <QList>

namespace rosarch {

/// A preprocessor macro as a `#define` (or a -D compile definition) makes it.
struct CppMacro
{
    QByteArray body; ///< replacement text, continuation lines joined, comments removed
    QList<QByteArray> parameters;
    bool functionLike = false;

    bool operator==(const CppMacro &) const = default;
};

/// Macros by name.
using CppMacros = QHash<QByteArray, CppMacro>;

} // namespace rosarch
