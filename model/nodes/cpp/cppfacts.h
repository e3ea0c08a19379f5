#pragma once

#include "core/diagnostic.h"
#include "core/evidence.h"
#include "core/languageanalysis.h"
#include "core/port.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

#include <vector>

namespace rosarch {

// Per-file facts that the C++ analyzer extracts in parallel (phase 1) and links afterwards
// (phase 2). They hold text only, so the syntax trees can be freed before linking.

/// What an expression (a port name, a parameter default, a guard variable) refers to, as far
/// as the function it appears in can tell. Members and parameter defaults are looked up later.
struct CppValue
{
    enum class Kind
    {
        None,              ///< no expression
        Literal,           ///< a string literal (or a bool/number for parameter defaults)
        Local,             ///< a local variable holding `literal`
        Member,            ///< a member variable `variable`, resolved when linking
        Parameter,         ///< the ROS parameter `parameter` (through `variable`, if any)
        FunctionParameter, ///< parameter `index` of the enclosing function
        SelfNode,          ///< `this`, `shared_from_this()`, a variable holding one of them
        SelfCall,          ///< `getName()`: a method `variable` of this object, without arguments
        Concatenation,     ///< `prefix + "/" + name`: the `parts`, joined
        Field,             ///< `params_->topic`, `p.topic`: `field` of the object `variable`
        Constant,          ///< `ns::kTopic`, `Foo::kTopic`: a constant `variable` (qualified)
        /// A local handed uninitialised to `variable(...)` as its argument `index`: what that
        /// function assigns to its reference parameter (`getParameters(topic)`)
        OutArgument,
        /// `costmap_.getName()`: the method `field`, without arguments, of the object `parts[0]`
        /// (a member or a parameter), resolved when linking if that object is the node
        ObjectCall,
        /// `for (auto & name : names_)`: each element of the container `parts[0]`
        Element,
        /// `Settings{.topic = "scan", .name = n}`, or a local whose fields the function sets
        /// (`s.topic = "scan";`): `parts` alternate each field's name (a Literal) and value;
        /// a list of string literals (`{"dock", "gate"}`) has fields without names
        Aggregate,
        Expression, ///< anything else
    };
    Kind kind = Kind::None;
    QString text;    ///< the expression as written
    QString literal; ///< Literal, Local
    QString
        variable; ///< Local, Member, Parameter (when read through a variable), FunctionParameter
    QString parameter;           ///< Parameter
    int index = -1;              ///< FunctionParameter
    std::vector<CppValue> parts; ///< Concatenation
    QString field;      ///< Field: the field read (`variable` is the object's member or local)
    QString objectType; ///< Field: the object's type as written, when the function knows it

