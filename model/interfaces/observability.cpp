#include "interfaces/observability.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include <mutex>

// Resources of a static library must be registered explicitly; outside any namespace. Both
// readers of this library's data register them (once each is enough, twice is harmless).
static void initObservabilityResources()
{
    static std::once_flag once;
    std::call_once(once, [] { Q_INIT_RESOURCE(interfaces); });
}

namespace rosarch {

const Observability &Observability::builtIn()
{
    static const Observability rules = [] {
        initObservabilityResources();
        QFile f(QStringLiteral(":/interfaces/observability.json"));
        if (!f.open(QIODevice::ReadOnly))
            return Observability();
        return fromJson(QJsonDocument::fromJson(f.readAll()).object());
    }();
    return rules;
}

Observability Observability::fromJson(const QJsonObject &rules, QStringList *problems)
{
    Observability o;
    const auto strings = [&](const char *key) {
        QStringList out;
        for (const QJsonValue &v : rules.value(QLatin1String(key)).toArray())
            if (v.isString() && !v.toString().isEmpty())
                out << v.toString();
        return out;
    };
    o.m_packages = strings("message_packages");
    o.m_helpers = strings("helpers");
    for (const QString &pattern : strings("name_segments")) {
        QRegularExpression re(QRegularExpression::anchoredPattern(pattern));
        if (re.isValid())
            o.m_segments << re;
        else if (problems)
            *problems << QStringLiteral("the name pattern '%1' is not a regular expression: %2")
                             .arg(pattern, re.errorString());
    }
    return o;
}

Observability Observability::merged(const Observability &other) const
{
    Observability o = *this;
    o.m_packages << other.m_packages;
    o.m_segments << other.m_segments;
    o.m_helpers << other.m_helpers;
    return o;
}

bool Observability::covers(const QString &name, const QString &type, const QString &helper) const
{
    const QString package = type.section(QLatin1Char('/'), 0, 0);
    if (!package.isEmpty() && type.contains(QLatin1Char('/')) && m_packages.contains(package))
        return true;
    for (const QString &h : m_helpers)
        if (helper.contains(h))
            return true;
    for (const QStringView segment : QStringView(name).split(QLatin1Char('/'), Qt::SkipEmptyParts))
        for (const QRegularExpression &re : m_segments)
            if (re.match(segment.toString()).hasMatch())
                return true;
    return false;
}

bool Observability::isEmpty() const
{
    return m_packages.isEmpty() && m_segments.isEmpty() && m_helpers.isEmpty();
}

} // namespace rosarch
