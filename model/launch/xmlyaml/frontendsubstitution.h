#pragma once

#include "core/substitution.h"

#include <QString>

namespace rosarch {

/// Parses the `$(...)` substitution language that the ROS 2 XML and YAML launch frontends use
/// in attribute values, e.g. "$(find-pkg-share $(var pkg))/config/a.yaml".
class FrontendSubstitution
{
public:
    /// Parses one attribute value. A syntax error (unbalanced parentheses, an unterminated
    /// quote) gives an Unknown substitution holding the whole value and sets `error`.
    static Substitution parse(const QString &value, QString *error = nullptr);
};

} // namespace rosarch
