#include "itemports.h"
#include "parameterview.h"
#include "rosnames.h"

#include <QRegularExpression>
#include <QSet>

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

} // namespace

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
        m.captured(0) == QLatin1String(kNodeNamePlaceholder))
        return {};
    return m.captured(1);
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
        seen.insert(item);
        Port one = p;
        QString key;
        for (const QChar c : item)
            key += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
        one.id = QStringLiteral("%1_%2").arg(p.id, key);
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
