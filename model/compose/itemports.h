#pragma once

#include "launchdependencies.h"
#include "port.h"

#include <QList>
#include <QString>

namespace rosarch {

/// The value an instance gives parameter `name` (launch, file or declared default); `found`
/// says whether it gives one.
QString settingValue(const NodeInstance &instance, const QString &name, bool *found);

/// The list parameter whose items name port `p` (`{node_names}`, `{sources}.topic`), or "".
QString itemList(const Port &p);

/// One port per item of the instance's value of `itemList(p)`, appended to `out`: named by the
/// item, or read from the parameter the item names; an item whose test (`{sources}.type`)
/// fails gets none. Without a list value the port is appended as it is.
void expandItems(const Port &p, const NodeInstance &instance, QList<Port> *out);

} // namespace rosarch
