#include "launch/xmlyaml/frontendentity.h"

namespace rosarch {

const FrontendAttribute *FrontendEntity::attribute(const QString &name) const
{
    for (const FrontendAttribute &a : attributes) {
        if (a.name == name)
            return &a;
    }
    return nullptr;
}

QList<const FrontendEntity *> FrontendEntity::childrenOfType(const QString &type) const
{
    QList<const FrontendEntity *> out;
    for (const FrontendEntity &c : children) {
        if (c.type == type)
            out << &c;
    }
    return out;
}

} // namespace rosarch
