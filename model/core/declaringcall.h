#pragma once

#include <QRegularExpression>
#include <QString>

namespace rosarch {

/// Whether `via` (ParameterDeclaration::via) is a declaring call whose name, type and default
/// rules are ROS 2's own: rclcpp's and rclpy's `declare_parameter`, nav2_util's and
/// autoware_utils' declaring helpers, a parameters handler's getter, generate_parameter_library. A
/// project's own helper may prefix, convert or default what it is given; `get_parameter_or` only
/// reads with a fallback.
inline bool isStandardDeclaringCall(const QString &via)
{
    return via == QLatin1String("declare_parameter") ||
           via == QLatin1String("declare_parameter_if_not_declared") ||
           via == QLatin1String("declare_or_get_parameter") ||
           via == QLatin1String("get_or_declare_parameter") ||
           via == QLatin1String("getOrDeclareParameter") ||
           via == QLatin1String("getParamGetter") ||
           via == QLatin1String("generate_parameter_library");
}

/// Whether a method hands out a getter that declares what it is called with under the
/// namespace it was made for (navigation2 MPPI's `ParametersHandler::getParamGetter(ns)`,
/// whose getter declares `ns.name` with `declare_parameter_if_not_declared`).
inline bool isParameterGetterFactory(const QString &method)
{
    return method == QLatin1String("getParamGetter");
}

/// Whether a declared name is all run-time parts (`{name}`, `{prefix}{key}`): it may be any
/// name at all.
inline bool parameterNameIsOpen(const QString &name)
{
    static const QRegularExpression part(QStringLiteral("\\{[^}]*\\}"));
    QString literal = name;
    literal.remove(part);
    return literal.remove(u'.').remove(u'_').remove(u'/').isEmpty();
}

} // namespace rosarch
