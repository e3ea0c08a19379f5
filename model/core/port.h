#pragma once

#include "core/evidence.h"
#include "core/provenance.h"

#include <QList>
#include <QString>

namespace rosarch {

enum class PortKind
{
    Publisher,
    Subscriber,
    ServiceServer,
    ServiceClient,
    ActionServer,
    ActionClient
};

/// "publisher", "subscriber", "service_server", ... as written in the JSON artifacts.
QString portKindName(PortKind kind);
/// Inverse of portKindName; returns false for an unknown name.
bool portKindFromName(const QString &name, PortKind *kind);
/// "topic", "service" or "action": what a port of this kind talks on.
QString portFamilyName(PortKind kind);
/// ACD port-id prefix: p, s, ps, rs, pa, ra.
QString portIdPrefix(PortKind kind);
/// Subscriber, service server, action server: ports that take input (`portin`).
bool isInputPort(PortKind kind);
/// Publisher, service server, action server: the side that provides a topic, service or action.
bool isProvidingPort(PortKind kind);

/// How the port's name was obtained from the code.
enum class NameOrigin
{
    Literal,    ///< a string literal at the call
    Member,     ///< a member variable (self.x / x_) holding a literal
    Local,      ///< a local variable holding a literal
    Parameter,  ///< the default of a declared parameter
    Expression, ///< could not be decided statically; `name` is the expression text
};
QString nameOriginName(NameOrigin origin);

/// A type as analysis writes a known one: "pkg/msg/T", "pkg/srv/T" or "pkg/action/T", not an
/// expression left as written (`node_param_.topic_type`, a template parameter, a C++ class).
bool isCanonicalInterfaceType(const QString &type);

/// In a pluginlib plugin's port name, the name the plugin is loaded under
/// (`{plugin}/toggle_filter`); an instance that loads the plugin fills it in.
inline constexpr char kPluginNamePlaceholder[] = "{plugin}";
/// In a port name, the name of the node that runs it (`get_name()`): each instance fills it in.
inline constexpr char kNodeNamePlaceholder[] = "{node}";

/// One communication port of an atomic node: publisher, subscriber, service, action.
struct Port
{
    QString id; ///< per-node id in ACD style: p1, s1, ps1, rs1, pa1, ra1
    PortKind kind = PortKind::Publisher;
    QString name;     ///< the name as written, resolved to a literal where possible ("~/x" kept)
    QString type;     ///< interface type, canonical "pkg/msg/T", "pkg/srv/T", "pkg/action/T"
    QString callback; ///< callback / handler function name; "lambda" for a lambda
    NameOrigin nameOrigin = NameOrigin::Literal;
    QString nameExpression; ///< the expression at the call when it is not a literal
    QString parameter;      ///< the parameter the name comes from (NameOrigin::Parameter)
    /// A name joined around the parameter's value (`prefix_ + "/state"`): the text before and
    /// after it, so that an instance's value replaces only the parameter's part.
    QString parameterPrefix;
    QString parameterSuffix;
    QString guard;          ///< condition under which the port exists, as written ("" = always)
    QString guardParameter; ///< the parameter the guard depends on, when known
    QString guardDefault;   ///< that parameter's declared default, when known
    QString via;            ///< helper class through which the port is created ("" = the node)
    QString qos;            ///< the QoS argument as written at the call ("" = none given)
    bool inherited = false; ///< declared in a project base class
    Evidence evidence;
    /// Where the node reaches the helper that creates the port, outermost first: hand-offs,
    /// setup calls, instantiations ("" via = empty).
    QList<Evidence> viaEvidence;

    Marks marks = {}; ///< provenance and review (blueprint §5); set by the corrected model
    bool isResolved() const { return nameOrigin != NameOrigin::Expression; }
    /// The type is known ("" is unknown too, but says so by itself).
    bool typeIsResolved() const { return type.isEmpty() || isCanonicalInterfaceType(type); }
    bool operator==(const Port &) const = default;
};

} // namespace rosarch
