#include "core/parameter.h"

#include <QRegularExpression>

namespace rosarch {

namespace {

QString scalarType(const QString &text, bool quoted)
{
    if (quoted)
        return QStringLiteral("string");
    const QString t = text.trimmed();
    // what rcl_yaml_param_parser takes for a bool
    static const QStringList bools{
        QStringLiteral("true"),  QStringLiteral("True"),  QStringLiteral("TRUE"),
        QStringLiteral("false"), QStringLiteral("False"), QStringLiteral("FALSE"),
        QStringLiteral("yes"),   QStringLiteral("Yes"),   QStringLiteral("YES"),
        QStringLiteral("no"),    QStringLiteral("No"),    QStringLiteral("NO"),
        QStringLiteral("on"),    QStringLiteral("On"),    QStringLiteral("ON"),
        QStringLiteral("off"),   QStringLiteral("Off"),   QStringLiteral("OFF")};
    if (bools.contains(t))
        return QStringLiteral("bool");
    static const QRegularExpression integer(QStringLiteral("^[-+]?(0x[0-9a-fA-F]+|[0-9]+)$"));
    if (integer.match(t).hasMatch())
        return QStringLiteral("integer");
    static const QRegularExpression real(
        QStringLiteral("^[-+]?(([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?|\\.inf|\\.Inf|"
                       "\\.INF|\\.nan|\\.NaN|\\.NAN)$"));
    if (real.match(t).hasMatch())
        return QStringLiteral("double");
    return QStringLiteral("string");
}

} // namespace

QString parameterValueType(const QString &text, bool quoted)
{
    const QString t = text.trimmed();
    // a substitution the file leaves to launch (`allow_substs`), or a value that rests on a
    // launch argument nobody set: its type is not known here
    if (t.contains(QLatin1String("$(")) || (t.isEmpty() && !quoted))
        return {};
    if (quoted || !t.startsWith(QLatin1Char('[')) || !t.endsWith(QLatin1Char(']')))
        return scalarType(t, quoted);
    const QString inner = t.mid(1, t.size() - 2).trimmed();
    if (inner.isEmpty())
        return {};
    const QString first = inner.section(QLatin1Char(','), 0, 0);
    return scalarType(first, false) + QStringLiteral("_array");
}

bool parameterTypeAccepts(const QString &declared, const QString &given)
{
    if (declared.isEmpty() || given.isEmpty() || declared == given)
        return true;
    // an empty list fits any array; bytes are written as integers
    if (declared == QLatin1String("byte_array"))
        return given == QLatin1String("integer_array");
    return false;
}

QString parameterTypeOfWritten(const QString &written)
{
    QString t = written.simplified().remove(u' ');
    t.remove(QStringLiteral("const"));
    t.remove(u'&');
    static const QRegularExpression constant(QStringLiteral("PARAMETER_([A-Z_]+)$"));
    const QRegularExpressionMatch m = constant.match(t);
    if (m.hasMatch()) {
        const QString k = m.captured(1).toLower();
        if (k == QLatin1String("not_set"))
            return {};
        return k;
    }
    static const QRegularExpression list(
        QStringLiteral("^(std::vector|vector|List|list|Sequence|typing\\.List)[<\\[](.*)[>\\]]$"));
    const QRegularExpressionMatch l = list.match(t);
    if (l.hasMatch()) {
        const QString element = l.captured(2);
        if (element == QLatin1String("uint8_t") || element == QLatin1String("unsigned char") ||
            element == QLatin1String("bytes"))
            return QStringLiteral("byte_array");
        const QString e = parameterTypeOfWritten(element);
        return e.isEmpty() || e.endsWith(QLatin1String("_array")) ? QString()
                                                                  : e + QStringLiteral("_array");
    }
    if (t == QLatin1String("bool"))
        return QStringLiteral("bool");
    if (t == QLatin1String("double") || t == QLatin1String("float"))
        return QStringLiteral("double");
    static const QRegularExpression integer(QStringLiteral(
        "^(std::)?(u?int(8|16|32|64)?(_t)?|long|longlong|unsignedint|unsigned|"
        "short|size_t|int64|rcl_interfaces::msg::ParameterType::PARAMETER_INTEGER)$"));
    if (integer.match(t).hasMatch())
        return QStringLiteral("integer");
    if (t == QLatin1String("std::string") || t == QLatin1String("string") ||
        t == QLatin1String("str") || t == QLatin1String("char*"))
        return QStringLiteral("string");
    return {};
}

namespace {

bool matchFrom(const QString &name, qsizetype n, const QString &key, qsizetype k, int depth)
{
    if (depth > 32)
        return true; // too many run-time parts to tell: take it as declared
    while (n < name.size()) {
        if (name.at(n) == u'{') {
            const qsizetype close = name.indexOf(u'}', n);
            if (close < 0)
                return name.mid(n) == key.mid(k);
            for (qsizetype j = k; j <= key.size(); ++j)
                if (matchFrom(name, close + 1, key, j, depth + 1))
                    return true;
            return false;
        }
        if (k >= key.size() || name.at(n) != key.at(k))
            return false;
        ++n;
        ++k;
    }
    return k == key.size();
}

} // namespace

bool parameterNameMatches(const QString &name, const QString &key)
{
    if (!name.contains(u'{'))
        return name == key;
    return matchFrom(name, 0, key, 0, 0);
}

QString parameterNameFor(const QString &name, const QString &plugin)
{
    QString out = name;
    return out.replace(QStringLiteral("{plugin}"), plugin);
}

bool parameterNameIsPattern(const QString &name)
{
    QString rest = name;
    rest.remove(QStringLiteral("{plugin}"));
    return rest.contains(u'{');
}

bool isBuiltinParameter(const QString &key)
{
    return key == QLatin1String("use_sim_time") ||
           key == QLatin1String("start_type_description_service") ||
           key.startsWith(QLatin1String("qos_overrides."));
}

} // namespace rosarch
