#include "core/qos.h"

#include <QRegularExpression>

namespace rosarch {

namespace {

bool containsAny(const QString &text, std::initializer_list<const char *> words)
{
    for (const char *w : words)
        if (text.contains(QLatin1String(w), Qt::CaseInsensitive))
            return true;
    return false;
}

/// A profile built at the call from literals and ROS's own names: every identifier in it is
/// a QoS vocabulary word, so the policies it does not set are ROS 2's defaults.
bool isLiteralProfile(const QString &text)
{
    static const QRegularExpression identifier(QStringLiteral(R"([A-Za-z_][A-Za-z_0-9]*)"));
    static const QRegularExpression vocabulary(QStringLiteral(
        R"(^(rclcpp|rclpy|QoS|QoSProfile|KeepLast|KeepAll|SensorDataQoS|SystemDefaultsQoS|)"
        R"(ServicesQoS|ParametersQoS|ParameterEventsQoS|RosoutQoS|ClockQoS|BestAvailableQoS|)"
        R"(reliable|best_effort|reliability|durability|durability_volatile|transient_local|)"
        R"(keep_last|keep_all|history|depth|QoSReliabilityPolicy|ReliabilityPolicy|)"
        R"(QoSDurabilityPolicy|DurabilityPolicy|QoSHistoryPolicy|HistoryPolicy|RELIABLE|)"
        R"(BEST_EFFORT|VOLATILE|TRANSIENT_LOCAL|KEEP_LAST|KEEP_ALL|SYSTEM_DEFAULT|)"
        R"(ReliabilityPolicy|Reliable|BestEffort|Volatile|TransientLocal|rmw_qos_profile_default|)"
        R"(rmw_qos_profile_sensor_data|qos_profile_sensor_data|qos_profile_system_default|)"
        R"(qos_profile_services_default|qos_profile_parameters|QoSInitialization|from_rmw|)"
        R"(rmw_qos_profile_services_default|rmw_qos_profile_system_default|)"
        R"(RMW_QOS_POLICY_RELIABILITY_RELIABLE|RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT|)"
        R"(RMW_QOS_POLICY_DURABILITY_VOLATILE|RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL|)"
        R"(true|false|True|False)$)"));
    const QString t = text.trimmed();
    if (t.isEmpty())
        return false;
    auto it = identifier.globalMatch(t);
    while (it.hasNext()) {
        const auto m = it.next();
        // digits glued to a suffix (10u) are not identifiers
        if (m.capturedStart() > 0 && t.at(m.capturedStart() - 1).isDigit())
            continue;
        if (!vocabulary.match(m.captured()).hasMatch())
            return false;
    }
    return true;
}

} // namespace

QosProfile QosProfile::fromWritten(const QString &written)
{
    QosProfile q;
    const QString t = QString(written).remove(QLatin1Char(' '));
    if (t.isEmpty())
        return q;
    const bool literal = isLiteralProfile(written);
    // A policy set explicitly (.best_effort(), ReliabilityPolicy.RELIABLE, the RMW enum)
    // counts even on a profile that is otherwise a variable; a named profile (SensorDataQoS)
    // only when it is ROS's own, spelled out at the call.
    if (containsAny(t, {".best_effort()", "Policy.BEST_EFFORT", "RELIABILITY_BEST_EFFORT"}) ||
        (literal && containsAny(t, {"sensordata", "sensor_data", "BestEffort"})))
        q.reliability = Reliability::BestEffort;
    else if (containsAny(t, {".reliable()", "Policy.RELIABLE", "RELIABILITY_RELIABLE"}) ||
             (literal && containsAny(t, {"Reliable"})))
        q.reliability = Reliability::Reliable;
    else if (literal &&
             !containsAny(t, {"reliability", "bestavailable", "system_default", "systemdefault"}))
        q.reliability = Reliability::Reliable;
    if (containsAny(
            t, {".transient_local()", "Policy.TRANSIENT_LOCAL", "DURABILITY_TRANSIENT_LOCAL"}) ||
        (literal && containsAny(t, {"TransientLocal"})))
        q.durability = Durability::TransientLocal;
    else if (containsAny(t, {".durability_volatile()", "Policy.VOLATILE", "DURABILITY_VOLATILE"}) ||
             (literal && containsAny(t, {"Volatile"})))
        q.durability = Durability::Volatile;
    else if (literal &&
             !containsAny(t, {"durability", "bestavailable", "system_default", "systemdefault"}))
        q.durability = Durability::Volatile;
    return q;
}

QString QosProfile::incompatibility(const QosProfile &offered, const QosProfile &requested)
{
    QStringList why;
    if (offered.reliability == Reliability::BestEffort &&
        requested.reliability == Reliability::Reliable)
        why << QStringLiteral("a best-effort publisher and a reliable subscription");
    if (offered.durability == Durability::Volatile &&
        requested.durability == Durability::TransientLocal)
        why << QStringLiteral("a volatile publisher and a transient-local subscription");
    return why.join(QStringLiteral(", and "));
}

QString QosProfile::reliabilityName(Reliability r)
{
    switch (r) {
    case Reliability::Reliable:
        return QStringLiteral("reliable");
    case Reliability::BestEffort:
        return QStringLiteral("best_effort");
    case Reliability::Unknown:
        break;
    }
    return {};
}

QString QosProfile::durabilityName(Durability d)
{
    switch (d) {
    case Durability::Volatile:
        return QStringLiteral("volatile");
    case Durability::TransientLocal:
        return QStringLiteral("transient_local");
    case Durability::Unknown:
        break;
    }
    return {};
}

} // namespace rosarch
