#include "compose/itemports.h"
#include "core/parameterview.h"
#include "core/rosnames.h"

#include <QRegularExpression>
#include <QSet>

#include <algorithm>

// Ports named per item of a list parameter (blueprint §1 "Names per instance").
namespace rosarch {

namespace {

// Whether an item's test is decided false. The test's first part compares the variable that
// the item's parameter is read into; an `else if` chain compares it again
// (`!(type == "scan") && type == "pointcloud" && !topic.empty()`). The test fails when one of
// the parts on that variable is false with the item's value; parts on others are not decided.
bool itemTestFails(const QString &guard, const QString &value)
{
    static const QRegularExpression operand(
        QStringLiteral(R"(^[\s!(]*([A-Za-z_][A-Za-z0-9_.>-]*)\s*(?:==|!=))"));
    const QStringList parts = guard.split(QLatin1String("&&"));
    const QRegularExpressionMatch first = operand.match(parts.constFirst());
    if (!first.hasMatch())
        return false;
    for (const QString &part : parts) {
        if (operand.match(part).captured(1) != first.captured(1))
            continue;
        bool known = false;
        if (!RosNames::evaluateGuard(part.trimmed(), value, &known) && known)
            return true;
    }
    return false;
}

QString unqualified(QString name)
{
    const qsizetype angle = name.indexOf(u'<');
    if (angle >= 0)
        name.truncate(angle);
    return name.section(QLatin1String("::"), -1).trimmed();
}

// Whether plugin class `cls` is, or derives from, the class `base` (unqualified names), through
// the bases of the plugin classes the model knows (`VoxelLayer : ObstacleLayer : CostmapLayer`).
bool derivesFrom(const AtomicNode &cls, const QString &base,
                 const QHash<QString, const AtomicNode *> &byName)
{
    QStringList pending{cls.className};
    QSet<QString> seen;
    constexpr int kMaxBases = 64; // a lineage is a few classes; a bound against odd models
    while (!pending.isEmpty() && seen.size() < kMaxBases) {
        const QString name = unqualified(pending.takeFirst());
        if (name == base)
            return true;
        if (seen.contains(name))
            continue;
        seen.insert(name);
        if (const AtomicNode *known = byName.value(name))
            pending += known->baseClasses;
    }
    return false;
}

// `grid != nullptr && ready`: `ready`. The loop over loaded plugins tests the cast it makes
// to the class that has the port; for a plugin of that class the test holds.
QString withoutNullTests(const QString &guard)
{
    static const QRegularExpression nullTest(QStringLiteral(
        R"(^\s*\(?\s*(?:[A-Za-z_]\w*\s*!=\s*(?:nullptr|NULL)|(?:nullptr|NULL)\s*!=\s*[A-Za-z_]\w*)\s*\)?\s*$)"));
    QStringList kept;
    for (const QString &part : guard.split(QLatin1String("&&"), Qt::SkipEmptyParts))
        if (!nullTest.match(part).hasMatch())
            kept.append(part.trimmed());
    return kept.join(QLatin1String(" && "));
}

QString portKey(const QString &item)
{
    QString key;
    for (const QChar c : item)
        key += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
    return key;
}

} // namespace

const AtomicNode *pluginClass(const QString &value,
                              const QHash<QString, const AtomicNode *> &pluginClasses)
{
    QString written = value.trimmed();
    written.replace(u'/', QLatin1String("::")); // the older pluginlib spelling pkg/Class
    if (written.startsWith(QLatin1String("::")))
        written = written.mid(2);
    return pluginClasses.value(written);
}

QString loadedPluginClass(const Port &p)
{
    const QLatin1String prefix(RosNames::kLoadedPluginPrefix);
    if (p.nameOrigin != NameOrigin::Parameter || !p.parameter.startsWith(prefix) ||
        !p.parameter.endsWith(u'}'))
        return {};
    return p.parameter.mid(prefix.size(), p.parameter.size() - prefix.size() - 1);
}

// `layer->getName() + "_raw"` for each layer a costmap loads: one port per loaded plugin whose
// class derives from the layer class the loop casts to (blueprint §1 "Names per instance").
QList<Port> expandLoadedPlugins(const QList<Port> &ports, const NodeInstance &instance,
                                const QHash<QString, const AtomicNode *> &pluginClasses)
{
    QHash<QString, const AtomicNode *> byName; // unqualified, for the bases as written
    for (const AtomicNode *n : pluginClasses)
        byName.insert(n->className, n);
    QList<Port> out;
    for (const Port &p : ports) {
        const QString base = loadedPluginClass(p);
        const bool aPluginBase =
            !base.isEmpty() &&
            std::any_of(pluginClasses.cbegin(), pluginClasses.cend(),
                        [&](const AtomicNode *n) { return derivesFrom(*n, base, byName); });
        if (!aPluginBase || instance.plugins.isEmpty()) {
            out.append(p); // not a plugin class, or no plugin loaded: only known at run time
            continue;
        }
        for (const ParameterSetting &plugin : instance.plugins) {
            const AtomicNode *cls = pluginClass(plugin.value, pluginClasses);
            Port one = p;
            if (!cls) // a class outside the workspace: it may be one
                one.guard = QStringLiteral("%1 is a %2").arg(plugin.name, base);
            else if (!derivesFrom(*cls, base, byName))
                continue;
            else // the cast's null test (`layer != nullptr`) holds for this plugin
                one.guard = withoutNullTests(p.guard);
            one.id = QStringLiteral("%1_%2").arg(p.id, portKey(plugin.name));
            one.name = p.parameterPrefix + plugin.name + p.parameterSuffix;
            one.parameter.clear(); // decided: the plugin's name
            one.parameterPrefix.clear();
            one.parameterSuffix.clear();
            out.append(one);
        }
    }
    return out;
}

QString settingValue(const NodeInstance &instance, const QString &name, bool *found)
{
    for (const ParameterSetting &p : instance.effectiveParameters) {
        if (p.name == name) {
            *found = true;
            return p.value;
        }
    }
    *found = false;
    return {};
}

// A name per item of a list parameter (blueprint §1 "Names per instance"): the item itself
// (`{node_names}`) or the value of a parameter the item names (`{sources}.topic`). The list
// parameter, or "" when the name is neither.
QString itemList(const Port &p)
{
    static const QRegularExpression item(QStringLiteral("\\{([A-Za-z0-9_.]+)\\}"));
    if (p.nameOrigin != NameOrigin::Parameter)
        return {};
    const QRegularExpressionMatch m = item.match(p.parameter);
    if (!m.hasMatch() || m.captured(0) == QLatin1String(kPluginNamePlaceholder) ||
        m.captured(0) == QLatin1String(kNodeNamePlaceholder) ||
        m.captured(0) == QLatin1String(RosNames::kNamespacePlaceholder))
        return {};
    return m.captured(1);
}

bool itemsPastBound(const Port &p, const NodeInstance &instance)
{
    bool set = false;
    const QString items = settingValue(instance, itemList(p), &set).trimmed();
    if (!set || !items.startsWith(u'['))
        return false;
    QSet<QString> distinct;
    for (const QString &item : parameterListItems(items))
        if (!item.isEmpty())
            distinct.insert(item);
    return distinct.size() > kMaxItemsPerList;
}

// One port per item of the instance's list (`[a, b]`), each named by its item; the port as
// it is when the instance gives no list, its name then only known at run time.
void expandItems(const Port &p, const NodeInstance &instance, QList<Port> *out)
{
    bool set = false;
    const QString list = itemList(p);
    const QString items = settingValue(instance, list, &set).trimmed();
    if (!set || !items.startsWith(u'[') || !items.endsWith(u']')) {
        out->append(p);
        return;
    }
    const QString pattern = QStringLiteral("{%1}").arg(list);
    QSet<QString> seen;
    for (const QString &item : parameterListItems(items)) {
        if (item.isEmpty() || seen.contains(item))
            continue;
        if (seen.size() >= kMaxItemsPerList) { // the rest stay one port, its name undecided
            out->append(p);
            return;
        }
        seen.insert(item);
        Port one = p;
        one.id = QStringLiteral("%1_%2").arg(p.id, portKey(item));
        one.name.replace(pattern, item); // the item, or a default that names it
        if (p.parameter == pattern) {
            one.name = p.parameterPrefix + item + p.parameterSuffix;
            one.parameter.clear(); // decided: the item names it
        } else {
            one.parameter.replace(pattern, item); // `scan.topic`, looked up as any other
            bool set = false;
            settingValue(instance, one.parameter, &set);
            if (!set && p.name.isEmpty()) { // declared without a default, and not given
                one.nameOrigin = NameOrigin::Expression;
                one.name = QStringLiteral("$(%1)").arg(one.parameter);
            }
        }
        // Built per item only where the item passes the test (`{sources}.type == "scan"`);
        // an item the instance does not type keeps the port, undecided.
        if (one.guardParameter.contains(pattern)) {
            one.guardParameter.replace(pattern, item);
            bool typed = false;
            QString value = settingValue(instance, one.guardParameter, &typed);
            if (!typed && !one.guardDefault.isEmpty()) { // the declared default decides
                value = one.guardDefault;
                typed = true;
            }
            if (!typed)
                one.guardParameter.clear();
            else if (itemTestFails(one.guard, value))
                continue;
        }
        out->append(one);
    }
}

} // namespace rosarch
