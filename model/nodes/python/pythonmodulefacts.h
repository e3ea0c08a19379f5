#pragma once

#include "core/diagnostic.h"
#include "core/evidence.h"
#include "core/parameter.h"
#include "core/port.h"

#include <QList>
#include <QString>
#include <QStringList>

// Plain facts that PythonModuleReader extracts from one Python file. They outlive the syntax
// tree, so PythonNodeLinker can resolve classes, bases and helpers across files.

namespace rosarch {

/// The node handle a port creation or a hand-off uses inside a class or function.
struct PythonHandle
{
    enum class Kind
    {
        Self,
        Parameter,
        Procedural,
        Setup ///< the node handed over later by `setup(node=...)` (py_trees' setup protocol)
    };

    Kind kind = Kind::Self;
    int index = -1; ///< Parameter: position among the explicit parameters; Procedural: index
    QString name;   ///< Parameter: its name
    QString method; ///< Parameter of a method other than the constructor: that method

    bool operator==(const PythonHandle &) const = default;
    /// The same handle, whatever name a parameter has at each place it is seen.
    bool sameAs(const PythonHandle &o) const
    {
        return kind == o.kind && (kind == Kind::Self || (index == o.index && method == o.method));
    }
};

/// One argument at a call site, with what is statically known about it.
struct PythonArgument
{
    QString keyword;       ///< "" for a positional argument
    QString text;          ///< as written
    bool isString = false; ///< resolves to a string (literal, local, member, parameter default)
    QString value;         ///< that string when isString
    NameOrigin origin = NameOrigin::Expression; ///< how it resolves
    QString parameter;       ///< the declared ROS parameter it comes from, when known
    int parameterIndex = -1; ///< names an explicit parameter of the enclosing function
    QString interfaceType;   ///< canonical "pkg/msg/T" when the argument is an interface type
    /// A loop variable over a list of strings (`for zone in ZONES:`): the strings in turn.
    QStringList items = {};
};

/// A port's name or type that is a parameter of the constructor, function or method around it,
/// so that each call site can supply it.
struct PythonParameterRef
{
    int index = -1;
    QString name;
    QString method; ///< "" for the constructor or a function

    bool isValid() const { return index >= 0; }
};

/// One piece of a port name built from parts (f-string, `.format`, `+`): literal text, or a
/// parameter that each call site supplies.
struct PythonNamePart
{
    QString text; ///< the literal text when `from` is not valid
    PythonParameterRef from;
};

/// A port-creating call (create_publisher, ActionServer(...), ...).
struct PythonPortFact
{
    Port port;
    QString method; ///< enclosing method ("" in functions): base ports vanish when overridden
    PythonHandle handle;
    PythonParameterRef nameFrom;
    PythonParameterRef typeFrom;
    QList<PythonNamePart> nameParts; ///< the name's parts when some are parameters; else empty
};

/// A call that passes a node handle on to a helper class or function.
struct PythonHandoff
{
    QString target;                  ///< callee, qualified through the imports
    int argument = -1;               ///< positional index of the handle, or -1
    QString keyword;                 ///< keyword of the handle when passed by name
    PythonHandle handle;             ///< which handle is passed
    QString method;                  ///< enclosing method ("" in functions)
    QList<PythonArgument> arguments; ///< all arguments of the call
    Evidence evidence;               ///< the call
};

/// A call `Name(...)` / `mod.Name(...)` that may instantiate a class or call a function.
struct PythonCall
{
    QString target; ///< callee, qualified through the imports
    QList<PythonArgument> arguments;
    Evidence evidence; ///< the call
};

/// A node built without a class: `x = rclpy.create_node('name')`, `x = Node('name')`.
struct PythonProcedural
{
    QString nodeName;
    QString function; ///< enclosing function or method ("" at module level)
    bool lifecycle = false;
    Evidence evidence; ///< the enclosing function (the create call at module level)
};

/// What a class or function body contains, per handle.
struct PythonScopeFacts
{
    QList<PythonPortFact> ports;
    QList<PythonHandoff> handoffs;
    QList<PythonCall> calls;
    QList<PythonProcedural> procedurals;
    QList<ParameterDeclaration> parameterDeclarations; ///< what the scope declares
    /// The scope, or its module, lets a node take parameters nobody declares.
    bool acceptsUndeclared = false;
};

struct PythonParameter
{
    QString name;
    bool hasDefault = false;
    bool defaultIsString = false;
    QString defaultValue; ///< literal content, or the default's text
};

struct PythonClassFacts : PythonScopeFacts
{
    QString name;
    QString qualifiedName;
    QStringList bases;       ///< as written
    QStringList baseTargets; ///< qualified through the imports
    Evidence evidence;
    QStringList methods;
    QList<QList<PythonParameter>> methodParameters; ///< explicit parameters, parallel to methods
    QStringList superCalledMethods;                 ///< overrides that call the base's version
    bool hasInit = false;
    QList<PythonParameter> initParameters; ///< explicit parameters of __init__ (self excluded)
    bool hasBaseInitCall = false;
    QList<PythonArgument> baseInitArguments; ///< super().__init__(...) arguments (self excluded)
};

struct PythonFunctionFacts : PythonScopeFacts
{
    QString name; ///< "" for the module-level statements
    QList<PythonParameter> parameters;
    Evidence evidence;
};

struct PythonModuleFacts
{
    QString file;
    QString package;
    QString modulePath; ///< dotted, e.g. "demo_nodes_py.topics.talker"
    QList<PythonClassFacts> classes;
    QList<PythonFunctionFacts> functions;
    QList<Diagnostic> diagnostics;
};

} // namespace rosarch
