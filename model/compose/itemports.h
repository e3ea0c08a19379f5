#pragma once

#include "core/atomicnode.h"
#include "core/launchdependencies.h"
#include "core/port.h"

#include <QHash>
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
/// fails gets none. Without a list value the port is appended as it is. Past
/// kMaxItemsPerList distinct items the rest stay one port, its name undecided.
void expandItems(const Port &p, const NodeInstance &instance, QList<Port> *out);
/// A list of names written in a parameter file is short: this many items are expanded.
inline constexpr qsizetype kMaxItemsPerList = 256;
/// Whether the instance's list for port `p` has more distinct items than expandItems expands.
bool itemsPastBound(const Port &p, const NodeInstance &instance);

/// The plugin class a `<name>.plugin` value names (`pkg::Class`, or the older `pkg/Class`)
/// among `pluginClasses` (by qualified name); null when the model has none of that name.
const AtomicNode *pluginClass(const QString &value,
                              const QHash<QString, const AtomicNode *> &pluginClasses);

/// The class `{plugin:Type}` names in port `p`'s parameter (a name per loaded plugin of that
/// class, RosNames' kLoadedPluginPrefix), or "".
QString loadedPluginClass(const Port &p);

/// The ports of `ports` with one port per plugin the instance loads whose class is, or derives
/// from, the class `{plugin:Type}` names, each named by the plugin's name; `pluginClasses` are
/// the model's plugin classes by qualified name. A port whose class no plugin class of the
/// model derives from, or whose instance loads no plugin, stays as it is.
QList<Port> expandLoadedPlugins(const QList<Port> &ports, const NodeInstance &instance,
                                const QHash<QString, const AtomicNode *> &pluginClasses);

} // namespace rosarch
