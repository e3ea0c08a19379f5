#pragma once

// Launch descriptions read from XML and YAML.
#include "core/substitution.h"

namespace rosarch::test {

// Launch descriptions read from XML and YAML.
namespace launch {

/// A $(var name) substitution.
inline Substitution var(const QString &name)
{
    return Substitution::configuration(name);
}

} // namespace launch

} // namespace rosarch::test
