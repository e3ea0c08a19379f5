#include "nodes/cpp/cppfunctionextractor.h"
#include "nodes/cpp/cppfunctiontext.h"
#include "nodes/cpp/cppparameterreader.h"

#include <cstring>

// CppFunctionExtractor's calls: port and parameter calls, instantiations, method and free
// calls, procedural nodes.

#include <algorithm>

namespace rosarch {

using namespace cppsyntax;
using namespace cppfunctiontext;

void CppFunctionExtractor::onCall(TSNode call)
{
    const CallShape shape = callShape(m_tree, ts::field(call, fields().function));
    if (shape.name.isEmpty())
        return;
    const auto args = arguments(ts::field(call, fields().arguments));
    onParameterCall(call, shape, args);
    if (m_portCalls.read(call, shape, args))
        return;

    const bool makeShared =
        shape.name == QLatin1String("make_shared") || shape.name == QLatin1String("make_unique");
    if (!makeShared) {
        markOutArguments(shape, args);
        addFreeCall(call, shape, args);
        addMethodCall(call, shape, args);
        return;
    }
    QString className;
    if (!ts::isNull(shape.templateArguments))
        className = firstTemplateArgument(m_tree, shape.templateArguments);
    else if (!shape.scope.isEmpty() && shape.scope != QLatin1String("std"))
        className = shape.scope; // Talker::make_shared(...)
    if (className.isEmpty())
        return;
    bool lifecycle = false;
    if (isProceduralNodeType(className, &lifecycle)) {
        addProceduralNode(call, args, lifecycle);
        return;
    }
    addInstantiation(className, args, call);
}

void CppFunctionExtractor::onParameterCall(TSNode call, const CallShape &shape,
                                           const std::vector<TSNode> &args)
{
    const QString &name = shape.name;
    if ((name == QLatin1String("allow_undeclared_parameters") ||
         name == QLatin1String("automatically_declare_parameters_from_overrides")) &&
        !args.empty() && m_tree.text(args.front()) == QLatin1String("true"))
        m_function.acceptsUndeclared = true;
    // a getter a parameters handler handed out, called through a local
    if (ts::isNull(shape.receiver) && shape.scope.isEmpty() && args.size() >= 3) {
        const auto local = m_locals.constFind(name);
        if (local != m_locals.cend() && !ts::isNull(local->value)) {
            CppParameterDeclaration d =
                CppParameterReader(m_tree, m_values).readGetterCall(call, args, local->value);
            if (!d.via.isEmpty()) {
                CppValue tested;
                m_portCalls.guardOf(call, &d.guard, &tested);
                m_function.parameterDeclarations.append(d);
                return;
            }
        }
    }
    // Both forms name a parameter: an ASCII name without it is neither (most calls), with no
    // lower-case copy made. Other names take the long way, where case mapping is Unicode's.
    if (isAscii(name) && !name.contains(QLatin1String("parameter"), Qt::CaseInsensitive))
        return;
    const CppParameterReader reader(m_tree, m_values);
    for (CppParameterDeclaration d : reader.readMany(call, shape, args)) {
        CppValue tested;
        m_portCalls.guardOf(call, &d.guard, &tested);
        m_function.parameterDeclarations.append(d);
    }
    CppParameterDeclaration declared = reader.read(call, shape, args, m_definition);
    if (!declared.via.isEmpty()) {
        CppValue tested;
        QString guard;
        m_portCalls.guardOf(call, &guard, &tested);
        if (!guard.isEmpty())
            declared.guard = guard;
        m_function.parameterDeclarations.append(declared);
    }
    const bool readDeclared = !declared.via.isEmpty() && !declared.parameter.isEmpty();
    const QString lower = name.toLower();
    const bool declares = lower.contains(QLatin1String("declare")) &&
                          lower.contains(QLatin1String("parameter")) &&
                          !lower.endsWith(QLatin1String("parameters"));
    const bool gets = name == QLatin1String("get_parameter") ||
                      name == QLatin1String("get_parameter_or") ||
                      name == QLatin1String("get_parameter_or_set_default");
    if (!declares && !gets)
        return;
    QString parameter;
    const int at = m_values.literalParameterIndex(args, &parameter);
    if (at < 0)
        return;
    const int next = at + 1;
    if (declares && readDeclared)
        return;
    if (declares) {
        CppParameterDeclaration decl;
        decl.parameter = parameter;
        if (next < int(args.size()))
            decl.defaultValue = m_values.evaluate(args[size_t(next)]);
        m_function.parameterDeclarations.append(decl);
        return;
    }
    if (next >= int(args.size()))
        return;
    // get_parameter("p", variable) / get_parameter_or("p", variable, default)
    const TSNode target = args[size_t(next)];
    if (name != QLatin1String("get_parameter") && next + 1 < int(args.size()) && !readDeclared)
        m_function.parameterDeclarations.append(
            {parameter, m_values.evaluate(args[size_t(next + 1)])});
    CppValue bound;
    bound.kind = CppValue::Kind::Parameter;
    bound.parameter = parameter;
    bound.text = simplified(m_tree, target);
    if (ts::is(target, "identifier")) {
        const QString var = m_tree.text(target);
        auto it = m_locals.find(var);
        if (it != m_locals.end()) {
            it->parameter = parameter;
            return;
        }
        bound.variable = var;
        if (m_member && !m_function.parameterNames.contains(var))
            m_function.memberBindings.append({var, bound});
    } else if (ts::is(target, "field_expression") &&
               ts::is(ts::field(target, fields().argument), "this")) {
        bound.variable = m_tree.text(ts::field(target, fields().field));
        m_function.memberBindings.append({bound.variable, bound});
    } else if (ts::is(target, "field_expression")) {
        addFieldBinding(target, bound); // get_parameter("p", params_.p)
    }
}

void CppFunctionExtractor::addInstantiation(const QString &className,
                                            const std::vector<TSNode> &args, TSNode where,
                                            const QString &member)
{
    CppInstantiation inst;
    inst.className = className;
    inst.member = member;
    inst.evidence = m_tree.evidence(where);
    if (member.isEmpty() && !className.isEmpty()) {
        m_portCalls.guardOf(where, &inst.guard, &inst.guardValue);
    }
    bool interesting = member.isEmpty() && !className.isEmpty();
    for (TSNode a : args) {
        CppValue v;
        if (ts::is(a, "parameter_declaration")) {
            // Most vexing parse: `T x(node)`; the "parameter" is the argument's text.
            const QString text = simplified(m_tree, a);
            if (!text.contains(u'('))
                v = m_values.evaluateIdentifier(text, 0);
            else if (text == QLatin1String("shared_from_this()") ||
                     text == QLatin1String("weak_from_this()"))
                v.kind = CppValue::Kind::SelfNode;
            else
                v.kind = CppValue::Kind::Expression;
            v.text = text;
        } else {
            v = m_values.evaluate(a);
        }
        if (v.kind == CppValue::Kind::SelfNode)
            interesting = true;
        inst.arguments.append(v);
    }
    // Member initializers matter only when they hand the node to a helper.
    if (!member.isEmpty())
        for (const CppValue &v : std::as_const(inst.arguments))
            if (v.kind == CppValue::Kind::SelfNode || v.kind == CppValue::Kind::FunctionParameter ||
                v.kind == CppValue::Kind::Member)
                interesting = true;
    if (interesting)
        m_function.instantiations.append(inst);
}

void CppFunctionExtractor::addMethodCall(TSNode call, const CallShape &shape,
                                         const std::vector<TSNode> &args)
{
    if (!m_member || ts::isNull(shape.receiver) || args.empty())
        return;
    // Only calls on a member (`x_->m(...)`, `this->x_.m(...)`), not on locals or parameters.
    const CppValue object = m_values.evaluate(shape.receiver);
    if (object.kind != CppValue::Kind::Member || object.variable.isEmpty())
        return;
    CppMethodCall c;
    c.member = object.variable;
    c.method = shape.name;
    if (!ts::isNull(shape.templateArguments))
        for (TSNode a : arguments(shape.templateArguments))
            c.templateArguments.append(simplified(m_tree, a));
    bool named = false;
    for (TSNode a : args) {
        CppValue v = m_values.evaluate(a);
        named = named || v.kind == CppValue::Kind::Literal || v.kind == CppValue::Kind::Local;
        c.arguments.append(std::move(v));
    }
    if (!named && c.templateArguments.isEmpty())
        return; // `pub_->publish(msg)`: nothing a lazy helper would key a port by
    m_portCalls.guardOf(call, &c.guard, &c.guardValue);
    c.evidence = m_tree.evidence(call);
    m_function.methodCalls.append(c);
}

// `std::string topic; getParameters(topic);`: a local declared without a value and handed to a
// function of this object (or a free one) may be filled through a reference parameter. The
// local then holds what that function assigns there, which the linker looks up.
void CppFunctionExtractor::markOutArguments(const CallShape &shape, const std::vector<TSNode> &args)
{
    if (!ts::isNull(shape.receiver) && !ts::is(shape.receiver, "this"))
        return;
    for (size_t i = 0; i < args.size(); ++i) {
        const TSNode a = unwrap(m_tree, args[i]);
        if (!ts::is(a, "identifier"))
            continue;
        const QString name = m_tree.text(a);
        const auto it = m_locals.find(name);
        if (it == m_locals.end()) {
            // `getParameters(std::string & topic) { readCommon(topic); }`: this function's own
            // reference parameter, filled for its caller by the function it is handed to
            const qsizetype at = m_function.parameterNames.indexOf(name);
            const QString type = at >= 0 ? m_function.parameterTypes.value(at) : QString();
            const bool assigned =
                std::any_of(m_function.outBindings.cbegin(), m_function.outBindings.cend(),
                            [&](const CppMemberBinding &b) { return b.member == name; });
            if (!assigned && type.contains(u'&') && !type.contains(QLatin1String("const"))) {
                CppValue filled;
                filled.kind = CppValue::Kind::OutArgument;
                filled.text = name;
                filled.variable = shape.name;
                filled.index = int(i);
                m_function.outBindings.append({name, filled});
            }
            continue;
        }
        if (!ts::isNull(it->value) || !it->parameter.isEmpty() || !it->outCall.isEmpty())
            continue;
        it->outCall = shape.name;
        it->outIndex = int(i);
    }
}

void CppFunctionExtractor::addFreeCall(TSNode where, const CallShape &shape,
                                       const std::vector<TSNode> &args)
{
    // Only calls without an object, and only those that pass something node-like: `this`, a
    // parameter, a member or a plain variable (a procedural node). In a free function any
    // other is kept apart: it may build nodes for `main`.
    if (!ts::isNull(shape.receiver) || shape.scope == QLatin1String("std"))
        return;
    if (isAscii(shape.name) ? !hasLowerCase(shape.name) : shape.name == shape.name.toUpper())
        return; // RCLCPP_INFO and other macros
    const bool mayBuild = !m_member && !shape.scope.startsWith(QLatin1String("rclcpp"));
    if (args.empty()) {
        if (mayBuild)
            m_function.builderCalls.append({shape.scope.isEmpty()
                                                ? shape.name
                                                : shape.scope + QStringLiteral("::") + shape.name,
                                            {},
                                            m_tree.evidence(where)});
        return;
    }
    CppFreeCall call;
    call.function =
        shape.scope.isEmpty() ? shape.name : shape.scope + QStringLiteral("::") + shape.name;
    bool handsSomething = false;
    for (TSNode a : args) {
        const CppValue v = m_values.evaluate(a);
        const bool plain = v.kind == CppValue::Kind::Expression && !v.text.isEmpty() &&
                           (v.text.at(0).isLetter() || v.text.at(0) == u'_') &&
                           !v.text.contains(u'(') && !v.text.contains(u' ');
        // (an OutArgument too: a name read into a local, handed on to a method of the class)
        handsSomething = handsSomething || plain || v.kind == CppValue::Kind::SelfNode ||
                         v.kind == CppValue::Kind::FunctionParameter ||
                         v.kind == CppValue::Kind::Member || v.kind == CppValue::Kind::OutArgument;
        call.arguments.append(v);
    }
    call.evidence = m_tree.evidence(where);
    if (handsSomething)
        m_function.freeCalls.append(call);
    else if (mayBuild)
        m_function.builderCalls.append(call);
}

void CppFunctionExtractor::addProceduralNode(TSNode creation, const std::vector<TSNode> &args,
                                             bool lifecycle)
{
    CppProceduralNode node;
    node.variable = assignedVariable(creation);
    if (node.variable.startsWith(QLatin1String("this->")))
        node.variable = node.variable.mid(6);
    node.lifecycle = lifecycle;
    if (!args.empty())
        node.nodeName = m_values.evaluate(args.front());
    node.evidence = m_tree.evidence(creation);
    TSNode up = ts_node_parent(creation);
    while (ts::is(up, "parenthesized_expression"))
        up = ts_node_parent(up);
    if (ts::is(up, "return_statement"))
        return; // `return rclcpp::Node::make_shared(...)`: a factory
    if (m_member) {
        // In a member function only a node kept in a member matters (a node-like component).
        if (node.variable.isEmpty() || m_locals.contains(node.variable) ||
            m_function.parameterNames.contains(node.variable))
            return;
        node.member = true;
    }
    m_function.proceduralNodes.append(node);
}

bool CppFunctionExtractor::isProceduralNodeType(const QString &className, bool *lifecycle) const
{
    QString c = withoutTemplateArguments(className);
    if (c.startsWith(QLatin1String("::")))
        c = c.mid(2);
    if (c == QLatin1String("rclcpp::Node") ||
        (c == QLatin1String("Node") && m_context.rclcppNodeInScope)) {
        *lifecycle = false;
        return true;
    }
    if (c == QLatin1String("rclcpp_lifecycle::LifecycleNode") ||
        (c == QLatin1String("LifecycleNode") && m_context.lifecycleNodeInScope)) {
        *lifecycle = true;
        return true;
    }
    return false;
}

QString CppFunctionExtractor::assignedVariable(TSNode expression) const
{
    TSNode n = expression;
    TSNode p = ts_node_parent(n);
    while (ts::is(p, "parenthesized_expression")) {
        n = p;
        p = ts_node_parent(p);
    }
    if (ts::is(p, "init_declarator") && nodesEqual(ts::field(p, fields().value), n))
        return m_tree.text(declaredName(ts::field(p, fields().declarator)));
    if (ts::is(p, "assignment_expression") && nodesEqual(ts::field(p, fields().right), n))
        return simplified(m_tree, ts::field(p, fields().left));
    if (ts::is(p, "argument_list") && ts::is(ts_node_parent(p), "field_initializer"))
        return simplified(m_tree, ts::namedChildren(ts_node_parent(p)).front());
    return {};
}

} // namespace rosarch
