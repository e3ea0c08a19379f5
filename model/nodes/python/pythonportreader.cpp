#include "nodes/python/pythonportreader.h"

#include "syntax/pythonsyntax.h"

namespace rosarch {

namespace {
enum class Form
{
    Method,
    Constructor
};

struct Signature
{
    const char *type;
    const char *name;
    const char *callback; ///< nullptr when the call takes none
};

Signature signature(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return {"msg_type", "topic", nullptr};
    case PortKind::Subscriber:
        return {"msg_type", "topic", "callback"};
    case PortKind::ServiceServer:
        return {"srv_type", "srv_name", "callback"};
    case PortKind::ServiceClient:
        return {"srv_type", "srv_name", nullptr};
    case PortKind::ActionServer:
        return {"action_type", "action_name", "execute_callback"};
    case PortKind::ActionClient:
        return {"action_type", "action_name", nullptr};
    }
    return {"", "", nullptr};
}

// Constructors take the node first: ActionServer(node, T, name, cb), Subscriber(node, T, name).
bool isConstructorForm(const SyntaxTree &tree, TSNode call)
{
    const std::string_view name = py::calleeName(tree, call);
    return name == "ActionServer" || name == "ActionClient" || name == "Subscriber";
}
} // namespace

PythonPortReader::PythonPortReader(const PythonResolver &resolver) : m_resolver(resolver) {}

bool PythonPortReader::recognize(TSNode call, PortKind *kind, TSNode *receiver) const
{
    const SyntaxTree &tree = m_resolver.tree();
    TSNode function = ts::field(call, "function");
    const std::string_view name = py::calleeName(tree, call);
    if (name.empty())
        return false;
    if (ts::is(function, "attribute")) {
        static const std::pair<std::string_view, PortKind> methods[] = {
            {"create_publisher", PortKind::Publisher},
            {"create_lifecycle_publisher", PortKind::Publisher},
            {"create_subscription", PortKind::Subscriber},
            {"create_service", PortKind::ServiceServer},
            {"create_client", PortKind::ServiceClient},
        };
        for (const auto &[method, k] : methods) {
            if (name == method) {
                *kind = k;
                *receiver = ts::field(function, "object");
                return true;
            }
        }
    }
    if (name == "ActionServer" || name == "ActionClient") {
        const QString q = m_resolver.qualifiedName(function);
        if (!q.startsWith(QLatin1String("rclpy.")) &&
            q != QLatin1String(name.data(), qsizetype(name.size())))
            return false;
        *kind = name == "ActionServer" ? PortKind::ActionServer : PortKind::ActionClient;
        *receiver = py::argument(tree, call, 0, "node");
        return !ts::isNull(*receiver);
    }
    if (name == "Subscriber" &&
        m_resolver.qualifiedName(function) == QLatin1String("message_filters.Subscriber")) {
        *kind = PortKind::Subscriber;
        *receiver = py::argument(tree, call, 0, "node");
        return !ts::isNull(*receiver);
    }
    return false;
}

TSNode PythonPortReader::nameArgument(TSNode call, PortKind kind) const
{
    const SyntaxTree &tree = m_resolver.tree();
    const int first = isConstructorForm(tree, call) ? 1 : 0;
    return py::argument(tree, call, first + 1, signature(kind).name);
}

TSNode PythonPortReader::typeArgument(TSNode call, PortKind kind) const
{
    const SyntaxTree &tree = m_resolver.tree();
    const int first = isConstructorForm(tree, call) ? 1 : 0;
    return py::argument(tree, call, first, signature(kind).type);
}

Port PythonPortReader::read(TSNode call, PortKind kind) const
{
    const SyntaxTree &tree = m_resolver.tree();
    const Signature sig = signature(kind);
    const int first = isConstructorForm(tree, call) ? 1 : 0;
    Port port;
    port.kind = kind;
    port.evidence = tree.evidence(call);

    TSNode type = typeArgument(call, kind);
    if (!ts::isNull(type))
        port.type = m_resolver.interfaceType(type);

    TSNode name = nameArgument(call, kind);
    if (!ts::isNull(name)) {
        const PythonValue v = m_resolver.value(name);
        port.name = v.value;
        port.nameOrigin = v.origin;
        port.parameter = v.parameter;
        if (v.origin != NameOrigin::Literal)
            port.nameExpression = tree.text(name);
    } else {
        port.nameOrigin = NameOrigin::Expression;
    }

    // message_filters.Subscriber has no callback of its own (a synchronizer calls back)
    if (sig.callback && py::calleeName(tree, call) != "Subscriber") {
        TSNode callback = py::argument(tree, call, first + 2, sig.callback);
        if (!ts::isNull(callback))
            port.callback = m_resolver.callbackName(callback);
    }
    // create_publisher(T, name, qos_profile), create_subscription(T, name, callback, qos_profile)
    if (kind == PortKind::Publisher || kind == PortKind::Subscriber) {
        const int at = first + (kind == PortKind::Publisher ? 2 : 3);
        TSNode qos = py::argument(tree, call, at, "qos_profile");
        if (!ts::isNull(qos))
            port.qos = QString(tree.text(qos)).simplified();
    }
    m_resolver.guard(call, &port.guard, &port.guardParameter, &port.guardDefault);
    return port;
}

} // namespace rosarch