    bool isNone() const { return kind == Kind::None; }
};

/// A `declare_parameter("p", default)` (or a nav2 equivalent) in a function.
struct CppParameterDeclaration
{
    QString parameter;     ///< the literal name ("" when `name` is an expression)
    CppValue defaultValue; ///< None when declared without one
    CppValue name = {};    ///< the name when it is not a literal (`plugin_name_ + ".x"`)
    /// Also the class's declaration (not only a name a port or guard reads): rclcpp's and
    /// nav2_util's declaring calls, `get_parameter_or`, `undeclare_parameter` ("undeclare").
    QString via = {};
    QString type = {};        ///< ROS parameter type the call decides ("" when open)
    bool hasDefault = false;  ///< a value is given (`defaultValue` may still be None for it)
    QString defaultText = {}; ///< the default as written
    bool readOnly = false;
    bool dynamicTyping = false;
    QString description = {};
    QString range = {};
    QString guard = {};
    Evidence evidence = {};
};

/// A member variable receiving a value: in-class initializer, constructor initializer list,
/// assignment, or `get_parameter("p", member_)`.
struct CppMemberBinding
{
    QString member;
    CppValue value;
};

/// A field of an object receiving a value: `params_.topic = declare_parameter("topic", ...)`,
/// `get_parameter("topic", params_->topic)`. Parameters structs are often filled by one class
/// and read by another, so the linker indexes these by struct type and field.
struct CppFieldBinding
{
    CppValue target; ///< a Field
    CppValue value;
};

/// A port-creating call, with everything the function itself can tell about it.
struct CppPortCall
{
    PortKind kind = PortKind::Publisher;
    CppValue name;
    QString typeWritten; ///< the interface type as written in the template argument
    bool typeIsTemplateParameter = false; ///< generic wrapper code, not a port
    QString callback;
    int callbackParameter = -1; ///< the callback is this parameter of the enclosing function
    QString guard;              ///< enclosing `if` conditions, joined with " && "
    CppValue guardValue;        ///< the variable (or parameter read) the guard tests
    QString receiver;           ///< "" for an implicit `this`, else the object expression
    /// The type an image_transport (sensor_msgs/msg/Image) or point_cloud_transport
    /// (sensor_msgs/msg/PointCloud2) call always has; "" for other calls.
    QString transportType;
    QString qos; ///< the QoS argument of a publisher or subscription, as written
    Evidence evidence;
};

/// `std::make_shared<X>(...)`, `std::make_unique<X>`, `X::make_shared()`, `new X(...)`,
/// `X x(...)`, or a constructor-initializer of a member whose type is X.
struct CppInstantiation
{
    QString className; ///< as written
    QString member;    ///< member initialized in a constructor initializer list ("" otherwise)
    QList<CppValue> arguments;
    QString guard; ///< enclosing `if` conditions, as for a port call (a local construction)
    Evidence evidence;
    CppValue guardValue = {}; ///< the variable (or parameter read) the guard tests
};

/// A call of a method on an object the function's class holds, with a string or template
/// argument: `debug_publisher_->publish<T>("debug/time", value)`. A helper that creates its
/// ports lazily (keyed by the name it is handed) creates them at such calls.
struct CppMethodCall
{
    QString member; ///< the object: a member variable
    QString method;
    QStringList templateArguments; ///< as written
    QList<CppValue> arguments;
    QString guard;       ///< enclosing `if` conditions, as for a port call
    CppValue guardValue; ///< the variable (or parameter read) the guard tests
    Evidence evidence;
};

/// A call of a free function that may hand it the node: `setup_publishers(node, "x")`.
struct CppFreeCall
{
    QString function; ///< as written, e.g. "setup" or "ns::setup"
    QList<CppValue> arguments;
    Evidence evidence;
};

/// `auto node = rclcpp::Node::make_shared("name")` and its equivalents: in a free function a
/// procedural node; stored into a member of a class that is no node, a node-like component.
struct CppProceduralNode
{
    QString variable;    ///< the variable holding the node ("" when not stored)
    bool member = false; ///< `variable` is a member, not a local
    CppValue nodeName;
    bool lifecycle = false;
    Evidence evidence; ///< the creating call
};

/// The initializer of a base class in a constructor: `Node("talker", options)`.
struct CppBaseInitializer
{
    QString name; ///< as written, e.g. "Node", "rclcpp::Node", "nav2::LifecycleNode"
    CppValue firstArgument;
    /// All arguments, for a base of the workspace (`TestActionServer("assisted_teleop")`)
    QList<CppValue> arguments = {};
};

/// A function definition (free, inline member or out-of-line member).
struct CppFunction
{
    QString name;           ///< unqualified
    QString ownerScope;     ///< out-of-line members: the class scope as written ("ns::Talker")
    int ownerClass = -1;    ///< inline members: index into CppFileFacts::classes
    QStringList namespaces; ///< enclosing namespaces at the definition
    bool isConstructor = false;
    QStringList parameterNames;
    QStringList parameterTypes;
    QStringList parameterDefaults; ///< literal defaults of parameters ("" when none)
    int requiredParameters = 0;    ///< parameters without a default
    bool variadic = false;
    QHash<QString, QString> aliases; ///< function-local `using X = ...;`
    QList<CppBaseInitializer> baseInitializers;
    QList<CppPortCall> ports;
    QList<CppParameterDeclaration> parameterDeclarations;
    QList<CppMemberBinding> memberBindings;
    QList<CppFieldBinding> fieldBindings;
    /// Values assigned to the function's own reference parameters (`std::string & topic`), by
    /// parameter name: what a caller's local holds after the call.
    QList<CppMemberBinding> outBindings;
    QList<CppInstantiation> instantiations;
    QList<CppFreeCall> freeCalls;
    /// In a free function, the other calls of free functions (`make_filter_line(options)`):
    /// a function that builds nodes for `main` is followed from it.
    QList<CppFreeCall> builderCalls;
    QList<CppMethodCall> methodCalls;
    QList<CppProceduralNode> proceduralNodes;
    QStringList templateParameters; ///< the function's own (`template <class T> void f()`)
    CppValue returnValue;           ///< a body that is a single `return x;`: x
    Evidence evidence;
    /// Sets `allow_undeclared_parameters(true)` or
    /// `automatically_declare_parameters_from_overrides(true)` on node options.
    bool acceptsUndeclared = false;
};

/// A class or struct definition with a body.
struct CppClass
{
    QString name;          ///< unqualified
    QString qualifiedName; ///< with enclosing namespaces and classes
    QStringList scope;     ///< enclosing namespaces and classes, outermost first
    QStringList bases;     ///< as written
    QStringList templateParameters;
    QHash<QString, QString> aliases;     ///< member `using X = ...;` / typedef
    QHash<QString, QString> memberTypes; ///< member variable -> its type as written
    QList<CppMemberBinding> memberInitializers;
    /// `Helper<T> member_{this, "name"};`: a helper built in the class body with the node
    QList<CppInstantiation> memberInstantiations;
    /// Methods declared in the body and defined elsewhere, with literal parameter defaults:
    /// name -> the defaults by parameter ("" where none). A definition out of the class
    /// repeats no default (`Relay(const std::string & name = "relay");`).
    QHash<QString, QStringList> declaredDefaults;
    Evidence evidence;
};

/// `PLUGINLIB_EXPORT_CLASS(ns::Class, base::Interface)`: a pluginlib plugin.
struct CppPluginExport
{
    QString className; ///< as written
    QString baseClass; ///< the plugin interface, as written
    Evidence evidence;
};

/// Everything extracted from one C++ file.
struct CppFileFacts
{
    QString path;
    QString package;
    bool isHeader = false;
    QList<CppClass> classes;
    QList<CppFunction> functions;
    QHash<QString, QString>
        aliases;                 ///< namespace-level `using X = ...;`, typedefs, using-declarations
    QStringList usingNamespaces; ///< `using namespace x;`
    QHash<QString, QString> constants; ///< namespace-level string constants: kTopic -> "chatter"
    QList<ComponentRegistration> registrations;
    QList<CppPluginExport> pluginExports;
    QList<Diagnostic> diagnostics;
};

} // namespace rosarch
