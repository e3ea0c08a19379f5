#pragma once

#include "core/evidence.h"

#include <QList>
#include <QString>

namespace rosarch {

/// One scalar attribute of a frontend entity: `name="value"` in XML, `name: value` in YAML.
struct FrontendAttribute
{
    QString name;
    QString value;
    Evidence evidence;
};

/// A launch entity as the XML and YAML frontends define it, independent of the format: a type
/// (`node`, `group`, ...), scalar attributes, and nested entities in document order. In XML the
/// nested entities are the child elements; in YAML they are the items of `children` (typed by
/// their single key) and the mappings listed under any other key (typed by that key, as
/// `param: [{name: a, value: 1}]`).
struct FrontendEntity
{
    QString type;
    Evidence evidence;
    QList<FrontendAttribute> attributes;
    QList<FrontendEntity> children;

    /// The attribute called `name`, or nullptr.
    const FrontendAttribute *attribute(const QString &name) const;
    /// The nested entities of one type, in document order.
    QList<const FrontendEntity *> childrenOfType(const QString &type) const;
};

} // namespace rosarch
