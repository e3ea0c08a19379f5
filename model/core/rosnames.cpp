#include "rosnames.h"

#include <QRegularExpression>

namespace rosarch::RosNames {

namespace {
QString trimmedNamespace(QString ns)
{
    ns = ns.trimmed();
    while (ns.endsWith(QLatin1Char('/')))
        ns.chop(1);
    if (!ns.isEmpty() && !ns.startsWith(QLatin1Char('/')))
        ns.prepend(QLatin1Char('/'));
    return ns;
}
} // namespace

QString scopeRelative(const QString &name)
{
    const QLatin1String scope(kClassifierScope);
    if (!name.startsWith(scope))
        return name;
    if (name.size() == scope.size())
        return {};
    return name.at(scope.size()) == QLatin1Char('/') ? name.mid(scope.size() + 1) : name;
}

QString fullyQualified(const QString &nameSpace, const QString &nodeName)
{
    return trimmedNamespace(nameSpace) + QLatin1Char('/') + nodeName;
}

QString expand(const QString &name, const QString &nameSpace, const QString &nodeName)
{
    const QString n = name.trimmed();
    if (n.startsWith(QLatin1Char('/')))
        return n;
    if (n == QLatin1String("~"))
        return fullyQualified(nameSpace, nodeName);
    if (n.startsWith(QLatin1String("~/")))
        return fullyQualified(nameSpace, nodeName) + n.mid(1);
    return trimmedNamespace(nameSpace) + QLatin1Char('/') + n;
}

bool isNameRule(const QString &from)
{
    const QString f = from.trimmed();
    return !f.isEmpty() && f != QLatin1String("__node") && f != QLatin1String("__name") &&
           f != QLatin1String("__ns") && !f.contains(QLatin1Char(':'));
}

QString remap(const QString &name, const QList<QPair<QString, QString>> &rules,
              const QString &nameSpace, const QString &nodeName, int *ruleUsed)
{
    // A file analysed on its own stands at the root: its names compare as they would there.
    auto atRoot = [](const QString &expanded) {
        const QString relative = scopeRelative(expanded);
        return relative.startsWith(QLatin1Char('/')) ? relative : QLatin1Char('/') + relative;
    };
    const QString expanded = expand(name, nameSpace, nodeName);
    for (qsizetype i = 0; i < rules.size(); ++i) {
        auto [from, to] = rules.at(i);
        // "node:from" is a rule for one node only (rcl's node-name prefix)
        if (const auto colon = from.indexOf(QLatin1Char(':')); colon > 0 && !from.contains("::")) {
            if (from.left(colon).trimmed() != nodeName)
                continue;
            from = from.mid(colon + 1);
        }
        if (!isNameRule(from) || to.trimmed().isEmpty())
            continue;
        if (atRoot(expand(from, nameSpace, nodeName)) == atRoot(expanded)) {
            if (ruleUsed)
                *ruleUsed = int(i);
            return expand(to, nameSpace, nodeName);
        }
    }
    if (ruleUsed)
        *ruleUsed = -1;
    return expanded;
}

bool truthy(const QString &value, bool *known)
{
    const QString v = value.trimmed().toLower();
    *known = true;
    if (v == QLatin1String("true") || v == QLatin1String("1"))
        return true;
    if (v == QLatin1String("false") || v == QLatin1String("0"))
        return false;
    *known = false;
    return true;
}

bool evaluateGuard(const QString &guard, const QString &parameterValue, bool *known)
{
    // a variable, or the parameter read in place: self.get_parameter('x').value,
    // this->get_parameter("x").as_bool(), node->get_parameter("x").get_value<bool>()
    static const QRegularExpression single(QStringLiteral(
        R"(^\s*(!|not\s+)?\s*(?:(?:this->|self\.)?[A-Za-z_][A-Za-z0-9_]*|)"
        R"((?:[A-Za-z_][A-Za-z0-9_]*(?:->|\.))*get_parameter\s*\(\s*['"][^'"]+['"]\s*\))"
        R"((?:(?:->|\.)[A-Za-z_][A-Za-z0-9_<>]*(?:\(\s*\))?)*)\s*)"
        R"((?:==\s*(true|false|True|False))?\s*$)"));
    const auto m = single.match(guard);
    if (!m.hasMatch()) {
        *known = false;
        return true;
    }
    bool value = truthy(parameterValue, known);
    if (!*known)
        return true;
    const QString compared = m.captured(2).toLower();
    if (compared == QLatin1String("false"))
        value = !value;
    return m.captured(1).isEmpty() ? value : !value;
}

} // namespace rosarch::RosNames
