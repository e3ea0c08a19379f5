#include "core/provenance.h"

namespace rosarch {

QString provenanceName(Provenance provenance)
{
    switch (provenance) {
    case Provenance::Recovered:
        return QStringLiteral("recovered");
    case Provenance::Suggested:
        return QStringLiteral("suggested");
    case Provenance::Corrected:
        return QStringLiteral("corrected");
    }
    return {};
}

} // namespace rosarch
