#include "nodes/cpp/cppfunctionextractor.h"
#include "nodes/cpp/cppfunctiontext.h"

#include <algorithm>
#include <cstring>

namespace rosarch {

using namespace cppsyntax;
using namespace cppfunctiontext;

namespace {

// The function_declarator inside a definition's declarator (through pointer/reference
// declarators of the return type).
TSNode functionDeclarator(TSNode declarator)
{
    TSNode n = declarator;
    for (int guard = 0; guard < 8 && !ts::isNull(n); ++guard) {
        if (ts::is(n, "function_declarator"))
            return n;
        TSNode inner = ts::field(n, fields().declarator);
        if (ts::isNull(inner)) {
            const auto kids = ts::namedChildren(n);
            if (kids.empty())
                break;
            inner = kids.back();
        }
        n = inner;
    }
    TSNode null{};
    return null;
}

} // namespace

CppFunctionExtractor::CppFunctionExtractor(const SyntaxTree &tree, Context context)
    : m_tree(tree), m_context(std::move(context))
{
}

CppFunction CppFunctionExtractor::extract(TSNode definition,
                                          const QStringList &functionTemplateParameters)
{
    m_definition = definition;
    m_function = CppFunction();
    m_function.ownerClass = m_context.ownerClass;
    m_function.namespaces = m_context.namespaces;
    m_function.evidence = m_tree.evidence(definition);
    m_templateParameters = m_context.templateParameters + functionTemplateParameters;
    m_function.templateParameters = functionTemplateParameters;
    readSignature(definition);
    m_member = m_context.ownerClass >= 0 || !m_function.ownerScope.isEmpty();
    readInitializers(definition);
    const TSNode body = ts::field(definition, fields().body);
    visit(body);
    // `std::string getName() override {return std::string("navigate_to_pose");}`
    const std::vector<TSNode> statements = arguments(body);
    if (statements.size() == 1 && ts::is(statements.front(), "return_statement")) {
        const std::vector<TSNode> value = arguments(statements.front());
        if (value.size() == 1)
            m_function.returnValue = m_values.evaluate(value.front());
    }
    // A function that returns the node it creates is a factory, not a node definition.
    m_function.proceduralNodes.removeIf(
        [this](const CppProceduralNode &n) { return m_returned.contains(n.variable); });
    return std::move(m_function);
}

void CppFunctionExtractor::readSignature(TSNode definition)
{
    const TSNode fd = functionDeclarator(ts::field(definition, fields().declarator));
    TSNode nameNode = ts::field(fd, fields().declarator);
    QStringList scope;
    while (ts::is(nameNode, "qualified_identifier")) {
        const TSNode s = ts::field(nameNode, fields().scope);
        if (!ts::isNull(s))
            scope.append(simplified(m_tree, s));
        nameNode = ts::field(nameNode, fields().name);
    }
    if (ts::is(nameNode, "template_function"))
        nameNode = ts::field(nameNode, fields().name);
    m_function.name = simplified(m_tree, nameNode);
    m_function.ownerScope = scope.join(QStringLiteral("::"));
    const QString className =
        m_function.ownerScope.isEmpty() ? m_context.className : lastSegment(m_function.ownerScope);
    m_function.isConstructor = !className.isEmpty() && m_function.name == className;

    for (TSNode p : ts::namedChildren(ts::field(fd, fields().parameters))) {
        if (ts::is(p, "comment") || m_tree.view(p) == "void")
            continue;
        const TSNode nameOf = declaredName(ts::field(p, fields().declarator));
        const TSNode def = ts::field(p, fields().defaultValue);
        QString defaultValue;
        stringLiteral(m_tree, def, &defaultValue);
        // The declaration without its default: "const std::string & topic".
        std::string_view declared = m_tree.view(p);
        if (!ts::isNull(def))
            declared = declared.substr(0, ts_node_start_byte(def) - ts_node_start_byte(p));
        QString declaration =
            QString::fromUtf8(declared.data(), qsizetype(declared.size())).simplified();
        if (declaration.endsWith(u'='))
            declaration = declaration.chopped(1).trimmed();
        if (ts::is(p, "variadic_parameter_declaration") || m_tree.view(p) == "...")
            m_function.variadic = true;
        else if (!ts::is(p, "optional_parameter_declaration"))
            ++m_function.requiredParameters;
        m_function.parameterNames.append(m_tree.text(nameOf));
        m_function.parameterTypes.append(declaration);
        m_function.parameterDefaults.append(defaultValue);
    }
}

void CppFunctionExtractor::readInitializers(TSNode definition)
{
    for (TSNode child : ts::namedChildren(definition)) {
        if (!ts::is(child, "field_initializer_list"))
            continue;
        for (TSNode init : ts::namedChildren(child)) {
            if (!ts::is(init, "field_initializer"))
                continue;
            TSNode nameNode{};
            TSNode list{};
            for (TSNode part : ts::namedChildren(init)) {
                if (ts::is(part, "argument_list") || ts::is(part, "initializer_list"))
                    list = part;
                else if (ts::isNull(nameNode))
                    nameNode = part;
            }
            const auto args = arguments(list);
            CppBaseInitializer base;
            base.name = simplified(m_tree, nameNode);
            if (!args.empty())
                base.firstArgument = m_values.evaluate(args.front());
            constexpr size_t kMaxArguments = 8; // a base's constructor takes a few
            // (a base is written like a member here: `Base(x)` parses as a field's initializer)
            for (size_t i = 0; i < args.size() && i < kMaxArguments; ++i)
                base.arguments.append(i == 0 ? base.firstArgument : m_values.evaluate(args[i]));
            m_function.baseInitializers.append(base);
            if (ts::is(nameNode, "field_identifier")) {
                if (args.size() == 1)
                    m_function.memberBindings.append({base.name, base.firstArgument});
                addInstantiation(QString(), args, init, base.name);
            }
            // Initializers can create ports and instantiate helpers, too.
            for (TSNode a : args)
                visit(a);
        }
    }
}

void CppFunctionExtractor::visit(TSNode root)
{
    // ts::walk, keeping the path from `root` down (m_path), so that the handlers know the
    // ancestors of the node they read without climbing with ts_node_parent, which descends
    // from the root of the tree on each call.
    if (ts::isNull(root))
        return;
    m_path.clear();
    TSTreeCursor cursor = ts_tree_cursor_new(root);
    for (;;) {
        const TSNode n = ts_tree_cursor_current_node(&cursor);
        if (visitNode(n) && ts_tree_cursor_goto_first_child(&cursor)) {
            m_path.push_back(n);
            continue;
        }
        // Up until a next sibling exists, never above `root`.
        bool moved = false;
        while (!moved && !m_path.empty()) {
            moved = ts_tree_cursor_goto_next_sibling(&cursor);
            if (!moved) {
                if (!ts_tree_cursor_goto_parent(&cursor))
                    break;
                m_path.pop_back();
            }
        }
        if (!moved)
            break;
    }
    ts_tree_cursor_delete(&cursor);
    m_path.clear();
}

bool CppFunctionExtractor::visitNode(TSNode n)
{
    enum
    {
        Declaration,
        Assignment,
        Call,
        New,
        Return,
        Alias,
        Using,
        TypeDefinition,
        Class,
        Struct,
        RangeFor
    };
    static const ts::TypeSet kinds(SyntaxTree::Grammar::Cpp,
                                   {"declaration", "assignment_expression", "call_expression",
                                    "new_expression", "return_statement", "alias_declaration",
                                    "using_declaration", "type_definition", "class_specifier",
                                    "struct_specifier", "for_range_loop"});
    static const ts::TypeSet identifier(SyntaxTree::Grammar::Cpp, {"identifier"});
    static const ts::TypeSet namespaceKeyword(SyntaxTree::Grammar::Cpp, {"namespace"});
    static const ts::TypeSet typeIdentifier(SyntaxTree::Grammar::Cpp, {"type_identifier"});
    const Fields &f = fields();
    switch (kinds.index(n)) {
    case Declaration:
        onDeclaration(n);
        return true;
    case Assignment:
        onAssignment(n);
        return true;
    case Call:
        onCall(n);
        return true;
    case New:
        onNew(n);
        return true;
    case Return: {
        const auto value = arguments(n);
        if (value.size() == 1 && identifier.contains(unwrap(m_tree, value.front())))
            m_returned.append(m_tree.text(unwrap(m_tree, value.front())));
        return true;
    }
    case Alias:
        m_function.aliases.insert(m_tree.text(ts::field(n, f.name)),
                                  simplified(m_tree, ts::field(n, f.type)));
        return false;
    case Using: {
        // `using std_msgs::msg::Int32;` inside a function body
        const auto kids = arguments(n);
        const QString target = kids.empty() ? QString() : simplified(m_tree, kids.back());
        const QString last = lastSegment(target);
        bool isNamespace = false;
        for (TSNode c : ts::children(n))
            isNamespace = isNamespace || namespaceKeyword.contains(c);
        if (!isNamespace && !last.isEmpty() && last != target)
            m_function.aliases.insert(last, target);
        return false;
    }
    case TypeDefinition: {
        const TSNode type = ts::field(n, f.type);
        for (TSNode c : ts::namedChildren(n))
            if (typeIdentifier.contains(c) && !ts_node_eq(c, type))
                m_function.aliases.insert(m_tree.text(c), simplified(m_tree, type));
        return false;
    }
    case Class:
    case Struct:
        return false; // local classes are not followed
    case RangeFor: {
        // `for (const auto & name : names_)`: the variable stands for each element in turn
        const QString name = m_tree.text(declaredName(ts::field(n, f.declarator)));
        CppLocal local;
        local.type = simplified(m_tree, ts::field(n, f.type));
        local.value = ts::field(n, f.right);
        local.element = true;
        if (!name.isEmpty())
            m_locals.insert(name, local);
        return true;
    }
    default:
        return true;
    }
}

// `for (std::size_t i = 0; ...)`: whether a for statement is among the three nearest ancestors
// of `value`, the nearest of which are `near` (innermost first), and above them the walk's path.
bool CppFunctionExtractor::inLoopHead(TSNode value, std::initializer_list<TSNode> near) const
{
    static const ts::TypeSet forStatement(SyntaxTree::Grammar::Cpp, {"for_statement"});
    if (ts::isNull(value))
        return false;
    // ts_node_parent finds a parent by byte ranges: for an empty node (a MISSING one) that can
    // be a token before it rather than the node holding it. Climb as CppLocal::setValue does.
    if (ts_node_start_byte(value) == ts_node_end_byte(value)) {
        CppLocal probe;
        probe.setValue(value);
        return probe.loopInitial;
    }
    int up = 0;
    TSNode last = value;
    for (TSNode a : near) {
        if (up == 3)
            return false;
        if (forStatement.contains(a))
            return true;
        ++up;
        last = a;
    }
    for (auto it = m_path.crbegin(); it != m_path.crend() && up < 3; ++it, ++up) {
        if (forStatement.contains(*it))
            return true;
        last = *it;
    }
    for (TSNode p = ts_node_parent(last); up < 3 && !ts::isNull(p); ++up, p = ts_node_parent(p))
        if (forStatement.contains(p))
            return true;
    return false;
}

void CppFunctionExtractor::onDeclaration(TSNode declaration)
{
    const QString type = simplified(m_tree, ts::field(declaration, fields().type));
    for (TSNode d : ts::fieldChildren(declaration, fields().declarator)) {
        if (ts::is(d, "init_declarator")) {
            const QString name = m_tree.text(declaredName(ts::field(d, fields().declarator)));
            const TSNode value = ts::field(d, fields().value);
            CppLocal local;
            local.type = type;
            if (ts::is(value, "argument_list") || ts::is(value, "initializer_list")) {
                const auto args = arguments(value);
                bool lifecycle = false;
                if (isProceduralNodeType(type, &lifecycle)) {
                    if (!m_member) { // `rclcpp::Node node("name");` in a free function
                        CppProceduralNode node;
                        node.variable = name;
                        node.lifecycle = lifecycle;
                        if (!args.empty())
                            node.nodeName = m_values.evaluate(args.front());
                        node.evidence = m_tree.evidence(declaration);
                        m_function.proceduralNodes.append(node);
                    }
                } else {
                    addInstantiation(type, args, declaration);
                }
                if (args.size() == 1 && !ts::is(args.front(), "initializer_pair"))
                    // std::string topic("chatter");
                    local.setValue(args.front(), inLoopHead(args.front(), {value, d, declaration}));
                else if (ts::is(value, "initializer_list")) // zones{"dock", "gate"}, s{.a = x}
                    local.setValue(value, inLoopHead(value, {d, declaration}));
            } else {
                local.setValue(value, inLoopHead(value, {d, declaration}));
            }
            if (!name.isEmpty())
                m_locals.insert(name, local);
        } else if (ts::is(d, "function_declarator")) {
            // `image_transport::ImageTransport it(shared_from_this());` parses as a function
            // declaration inside a body; treat it as a local constructed from its arguments.
            const QString name = m_tree.text(declaredName(ts::field(d, fields().declarator)));
            if (name.isEmpty())
                continue;
            CppLocal local;
            local.type = type;
            m_locals.insert(name, local);
            std::vector<TSNode> args;
            for (TSNode p : arguments(ts::field(d, fields().parameters)))
                args.push_back(p);
            addInstantiation(type, args, declaration);
        } else {
            const QString name = m_tree.text(declaredName(d));
            if (!name.isEmpty()) {
                CppLocal local;
                local.type = type;
                m_locals.insert(name, local);
            }
        }
    }
}

void CppFunctionExtractor::onAssignment(TSNode assignment)
{
    const TSNode left = ts::field(assignment, fields().left);
    const TSNode right = ts::field(assignment, fields().right);
    const TSNode op = ts::field(assignment, fields().op);
    const bool plain = ts::isNull(op) || m_tree.view(op) == "=";
    const TSNode value = plain ? right : assignment;
    if (ts::is(left, "identifier")) {
        const QString name = m_tree.text(left);
        auto it = m_locals.find(name);
        if (it != m_locals.end()) {
            if (plain && joinsItself(value, name)) { // the value so far, joined
                it->parentJoined = true;
                return;
            }
            it->setValue(value, plain ? inLoopHead(value, {assignment}) : inLoopHead(value, {}));
            return;
        }
        if (const qsizetype at = m_function.parameterNames.indexOf(name); at >= 0) {
            // `std::string & topic` filled for the caller (`topic = declare_parameter(...)`)
            const QString type = m_function.parameterTypes.value(at);
            if (plain && type.contains(u'&') && !type.contains(QLatin1String("const")))
                m_function.outBindings.append({name, m_values.evaluate(value)});
            return;
        }
        if (m_member)
            addMemberBinding(name, value, plain && joinsItself(value, name));
    } else if (ts::is(left, "field_expression") &&
               ts::is(ts::field(left, fields().argument), "this")) {
        m_function.memberBindings.append(
            {m_tree.text(ts::field(left, fields().field)), m_values.evaluate(value)});
    } else if (ts::is(left, "field_expression")) {
        // `settings.topic = "scan";` on a struct local: what the local then holds
        const TSNode object = ts::field(left, fields().argument);
        if (plain && ts::is(object, "identifier") &&
            m_tree.view(ts::field(left, fields().op)) == ".") {
            auto it = m_locals.find(m_tree.text(object));
            if (it != m_locals.end() && ts::isNull(it->value)) {
                const QString field = m_tree.text(ts::field(left, fields().field));
                it->fields.removeIf([&](const auto &f) { return f.first == field; });
                constexpr qsizetype kMaxFields = 64;
                if (it->fields.size() < kMaxFields)
                    it->fields.append({field, value});
            }
        }
        addFieldBinding(left, m_values.evaluate(value));
    }
}

// `params_.topic = declare_parameter(...)`. Only parameter reads are kept: a literal stored
// into a field is as often a message filled in a test as a setting.
void CppFunctionExtractor::addFieldBinding(TSNode target, const CppValue &value)
{
    if (value.kind != CppValue::Kind::Parameter)
        return;
    const CppValue field = m_values.evaluate(target);
    if (field.kind == CppValue::Kind::Field)
        m_function.fieldBindings.append({field, value});
}

void CppFunctionExtractor::onNew(TSNode expression)
{
    const QString type = simplified(m_tree, ts::field(expression, fields().type));
    const auto args = arguments(ts::field(expression, fields().arguments));
    bool lifecycle = false;
    if (isProceduralNodeType(type, &lifecycle)) {
        addProceduralNode(expression, args, lifecycle);
        return;
    }
    addInstantiation(type, args, expression);
}

// `topic = joinWithParentNamespace(topic)`: a name joined to the parent namespace in place.
bool CppFunctionExtractor::joinsItself(TSNode value, const QString &name) const
{
    if (!ts::is(value, "call_expression"))
        return false;
    const CallShape shape = callShape(m_tree, ts::field(value, fields().function));
    const auto args = arguments(ts::field(value, fields().arguments));
    return shape.name == QLatin1String(kJoinWithParentNamespace) && args.size() == 1 &&
           ts::is(args.front(), "identifier") && m_tree.text(args.front()) == name;
}

// A member's value in this function. A join of the member to the parent namespace replaces the
// value this function gave it before; joined to a value given elsewhere, it is not decided.
void CppFunctionExtractor::addMemberBinding(const QString &name, TSNode value, bool joinsItself)
{
    if (!joinsItself) {
        m_function.memberBindings.append({name, m_values.evaluate(value)});
        return;
    }
    auto &bindings = m_function.memberBindings;
    for (auto it = bindings.end(); it != bindings.begin();) {
        --it;
        if (it->member == name) {
            it->value = joinedWithParentNamespace(it->value);
            return;
        }
    }
    CppValue undecided;
    undecided.kind = CppValue::Kind::Expression;
    undecided.text = m_tree.text(value);
    bindings.append({name, undecided});
}

} // namespace rosarch
