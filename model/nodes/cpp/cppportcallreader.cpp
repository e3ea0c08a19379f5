#include "nodes/cpp/cppportcallreader.h"

namespace rosarch {

using namespace cppsyntax;

namespace {

bool encloses(TSNode outer, TSNode inner)
{
    return !ts::isNull(outer) && ts_node_start_byte(inner) >= ts_node_start_byte(outer) &&
           ts_node_end_byte(inner) <= ts_node_end_byte(outer);
}

bool sameNode(TSNode a, TSNode b)
{
    return !ts::isNull(a) && !ts::isNull(b) && ts_node_eq(a, b);
}

struct PortCallKind
{
    bool port = false;
    bool generic = false; ///< create_generic_*: the type is the second argument, as a string
    PortKind kind = PortKind::Publisher;
    bool freeForm =
        false; ///< the node is the first argument: rclcpp_action::create_server(node, ...)
    QString transportType; ///< image_transport, point_cloud_transport: the type is fixed
};

const QString imageType = QStringLiteral("sensor_msgs/msg/Image");
const QString pointCloudType = QStringLiteral("sensor_msgs/msg/PointCloud2");

// pct_, point_cloud_transport_, cloud_transport: a PointCloudTransport (a member's type is not
// known to the file that calls it).
bool looksLikePointCloudTransport(const QString &receiver)
{
    const QString r = receiver.toLower();
    return r.contains(QLatin1String("pct")) || r.contains(QLatin1String("point_cloud")) ||
           r.contains(QLatin1String("pointcloud")) || r.contains(QLatin1String("cloud_transport"));
}

bool looksLikeImageTransport(const QString &receiver)
{
    const QString r = receiver.toLower();
    return r == QLatin1String("it") || r == QLatin1String("it_") ||
           r.contains(QLatin1String("transport")) || r.endsWith(QLatin1String("it_")) ||
           r.contains(QLatin1String("image_transport"));
}

PortCallKind portCallKind(const CallShape &shape, const QString &receiverText,
                          const QString &receiverType)
{
    PortCallKind k;
    const QString &n = shape.name;
    const QString &scope = shape.scope;
    const bool scoped = !scope.isEmpty();
    // `rclcpp::Node::create_publisher` names the member explicitly; anything else scoped is a
    // free function that takes the node first.
    const bool memberQualified = scoped && scope.endsWith(QLatin1String("Node"));
    const bool free = scoped && !memberQualified;
    const bool imageScope = scope.contains(QLatin1String("image_transport"));
    const bool cloudScope = scope.contains(QLatin1String("point_cloud_transport"));
    k.freeForm = free;
    if (cloudScope) {
        if (n == QLatin1String("create_publisher") || n == QLatin1String("create_subscription")) {
            k.port = true;
            k.kind =
                n == QLatin1String("create_publisher") ? PortKind::Publisher : PortKind::Subscriber;
            k.transportType = pointCloudType;
        }
        return k;
    }
    const bool receiverIsCloud = !scoped && !ts::isNull(shape.receiver) &&
                                 (receiverType.contains(QLatin1String("PointCloudTransport")) ||
                                  looksLikePointCloudTransport(receiverText));
    if (receiverIsCloud && (n == QLatin1String("advertise") || n == QLatin1String("subscribe"))) {
        k.port = true;
        k.kind = n == QLatin1String("advertise") ? PortKind::Publisher : PortKind::Subscriber;
        k.transportType = pointCloudType;
        return k;
    }
    if (imageScope) {
        if (n == QLatin1String("create_publisher") ||
            n == QLatin1String("create_camera_publisher")) {
            k.port = true;
            k.kind = PortKind::Publisher;
            k.transportType = imageType;
        } else if (n == QLatin1String("create_subscription") ||
                   n == QLatin1String("create_camera_subscription")) {
            k.port = true;
            k.kind = PortKind::Subscriber;
            k.transportType = imageType;
        }
        return k;
    }
    if (n == QLatin1String("create_publisher")) {
        k.port = true;
        k.kind = PortKind::Publisher;
    } else if (n == QLatin1String("create_subscription")) {
        k.port = true;
        k.kind = PortKind::Subscriber;
    } else if (n == QLatin1String("create_service")) {
        k.port = true;
        k.kind = PortKind::ServiceServer;
    } else if (n == QLatin1String("create_client")) {
        k.port = true;
        k.kind = scope.contains(QLatin1String("rclcpp_action")) ? PortKind::ActionClient
                                                                : PortKind::ServiceClient;
    } else if (n == QLatin1String("create_server") &&
               scope.contains(QLatin1String("rclcpp_action"))) {
        k.port = true;
        k.kind = PortKind::ActionServer;
    } else if (n == QLatin1String("create_generic_publisher") ||
               n == QLatin1String("create_generic_subscription")) {
        k.port = true;
        k.generic = true;
        k.kind =
            n.endsWith(QLatin1String("publisher")) ? PortKind::Publisher : PortKind::Subscriber;
    } else if (n == QLatin1String("create_action_server")) {
        k.port = true;
        k.kind = PortKind::ActionServer;
    } else if (n == QLatin1String("create_action_client")) {
        k.port = true;
        k.kind = PortKind::ActionClient;
    } else if (!scoped && !ts::isNull(shape.receiver) &&
               (n == QLatin1String("advertise") || n == QLatin1String("advertiseCamera"))) {
        k.port = true;
        k.kind = PortKind::Publisher;
        k.transportType = imageType;
    } else if (!scoped && !ts::isNull(shape.receiver) &&
               (n == QLatin1String("subscribe") || n == QLatin1String("subscribeCamera")) &&
               (receiverType.contains(QLatin1String("ImageTransport")) ||
                looksLikeImageTransport(receiverText))) {
        k.port = true;
        k.kind = PortKind::Subscriber;
        k.transportType = imageType;
    }
    return k;
}

bool isNodeHandleArgument(const QString &text)
{
    return text.contains(QLatin1String("get_node_")) || text.contains(QLatin1String("_interface"));
}

bool looksLikeNonCallback(const QString &text)
{
    const QString t = text.toLower();
    return t.contains(QLatin1String("qos")) || t.contains(QLatin1String("option")) ||
           t.contains(QLatin1String("group")) || t.contains(QLatin1String("profile")) ||
           t == QLatin1String("nullptr") || t == QLatin1String("null");
}

} // namespace

CppPortCallReader::CppPortCallReader(const SyntaxTree &tree, const CppValueEvaluator &values,
                                     const QHash<QString, CppLocal> &locals,
                                     const QStringList &templateParameters,
                                     const TSNode &definition, CppFunction &function,
                                     const QHash<QString, QString> &classAliases)
    : m_tree(tree), m_values(values), m_locals(locals), m_templateParameters(templateParameters),
      m_definition(definition), m_function(function), m_classAliases(classAliases)
{
}

// `std::make_shared<message_filters::Subscriber<Imu>>(node, "imu")`: a subscription whose
// messages go to a synchronizer rather than a callback. Autoware's GPU pipeline makes its
// point cloud ports the same way (`cuda_blackboard::CudaBlackboardPublisher<CudaPointCloud2>`
// and `CudaBlackboardSubscriber`, on an ordinary sensor_msgs/msg/PointCloud2 topic).
bool CppPortCallReader::readMessageFilter(TSNode call, const CallShape &shape,
                                          const std::vector<TSNode> &args)
{
    if ((shape.name != QLatin1String("make_shared") &&
         shape.name != QLatin1String("make_unique")) ||
        ts::isNull(shape.templateArguments) || args.size() < 2)
        return false;
    QString made = firstTemplateArgument(m_tree, shape.templateArguments);
    // `using Sub1 = message_filters::Subscriber<Msg1>;` in the function or its class
    if (const QString local = m_function.aliases.value(made); !local.isEmpty())
        made = local;
    else if (const QString member = m_classAliases.value(made); !member.isEmpty())
        made = member;
    QString plain = withoutTemplateArguments(made).remove(u' ');
    if (plain.startsWith(QLatin1String("::")))
        plain = plain.mid(2);
    CppPortCall port;
    if (plain == QLatin1String("cuda_blackboard::CudaBlackboardPublisher") ||
        plain == QLatin1String("cuda_blackboard::CudaBlackboardSubscriber")) {
        port.transportType = pointCloudType;
        port.kind =
            plain.endsWith(QLatin1String("Publisher")) ? PortKind::Publisher : PortKind::Subscriber;
    } else if (plain == QLatin1String("message_filters::Subscriber")) {
        port.kind = PortKind::Subscriber;
    } else {
        return false;
    }
    port.evidence = m_tree.evidence(call);
    port.name = m_values.evaluate(args[1]);
    port.typeWritten = templateArgumentsOf(made).value(0);
    const QString head = splitScope(withoutTemplateArguments(port.typeWritten)).value(0);
    port.typeIsTemplateParameter =
        m_templateParameters.contains(head) || m_templateParameters.contains(port.typeWritten);
    port.receiver = simplified(m_tree, args.front());
    if (args.size() > 2)
        port.qos = simplified(m_tree, args[2]);
    guardOf(call, &port.guard, &port.guardValue);
    m_function.ports.append(port);
    return true;
}

bool CppPortCallReader::read(TSNode call, const CallShape &shape, const std::vector<TSNode> &args)
{
    // The names portCallKind and readMessageFilter know: any other call creates no port, and
    // its receiver's text is not needed.
    static const QStringList known = {QStringLiteral("create_publisher"),
                                      QStringLiteral("create_subscription"),
                                      QStringLiteral("create_service"),
                                      QStringLiteral("create_client"),
                                      QStringLiteral("create_server"),
                                      QStringLiteral("create_generic_publisher"),
                                      QStringLiteral("create_generic_subscription"),
                                      QStringLiteral("create_action_server"),
                                      QStringLiteral("create_action_client"),
                                      QStringLiteral("create_camera_publisher"),
                                      QStringLiteral("create_camera_subscription"),
                                      QStringLiteral("advertise"),
                                      QStringLiteral("advertiseCamera"),
                                      QStringLiteral("subscribe"),
                                      QStringLiteral("subscribeCamera"),
                                      QStringLiteral("make_shared"),
                                      QStringLiteral("make_unique")};
    if (!known.contains(shape.name))
        return false;
    if (readMessageFilter(call, shape, args))
        return true;
    QString receiverText;
    QString receiverType;
    if (!ts::isNull(shape.receiver)) {
        receiverText = simplified(m_tree, shape.receiver);
        const auto it = m_locals.constFind(receiverText);
        if (it != m_locals.constEnd())
            receiverType = it->type;
    }
    const PortCallKind k = portCallKind(shape, receiverText, receiverType);
    if (!k.port)
        return false;
    int nameIndex = 0;
    if (k.freeForm) {
        nameIndex = 1;
        while (nameIndex < int(args.size()) - 1 &&
               isNodeHandleArgument(simplified(m_tree, args[size_t(nameIndex)])))
            ++nameIndex;
    }
    if (nameIndex >= int(args.size()))
        return false;

    CppPortCall port;
    port.kind = k.kind;
    port.transportType = k.transportType;
    port.evidence = m_tree.evidence(call);
    port.name = m_values.evaluate(args[size_t(nameIndex)]);
    if (!ts::isNull(shape.templateArguments))
        port.typeWritten = firstTemplateArgument(m_tree, shape.templateArguments);
    else if (k.freeForm && shape.scope.endsWith(u'>'))
        // a static factory: `PollingSubscriber<Odometry>::create_subscription(this, "odom")`
        port.typeWritten = templateArgumentsOf(shape.scope).value(0);
    int callbackFrom = nameIndex + 1;
    if (k.generic && nameIndex + 1 < int(args.size())) {
        const CppValue type = m_values.evaluate(args[size_t(nameIndex + 1)]);
        port.typeWritten =
            type.kind == CppValue::Kind::Literal || type.kind == CppValue::Kind::Local
                ? type.literal
                : type.text;
        ++callbackFrom;
    }
    if (!port.typeWritten.isEmpty() && !k.generic) {
        const QString head = splitScope(withoutTemplateArguments(port.typeWritten)).value(0);
        port.typeIsTemplateParameter =
            m_templateParameters.contains(head) || m_templateParameters.contains(port.typeWritten);
    }
    if (k.freeForm)
        port.receiver = simplified(m_tree, args.front());
    else if (!ts::isNull(shape.receiver))
        port.receiver = receiverText;
    if (port.kind == PortKind::Subscriber || port.kind == PortKind::ServiceServer ||
        port.kind == PortKind::ActionServer) {
        port.callback = callbackName(args, callbackFrom);
        const int at = m_function.parameterNames.indexOf(port.callback);
        if (at >= 0 && !m_locals.contains(port.callback))
            port.callbackParameter = at;
    }
    if (port.kind == PortKind::Publisher || port.kind == PortKind::Subscriber) {
        // QoS follows the name, or the callback in wrappers that take it first
        // (nav2's create_subscription(topic, callback, qos)).
        for (int i = callbackFrom; i < int(args.size()) && i <= callbackFrom + 1; ++i) {
            const QString text = simplified(m_tree, args[size_t(i)]);
            const bool callback = text.startsWith(QLatin1String("std::bind")) ||
                                  text.startsWith(QLatin1String("bind(")) ||
                                  text.startsWith(QLatin1String("std::forward")) ||
                                  text.startsWith(QLatin1Char('[')) ||
                                  text.startsWith(QLatin1Char('&')) ||
                                  (!port.callback.isEmpty() && text.contains(port.callback));
            if (!callback) {
                port.qos = text;
                break;
            }
        }
    }
    guardOf(call, &port.guard, &port.guardValue);
    m_function.ports.append(port);
    // A camera publisher or subscription has its camera info beside the image: `camera_info`
    // for `image_raw`, made by the same call (when the image's name is known).
    const bool camera = shape.name == QLatin1String("create_camera_publisher") ||
                        shape.name == QLatin1String("create_camera_subscription") ||
                        shape.name == QLatin1String("advertiseCamera") ||
                        shape.name == QLatin1String("subscribeCamera");
    if (camera && k.transportType == imageType &&
        (port.name.kind == CppValue::Kind::Literal || port.name.kind == CppValue::Kind::Local)) {
        CppPortCall info = port;
        info.name.literal = port.name.literal.left(port.name.literal.lastIndexOf(u'/') + 1) +
                            QStringLiteral("camera_info");
        info.transportType = QStringLiteral("sensor_msgs/msg/CameraInfo");
        info.typeWritten.clear();
        m_function.ports.append(info);
    }
    return true;
}

QString CppPortCallReader::callbackName(const std::vector<TSNode> &args, int first) const
{
    for (int i = first; i < int(args.size()); ++i) {
        const TSNode a = unwrap(m_tree, args[size_t(i)]);
        const auto t = ts::type(a);
        if (t == "lambda_expression")
            return QStringLiteral("lambda");
        if (t == "pointer_expression") {
            const QString target = simplified(m_tree, ts::field(a, fields().argument));
            return lastSegment(target);
        }
        if (t == "call_expression") {
            const CallShape shape = callShape(m_tree, ts::field(a, fields().function));
            if (shape.name == QLatin1String("bind") || shape.name == QLatin1String("bind_front")) {
                const auto bound = arguments(ts::field(a, fields().arguments));
                if (bound.empty())
                    return QStringLiteral("bind");
                const TSNode target = unwrap(m_tree, bound.front());
                if (ts::is(target, "pointer_expression"))
                    return lastSegment(simplified(m_tree, ts::field(target, fields().argument)));
                if (ts::is(target, "lambda_expression"))
                    return QStringLiteral("lambda");
                return lastSegment(simplified(m_tree, target));
            }
            continue; // QoS constructors and the like
        }
        if (t == "identifier" || t == "field_expression" || t == "qualified_identifier") {
            const QString text = simplified(m_tree, a);
            if (looksLikeNonCallback(text))
                continue;
            if (t == "identifier") {
                const auto it = m_locals.constFind(text);
                if (it != m_locals.constEnd() && !ts::isNull(it->value)) {
                    const TSNode value = unwrap(m_tree, it->value);
                    if (ts::is(value, "call_expression")) {
                        // A local holding std::bind(&C::f, ...) names f.
                        const QString bound = callbackName({value}, 0);
                        if (!bound.isEmpty() && bound != QLatin1String("lambda"))
                            return bound;
                    }
                }
                return text;
            }
            if (t == "field_expression")
                return m_tree.text(ts::field(a, fields().field));
            return lastSegment(text);
        }
    }
    return {};
}

void CppPortCallReader::guardOf(TSNode call, QString *guard, CppValue *guardValue) const
{
    QStringList conditions;
    TSNode child = call;
    for (TSNode p = ts_node_parent(call); !ts::isNull(p) && !sameNode(p, m_definition);
         child = p, p = ts_node_parent(p)) {
        if (!ts::is(p, "if_statement"))
            continue;
        const TSNode clause = ts::field(p, fields().condition);
        TSNode value = ts::field(clause, fields().value);
        if (ts::isNull(value))
            value = clause;
        QString text = simplified(m_tree, value);
        if (ts::is(value, "condition_clause") && text.startsWith(u'(') && text.endsWith(u')'))
            text = text.mid(1, text.size() - 2).trimmed();
        bool negated = false;
        if (encloses(ts::field(p, fields().consequence), child))
            negated = false;
        else if (encloses(ts::field(p, fields().alternative), child))
            negated = true;
        else
            continue; // inside the condition itself
        conditions.prepend(negated ? QStringLiteral("!(%1)").arg(text) : text);
        if (guardValue->isNone()) {
            CppValue found;
            ts::walk(value, [&](TSNode n) {
                if (found.kind == CppValue::Kind::Parameter)
                    return false;
                const auto t = ts::type(n);
                if (t == "identifier" || t == "field_expression" || t == "call_expression") {
                    const CppValue v = m_values.evaluate(n);
                    if (v.kind == CppValue::Kind::Parameter ||
                        (found.isNone() &&
                         (v.kind == CppValue::Kind::Member || v.kind == CppValue::Kind::Local)))
                        found = v;
                    return false;
                }
                return true;
            });
            *guardValue = found;
        }
    }
    *guard = conditions.join(QStringLiteral(" && "));
}

} // namespace rosarch
