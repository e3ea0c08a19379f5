#include "core/rosnames.h"

#include <algorithm>
#include <optional>

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

QString withParentNamespace(const QString &name, const QString &nodeNamespace)
{
    const QString prefix = QLatin1String(kParentNamespacePlaceholder) + QLatin1Char('/');
    if (!name.startsWith(prefix))
        return name;
    const QString rest = name.mid(prefix.size());
    if (rest.startsWith(u'/'))
        return rest;
    QString ns = nodeNamespace;
    while (ns.endsWith(u'/'))
        ns.chop(1);
    return ns.left(std::max<qsizetype>(0, ns.lastIndexOf(u'/'))) + QLatin1Char('/') + rest;
}

QString withNamespace(const QString &name, const QString &ns)
{
    const QLatin1String placeholder(kNamespacePlaceholder);
    if (!name.contains(placeholder))
        return name;
    QString root = ns;
    while (root.endsWith(u'/'))
        root.chop(1);
    if (!root.isEmpty() && !root.startsWith(u'/'))
        root.prepend(u'/');
    QString out = name;
    out.replace(placeholder + QLatin1Char('/'), root + QLatin1Char('/'));
    out.replace(placeholder, root.isEmpty() ? QStringLiteral("/") : root);
    return out;
}

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

namespace {

/// `text` without parentheses that wrap all of it: "((x))" -> "x"; "(a) && (b)" stays.
QString unwrapped(QString text)
{
    for (int bound = 0; bound < 16; ++bound) {
        text = text.trimmed();
        if (!text.startsWith(QLatin1Char('(')) || !text.endsWith(QLatin1Char(')')))
            return text;
        int depth = 0;
        for (qsizetype i = 0; i < text.size(); ++i) {
            depth += text.at(i) == QLatin1Char('(') ? 1 : text.at(i) == QLatin1Char(')') ? -1 : 0;
            if (depth == 0 && i + 1 < text.size())
                return text; // the first parenthesis closes before the end
        }
        text = text.mid(1, text.size() - 2);
    }
    return text;
}

/// The literal a guard compares with: a bool, a number or a quoted string, as its text.
std::optional<QString> literalOf(const QString &text)
{
    const QString t = text.trimmed();
    if (t.size() >= 2 && (t.front() == QLatin1Char('"') || t.front() == QLatin1Char('\'')) &&
        t.back() == t.front() && !t.mid(1, t.size() - 2).contains(t.front()))
        return t.mid(1, t.size() - 2);
    static const QRegularExpression plain(
        QStringLiteral(R"(^(true|false|True|False|-?\d+(\.\d+)?)$)"));
    if (plain.match(t).hasMatch())
        return t;
    return std::nullopt;
}

} // namespace

bool evaluateGuard(const QString &guard, const QString &parameterValue, bool *known)
{
    // a variable, or the parameter read in place: self.get_parameter('x').value,
    // this->get_parameter("x").as_bool(), node->get_parameter("x").get_value<bool>()
    static const QRegularExpression single(QStringLiteral(
        R"(^\s*(?:(?:this->|self\.)?[A-Za-z_][A-Za-z0-9_]*|)"
        R"((?:[A-Za-z_][A-Za-z0-9_]*(?:->|\.))*get_parameter\s*\(\s*['"][^'"]+['"]\s*\))"
        R"((?:(?:->|\.)[A-Za-z_][A-Za-z0-9_<>]*(?:\(\s*\))?)*)\s*$)"));
    *known = false;
    QString text = unwrapped(guard);
    bool negated = false;
    for (int bound = 0; bound < 16; ++bound) { // !x, not x, !(x), !!x
        if (text.startsWith(QLatin1Char('!')) && !text.startsWith(QLatin1String("!="))) {
            text = unwrapped(text.mid(1));
        } else if (text.startsWith(QLatin1String("not ")) ||
                   text.startsWith(QLatin1String("not("))) {
            text = unwrapped(text.mid(3));
        } else {
            break;
        }
        negated = !negated;
    }
    // x == literal, x != literal (a bool, a number, or a string: an enum-like parameter)
    static const QRegularExpression comparison(QStringLiteral(R"(^(.+?)\s*(==|!=)\s*(.+)$)"));
    QString operand = text;
    std::optional<QString> literal;
    bool equal = true;
    if (const auto m = comparison.match(text); m.hasMatch()) {
        literal = literalOf(m.captured(3));
        if (!literal)
            return true;
        operand = unwrapped(m.captured(1));
        equal = m.captured(2) == QLatin1String("==");
    }
    if (!single.match(operand).hasMatch())
        return true;
    bool value = false;
    bool boolLiteral = false;
    const bool wanted = literal ? truthy(*literal, &boolLiteral) : true;
    if (!literal || (boolLiteral && !literal->front().isDigit())) { // x, x == true
        value = truthy(parameterValue, known);
        if (!*known)
            return true;
        value = value == wanted;
    } else { // x == 3, x == "fast": compared as numbers when both are, else as text
        bool okA = false, okB = false;
        const double a = parameterValue.trimmed().toDouble(&okA), b = literal->toDouble(&okB);
        value = okA && okB ? a == b : parameterValue == *literal;
        *known = true;
    }
    if (!equal)
        value = !value;
    return negated ? !value : value;
}

} // namespace rosarch::RosNames
