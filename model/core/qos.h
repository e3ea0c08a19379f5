#pragma once

#include <QString>

namespace rosarch {

/// The two QoS policies whose mismatch stops a publisher and a subscription from talking, as
/// far as the QoS argument at the creating call says (blueprint: a QoS incompatibility is
/// reported only when both sides are literal in the code).
struct QosProfile
{
    enum class Reliability
    {
        Unknown,
        Reliable,
        BestEffort
    };
    enum class Durability
    {
        Unknown,
        Volatile,
        TransientLocal
    };

    Reliability reliability = Reliability::Unknown;
    Durability durability = Durability::Unknown;

    /// Reads the QoS argument as written at a create_publisher / create_subscription call in
    /// C++ or Python: a depth (`10`), `rclcpp::QoS(10).best_effort()`, `SensorDataQoS()`,
    /// `qos_profile_sensor_data`, `QoSProfile(depth=1, durability=...TRANSIENT_LOCAL)`, ...
    /// A policy the text does not settle (a variable, a profile read from a parameter) stays
    /// Unknown; one the text leaves at ROS 2's default (reliable, volatile) gets that default
    /// when the text is a literal profile.
    static QosProfile fromWritten(const QString &written);

    /// Why a publisher with `offered` cannot reach a subscription that `requested`, as
    /// "best-effort publisher, reliable subscription" ("" when compatible or unknown).
    static QString incompatibility(const QosProfile &offered, const QosProfile &requested);

    static QString reliabilityName(Reliability r);
    static QString durabilityName(Durability d);
};

} // namespace rosarch
