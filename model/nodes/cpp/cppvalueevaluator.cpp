#include "nodes/cpp/cppvalueevaluator.h"

#include "core/rosnames.h"

#include "syntax/cpppreprocessor.h"

#include <QRegularExpression>

#include <algorithm>

namespace rosarch {

using namespace cppsyntax;

namespace {

// A variable that by its name holds a node: `node`, `node_`, `parent`, `node_ptr`.
bool isNodeHandleName(const QString &variable)
{
    static const QRegularExpression name(
        QStringLiteral(R"(^(this->)?(node|parent|parent_node|node_ptr|nh|node_handle)_?$)"));
    return name.match(variable).hasMatch();
}

// A part of a concatenation; a concatenation inside one is flattened into it.
void appendPart(CppValue *whole, CppValue part)
{
    if (part.kind == CppValue::Kind::Concatenation)
        for (CppValue &inner : part.parts)
            whole->parts.push_back(std::move(inner));
    else
        whole->parts.push_back(std::move(part));
}

CppValue literalPart(const QString &text)
{
    CppValue v;
    v.kind = CppValue::Kind::Literal;
    v.literal = text;
    v.text = text;
    return v;
}

// `{}`, `{0}` placeholders of a std::format / fmt::format string, split into literal pieces and
// argument indices (-1 in `indices` marks a literal piece). False when the string is malformed
// or a placeholder has a format spec (`{:02}`).
bool splitFormat(const QString &format, QStringList *pieces, QList<int> *indices)
{
    QString piece;
    int next = 0;
    for (qsizetype i = 0; i < format.size(); ++i) {
        const QChar c = format.at(i);
        if ((c == u'{' || c == u'}') && i + 1 < format.size() && format.at(i + 1) == c) {
            piece += c;
            ++i;
            continue;
        }
        if (c == u'}')
            return false;
        if (c != u'{') {
            piece += c;
            continue;
        }
        const qsizetype close = format.indexOf(u'}', i);
        if (close < 0)
            return false;
        const QString spec = format.mid(i + 1, close - i - 1);
        if (!spec.section(u':', 1).isEmpty())
            return false; // `{:02}`, `{:.2f}`: a format spec changes the text
        const QString id = spec.section(u':', 0, 0).trimmed();
        bool ok = true;
        const int index = id.isEmpty() ? next++ : id.toInt(&ok);
        if (!ok)
            return false;
        if (!piece.isEmpty()) {
            pieces->append(piece);
            indices->append(-1);
            piece.clear();
        }
        pieces->append(QString());
        indices->append(index);
        i = close;
    }
    if (!piece.isEmpty()) {
        pieces->append(piece);
        indices->append(-1);
    }
    return true;
}

// `for (std::size_t i = 0; ...)`: the initial value is no value of the variable in the body.
bool isLoopVariable(TSNode value)
{
    TSNode n = ts_node_parent(value);
    for (int up = 0; up < 3 && !ts::isNull(n); ++up, n = ts_node_parent(n))
        if (ts::is(n, "for_statement"))
            return true;
    return false;
}

} // namespace

void CppLocal::setValue(TSNode v)
{
    value = v;
    loopInitial = !ts::isNull(v) && isLoopVariable(v);
}

CppValueEvaluator::CppValueEvaluator(const SyntaxTree &tree, const QHash<QString, CppLocal> &locals,
                                     const CppFunction &function, const CppMacros *macros)
    : m_tree(tree), m_locals(locals), m_function(function), m_macros(macros)
{
}

int CppValueEvaluator::literalParameterIndex(const std::vector<TSNode> &args, QString *parameter,
                                             int depth) const
{
    for (size_t i = 0; i < args.size() && i < 3; ++i) {
        const CppValue v = evaluate(args[i], depth + 1);
        // `declare_or_get_parameter(name_ + "." + "map_topic", std::string("map"))`: the name
        // is built at run time; the literal after it is the default, not the name.
        if (v.kind == CppValue::Kind::Concatenation)
            return -1;
        if (v.kind != CppValue::Kind::Literal && v.kind != CppValue::Kind::Local)
            continue;
        // A bool or a number (or nothing) is not a parameter name.
        const QChar first = v.literal.isEmpty() ? QChar() : v.literal.at(0);
        if (first.isNull() || first.isDigit() || first == u'-' || first == u'.' ||
            v.literal == QLatin1String("true") || v.literal == QLatin1String("false"))
            continue;
        *parameter = v.literal;
        return int(i);
    }
    return -1;
}

CppValue CppValueEvaluator::evaluate(TSNode expression, int depth) const
{
    CppValue v;
    if (ts::isNull(expression))
        return v;
    v.text = simplified(m_tree, expression);
    // Every path deeper counts, identifiers and parameter calls included: a self-referencing
    // assignment (`x = node.declare_parameter(prefix + "x", x);`) must end, not recurse.
    if (depth > kMaxDepth) {
        v.kind = CppValue::Kind::Expression;
        return v;
    }
    const TSNode n = unwrap(m_tree, expression);
    QString literal;
    if (stringLiteral(m_tree, n, &literal)) {
        v.kind = CppValue::Kind::Literal;
        v.literal = literal;
        return v;
    }
    const auto t = ts::type(n);
    if (t == "true" || t == "false" || t == "number_literal" || t == "char_literal") {
        v.kind = CppValue::Kind::Literal; // as written, for parameter defaults and guards
        v.literal = m_tree.text(n);
        return v;
    }
    if (t == "this") {
        v.kind = CppValue::Kind::SelfNode;
        return v;
    }
    if (t == "pointer_expression" && ts::is(ts::field(n, fields().argument), "this")) {
        v.kind = CppValue::Kind::SelfNode;
        return v;
    }
    if (t == "identifier") {
        CppValue r = evaluateIdentifier(m_tree.text(n), depth);
        r.text = v.text;
        return r;
    }
    // `prefix + "/" + name`, `std::string(ns_) + "/" + name`: the parts, resolved later.
    if (t == "binary_expression" && m_tree.text(ts::field(n, fields().op)) == QLatin1String("+")) {
        v.kind = CppValue::Kind::Concatenation;
        for (const TSFieldId side : {fields().left, fields().right})
            appendPart(&v, evaluate(ts::field(n, side), depth + 1));
        return v;
    }
    if (t == "field_expression" && ts::is(ts::field(n, fields().argument), "this")) {
        v.kind = CppValue::Kind::Member;
        v.variable = m_tree.text(ts::field(n, fields().field));
        return v;
    }
    if (t == "field_expression") {
        CppValue f = evaluateField(n, depth);
        f.text = v.text;
        return f;
    }
    if (t == "compound_literal_expression" || t == "initializer_list") {
        CppValue a =
            evaluateAggregate(t == "initializer_list" ? n : ts::field(n, fields().value), depth);
        if (!a.isNone()) {
            a.text = v.text;
            return a;
        }
    }
    // `ns::kTopic`, `Foo::kTopic`: a constant of the workspace, looked up when linking.
    if (t == "qualified_identifier") {
        v.kind = CppValue::Kind::Constant;
        v.variable = v.text.startsWith(QLatin1String("::")) ? v.text.mid(2) : v.text;
        return v;
    }
    if (t == "call_expression") {
        const CallShape shape = callShape(m_tree, ts::field(n, fields().function));
        const bool onSelf = ts::isNull(shape.receiver) || ts::is(shape.receiver, "this");
        if (m_macros && ts::isNull(shape.receiver) && shape.scope.isEmpty() &&
            ts::isNull(shape.templateArguments)) {
            // TOPIC("scan") with `#define TOPIC(x) "robot/" x`: the string it expands to.
            const auto macro = m_macros->constFind(shape.name.toUtf8());
            if (macro != m_macros->cend() && macro->functionLike) {
                QList<QByteArray> texts;
                for (TSNode a : arguments(ts::field(n, fields().arguments)))
                    texts.append(
                        QByteArray(m_tree.view(a).data(), qsizetype(m_tree.view(a).size())));
                const QString value = CppPreprocessor::expandedValue(*macro, texts, *m_macros);
                if (!value.isNull()) {
                    v.kind = CppValue::Kind::Literal;
                    v.literal = value;
                    return v;
                }
            }
        }
        if ((shape.name == QLatin1String("shared_from_this") ||
             shape.name == QLatin1String("weak_from_this")) &&
            onSelf) {
            v.kind = CppValue::Kind::SelfNode;
            return v;
        }
        const QString lower = shape.name.toLower();
        if (lower.contains(QLatin1String("parameter")) &&
            !lower.endsWith(QLatin1String("parameters")) &&
            (lower.contains(QLatin1String("get")) || lower.contains(QLatin1String("declare")))) {
            QString parameter;
            const std::vector<TSNode> callArgs = arguments(ts::field(n, fields().arguments));
            if (literalParameterIndex(callArgs, &parameter, depth) >= 0) {
                v.kind = CppValue::Kind::Parameter;
                v.parameter = parameter;
                return v;
            }
            // `declare_or_get_parameter(source_name_ + ".topic", std::string("scan"))`: a name
            // the linker may decide (`parts[0]`), with the default after it (`parts[1]`).
            for (size_t i = 0; i < callArgs.size() && i < 3 && depth < 6; ++i) {
                CppValue name = evaluate(callArgs[i], depth + 1);
                if (name.kind != CppValue::Kind::Concatenation)
                    continue;
                v.kind = CppValue::Kind::Parameter;
                v.parts.push_back(std::move(name));
                if (i + 1 < callArgs.size())
                    v.parts.push_back(evaluate(callArgs[i + 1], depth + 1));
                return v;
            }
        }
        const std::vector<TSNode> args = arguments(ts::field(n, fields().arguments));
        // `std::shared_ptr<rclcpp::Node>(this, [](rclcpp::Node *) {})`: a handle on this node.
        if (shape.name == QLatin1String("shared_ptr") && !args.empty() &&
            evaluate(args.front(), depth + 1).kind == CppValue::Kind::SelfNode) {
            v.kind = CppValue::Kind::SelfNode;
            return v;
        }
        if (CppValue s = evaluateStringCall(shape, args, depth); !s.isNone()) {
            s.text = v.text;
            return s;
        }
        if (!ts::isNull(shape.receiver) && depth < 6) {
            // get_parameter("p").as_string(), .get_value<T>(), node.lock(), ...
            const CppValue inner = evaluate(shape.receiver, depth + 1);
            if (inner.kind == CppValue::Kind::Parameter) {
                CppValue r = inner;
                r.text = v.text;
                return r;
            }
            // `node->get_name()`: the name of the node a helper or plugin is handed
            if ((shape.name == QLatin1String("get_name") ||
                 shape.name == QLatin1String("get_namespace") ||
                 shape.name == QLatin1String("get_fully_qualified_name")) &&
                args.empty() &&
                (inner.kind == CppValue::Kind::SelfNode ||
                 ((inner.kind == CppValue::Kind::FunctionParameter ||
                   inner.kind == CppValue::Kind::Member) &&
                  isNodeHandleName(inner.variable.isEmpty() ? inner.text : inner.variable)))) {
                v.kind = CppValue::Kind::SelfCall;
                v.variable = shape.name;
                return v;
            }
            if (shape.name == QLatin1String("lock") &&
                (inner.kind == CppValue::Kind::SelfNode ||
                 inner.kind == CppValue::Kind::FunctionParameter ||
                 inner.kind == CppValue::Kind::Member)) {
                CppValue r = inner; // the weak pointer's node is the node it points to
                r.text = v.text;
                return r;
            }
            // `layer->getName()` in a loop over loaded plugin objects: the name each plugin of
            // that class is loaded under, which the instance's plugin parameters decide.
            if (shape.name == QLatin1String("getName") && args.empty() &&
                inner.kind == CppValue::Kind::Element) {
                const QString cls = elementClass(inner.variable);
                if (!cls.isEmpty()) {
                    v.kind = CppValue::Kind::Parameter;
                    v.parameter = QStringLiteral("%1%2}").arg(
                        QLatin1String(RosNames::kLoadedPluginPrefix), cls);
                    return v;
                }
            }
            // `costmap_.getName()` on an object that may turn out to be the node itself
            if (args.empty() && ts::isNull(shape.templateArguments) &&
                (inner.kind == CppValue::Kind::FunctionParameter ||
                 inner.kind == CppValue::Kind::Member)) {
                v.kind = CppValue::Kind::ObjectCall;
                v.field = shape.name;
                v.parts.push_back(inner);
                return v;
            }
        }
        // `getName()`: a method of this object without arguments, resolved through what it
        // returns in the object's most derived class.
        if (onSelf && args.empty() && ts::isNull(shape.templateArguments) &&
            shape.scope.isEmpty()) {
            v.kind = CppValue::Kind::SelfCall;
            v.variable = shape.name;
            return v;
        }
    }
    v.kind = CppValue::Kind::Expression;
    return v;
}

CppValue CppValueEvaluator::evaluateIdentifier(const QString &name, int depth) const
{
    const auto local = m_locals.constFind(name);
    if (local != m_locals.constEnd() && local->parentJoined)
        return joinedWithParentNamespace(evaluateBoundIdentifier(name, depth));
    return evaluateBoundIdentifier(name, depth);
}

CppValue CppValueEvaluator::evaluateBoundIdentifier(const QString &name, int depth) const
{
    CppValue v;
    v.text = name;
    v.variable = name;
    const auto it = m_locals.constFind(name);
    if (it != m_locals.constEnd()) {
        if (!it->parameter.isEmpty()) {
            v.kind = CppValue::Kind::Parameter;
            v.parameter = it->parameter;
            return v;
        }
        if (it->element && !ts::isNull(it->value) && depth < 6) {
            v.kind = CppValue::Kind::Element;
            v.parts.push_back(evaluate(it->value, depth + 1));
            return v;
        }
        if (ts::isNull(it->value) && !it->fields.isEmpty()) { // `Settings s; s.topic = "scan";`
            v.kind = CppValue::Kind::Aggregate;
            for (const auto &[field, value] : it->fields) {
                CppValue name;
                name.kind = CppValue::Kind::Literal;
                name.literal = field;
                v.parts.push_back(name);
                v.parts.push_back(evaluate(value, depth + 1));
            }
            return v;
        }
        if (ts::isNull(it->value) && !it->outCall.isEmpty()) {
            v.kind = CppValue::Kind::OutArgument;
            v.variable = it->outCall;
            v.index = it->outIndex;
            return v;
        }
        if (!ts::isNull(it->value) && depth < 6 && !it->loopInitial) {
            const CppValue inner = evaluate(it->value, depth + 1);
            switch (inner.kind) {
            case CppValue::Kind::Literal:
            case CppValue::Kind::Local:
                v.kind = CppValue::Kind::Local;
                v.literal = inner.literal;
                return v;
            case CppValue::Kind::Parameter:
                v.kind = CppValue::Kind::Parameter;
                v.parameter = inner.parameter;
                v.parts = inner.parts; // a name the linker builds
                return v;
            case CppValue::Kind::SelfNode:
            case CppValue::Kind::Member:
            case CppValue::Kind::FunctionParameter:
            case CppValue::Kind::SelfCall:
            case CppValue::Kind::Concatenation:
            case CppValue::Kind::Field:
            case CppValue::Kind::Element:
            case CppValue::Kind::Aggregate:
            case CppValue::Kind::Constant: {
                CppValue r = inner;
                r.text = name;
                return r;
            }
            default:
                break;
            }
        }
        v.kind = CppValue::Kind::Expression;
        return v;
    }
    const qsizetype index = m_function.parameterNames.indexOf(name);
    if (index >= 0) {
        v.kind = CppValue::Kind::FunctionParameter;
        v.index = int(index);
        return v;
    }
    // Not a local: a member (or a namespace-level constant, which the linker also knows).
    v.kind = CppValue::Kind::Member;
    return v;
}

// `params_->topic`, `this->params_.topic`, `p.topic` (p a local or a parameter of the function),
// `handler_->getParams()->topic`: a field, with what the function knows of the object.
CppValue CppValueEvaluator::evaluateAggregate(TSNode list, int depth) const
{
    CppValue v;
    if (depth > kMaxDepth || !ts::is(list, "initializer_list"))
        return v;
    // `{"dock", "gate"}`: a list of names, its fields unnamed
    const std::vector<TSNode> items = ts::namedChildren(list);
    QString literal;
    if (!items.empty() && std::all_of(items.cbegin(), items.cend(), [&](TSNode item) {
            return stringLiteral(m_tree, unwrap(m_tree, item), &literal);
        })) {
        for (TSNode item : items) {
            v.parts.push_back({});
            v.parts.back().kind = CppValue::Kind::Literal;
            v.parts.push_back(evaluate(item, depth + 1));
        }
        v.kind = CppValue::Kind::Aggregate;
        return v;
    }
    for (TSNode pair : items) {
        if (!ts::is(pair, "initializer_pair"))
            continue;
        const std::vector<TSNode> kids = ts::namedChildren(pair);
        const QString designator = kids.empty() ? QString() : simplified(m_tree, kids.front());
        if (!designator.startsWith(u'.'))
            continue; // `[0] = x`
        CppValue name;
        name.kind = CppValue::Kind::Literal;
        name.literal = designator.mid(1).trimmed();
        v.parts.push_back(name);
        v.parts.push_back(evaluate(ts::field(pair, fields().value), depth + 1));
    }
    if (!v.parts.empty())
        v.kind = CppValue::Kind::Aggregate;
    return v;
}

QString CppValueEvaluator::elementClass(const QString &variable) const
{
    const auto it = m_locals.constFind(variable);
    if (it == m_locals.constEnd() || !it->element)
        return {};
    // `auto x = std::dynamic_pointer_cast<CostmapLayer>(layer);`, `dynamic_cast<T *>(layer.get())`
    static const QRegularExpression cast(QStringLiteral(
        R"(^(?:std::)?dynamic(?:_pointer)?_cast\s*<\s*(?:const\s+)?([A-Za-z_][\w:]*)\s*\*?\s*>\s*)"
        R"(\(\s*([A-Za-z_]\w*)\s*(?:\.\s*get\s*\(\s*\))?\s*\)$)"));
    for (auto l = m_locals.constBegin(); l != m_locals.constEnd(); ++l) {
        if (l->element || ts::isNull(l->value) || !ts::is(l->value, "call_expression"))
            continue;
        const QRegularExpressionMatch m = cast.match(simplified(m_tree, l->value));
        if (m.hasMatch() && m.captured(2) == variable)
            return lastSegment(m.captured(1));
    }
    // `for (std::shared_ptr<Layer> & layer : layers)`: the pointee of a smart pointer
    static const QRegularExpression declared(QStringLiteral(
        R"(^(?:const\s+)?(?:std::(?:shared|unique)_ptr\s*<\s*(?:const\s+)?([\w:]+)\s*>|([\w:]+)))"));
    const QRegularExpressionMatch m = declared.match(it->type.trimmed());
    const QString type = m.captured(1).isEmpty() ? m.captured(2) : m.captured(1);
    if (type.isEmpty() || type == QLatin1String("auto") || type.startsWith(QLatin1String("std::")))
        return {};
    return lastSegment(type);
}

CppValue CppValueEvaluator::evaluateField(TSNode n, int depth) const
{
    CppValue v;
    v.kind = CppValue::Kind::Field;
    v.field = m_tree.text(ts::field(n, fields().field));
    const TSNode object = unwrap(m_tree, ts::field(n, fields().argument));
    if (ts::is(object, "identifier")) {
        const QString name = m_tree.text(object);
        const auto local = m_locals.constFind(name);
        const qsizetype index = m_function.parameterNames.indexOf(name);
        if (local != m_locals.constEnd()) {
            // `auto & p = params_;` reads the member; `Parameters p;` has its own type.
            // `Settings s; s.topic = "scan";`: the field as this function set it (only that
            // one: a field computed from others must not evaluate the whole struct again)
            for (const auto &[field, value] : local->fields) {
                if (field != v.field)
                    continue;
                const QString key = name + u'.' + field; // `s.a = s.b + s.b; s.b = s.a;`
                if (m_fieldsOnTheWay.contains(key)) {
                    v.kind = CppValue::Kind::Expression;
                    return v;
                }
                m_fieldsOnTheWay.insert(key);
                CppValue held = evaluate(value, depth + 1);
                m_fieldsOnTheWay.remove(key);
                return held;
            }
            const CppValue held =
                ts::isNull(local->value) ? CppValue() : evaluate(local->value, depth + 1);
            if (held.kind == CppValue::Kind::Member)
                v.variable = held.variable;
            else
                v.objectType = local->type;
            if (held.kind == CppValue::Kind::Aggregate) { // `auto s = Settings{.topic = x};`
                for (size_t i = 0; i + 1 < held.parts.size(); i += 2)
                    if (held.parts[i].literal == v.field)
                        return held.parts[i + 1];
            }
        } else if (index >= 0) {
            QString type = m_function.parameterTypes.value(index);
            if (type.endsWith(name))
                type = type.chopped(name.size()).trimmed();
            v.objectType = type;
            v.index = int(index); // a caller's argument may set the field (an Aggregate)
        } else {
            v.variable = name;
        }
    } else if (ts::is(object, "field_expression") &&
               ts::is(ts::field(object, fields().argument), "this")) {
        v.variable = m_tree.text(ts::field(object, fields().field));
    } else if (!ts::is(object, "call_expression")) {
        v.kind = CppValue::Kind::Expression; // `msg->header.frame_id`, `arr[i].topic`, ...
    }
    return v;
}

// Calls that make a string of their arguments: `std::string(x)` and `std::to_string(x)` are x,
// `x.c_str()` is x, `std::format("{}/{}", a, b)` / `fmt::format(...)` join the pieces and
// arguments; a node's `resolve_topic_or_service_name(x, …)` is x, and image_transport's
// `getCameraInfoTopic(x)` is x's sibling `camera_info`. None when the call is none of them.
CppValue joinedWithParentNamespace(CppValue inner)
{
    // A message's field (`msg->filter_mask_topic`) is what another node sends at run time.
    if (inner.kind == CppValue::Kind::Expression || inner.kind == CppValue::Kind::None ||
        inner.kind == CppValue::Kind::Field) {
        inner.kind = CppValue::Kind::Expression;
        return inner;
    }
    CppValue prefix;
    prefix.kind = CppValue::Kind::Literal;
    prefix.literal = QLatin1String(RosNames::kParentNamespacePlaceholder) + QLatin1Char('/');
    prefix.text = QStringLiteral("\"%1\"").arg(prefix.literal);
    CppValue joined;
    joined.kind = CppValue::Kind::Concatenation;
    joined.text = QStringLiteral("%1(%2)").arg(QLatin1String(kJoinWithParentNamespace), inner.text);
    joined.parts.push_back(prefix);
    joined.parts.push_back(std::move(inner));
    return joined;
}

CppValue CppValueEvaluator::evaluateStringCall(const CallShape &shape,
                                               const std::vector<TSNode> &args, int depth) const
{
    const bool inStd = shape.scope == QLatin1String("std");
    const bool one = ts::isNull(shape.receiver) && args.size() == 1 && inStd;
    if (one && shape.name == QLatin1String("string"))
        return evaluate(args.front(), depth + 1);
    if (one && shape.name == QLatin1String("to_string")) {
        // Only an integer reads the same in code and in the name (to_string(0.5) is "0.500000").
        static const QRegularExpression integer(QStringLiteral("^-?\\d+$"));
        CppValue inner = evaluate(args.front(), depth + 1);
        const bool known =
            inner.kind == CppValue::Kind::Literal || inner.kind == CppValue::Kind::Local;
        if (!known || !integer.match(inner.literal).hasMatch())
            inner.kind = CppValue::Kind::Expression;
        return inner;
    }
    // navigation2's costmap layers: a relative name joined to the parent of the node's
    // namespace, which the instance decides.
    if (shape.name == QLatin1String(kJoinWithParentNamespace) && args.size() == 1)
        return joinedWithParentNamespace(evaluate(args.front(), depth + 1));
    if (shape.name == QLatin1String("c_str") && !ts::isNull(shape.receiver) && args.empty())
        return evaluate(shape.receiver, depth + 1);
    // `node_base->resolve_topic_or_service_name("depth/image_rect", false)`: the name expanded
    // in the node's namespace, as the port itself would expand it.
    if (shape.name == QLatin1String("resolve_topic_or_service_name") && !args.empty())
        return evaluate(args.front(), depth + 1);
    // `image_transport::getCameraInfoTopic(image)`: the `camera_info` beside the image.
    if (shape.name == QLatin1String("getCameraInfoTopic") && args.size() == 1) {
        CppValue v = evaluate(args.front(), depth + 1);
        if (v.kind != CppValue::Kind::Literal && v.kind != CppValue::Kind::Local) {
            v = {};
            v.kind = CppValue::Kind::Expression;
            return v;
        }
        const qsizetype slash = v.literal.lastIndexOf(u'/');
        v.literal = v.literal.left(slash + 1) + QStringLiteral("camera_info");
        return v;
    }
    if (shape.name != QLatin1String("format") || !ts::isNull(shape.receiver) ||
        !(inStd || shape.scope == QLatin1String("fmt")) || args.empty())
        return {};
    CppValue v;
    v.kind = CppValue::Kind::Expression;
    QString format;
    QStringList pieces;
    QList<int> indices;
    if (!stringLiteral(m_tree, unwrap(m_tree, args.front()), &format) ||
        !splitFormat(format, &pieces, &indices))
        return v;
    v.kind = CppValue::Kind::Concatenation;
    for (qsizetype i = 0; i < pieces.size(); ++i) {
        const int index = indices.at(i);
        if (index < 0) {
            v.parts.push_back(literalPart(pieces.at(i)));
            continue;
        }
        if (size_t(index) + 1 >= args.size()) {
            v.kind = CppValue::Kind::Expression;
            v.parts.clear();
            return v;
        }
        appendPart(&v, evaluate(args[size_t(index) + 1], depth + 1));
    }
    return v;
}

} // namespace rosarch
