#include "nodes/cpp/cppfileextractor.h"

#include "nodes/cpp/cppfunctionextractor.h"
#include "syntax/cpperrorrecovery.h"
#include "syntax/cpppreprocessor.h"
#include "syntax/cppsyntax.h"

namespace rosarch {

using namespace cppsyntax;

namespace {

struct Scope
{
    QStringList namespaces;
    QStringList path; ///< namespaces and enclosing classes
    int classIndex = -1;
    QString className;
    QStringList templateParameters;
};

QStringList templateParameterNames(const SyntaxTree &tree, TSNode list)
{
    QStringList names;
    for (TSNode p : ts::namedChildren(list)) {
        TSNode name = ts::field(p, fields().name);
        if (ts::isNull(name)) {
            if (ts::is(p, "parameter_declaration") || ts::is(p, "optional_parameter_declaration"))
                name = declaredName(ts::field(p, fields().declarator));
            else
                for (TSNode c : ts::namedChildren(p))
                    if (ts::is(c, "type_identifier") || ts::is(c, "identifier"))
                        name = c;
        }
        if (!ts::isNull(name))
            names.append(tree.text(name));
    }
    return names;
}

class Walker
{
public:
    Walker(const SyntaxTree &tree, CppFileFacts &facts, const CppMacros &macros)
        : m_tree(tree), m_facts(facts), m_macros(macros)
    {
        // Each of the four texts starts with "using ": one scan for that instead of four.
        const std::string_view src(tree.source().constData(), size_t(tree.source().size()));
        for (size_t at = src.find("using "); at != std::string_view::npos;
             at = src.find("using ", at + 1)) {
            const std::string_view rest = src.substr(at);
            m_rclcppNode = m_rclcppNode || rest.starts_with("using rclcpp::Node;") ||
                           rest.starts_with("using namespace rclcpp;");
            m_lifecycleNode = m_lifecycleNode ||
                              rest.starts_with("using rclcpp_lifecycle::LifecycleNode;") ||
                              rest.starts_with("using namespace rclcpp_lifecycle;");
        }
    }

    void visitScope(TSNode n, const Scope &scope)
    {
        for (TSNode child : ts::namedChildren(n))
            visitDeclaration(child, scope, {});
    }

    void visitDeclaration(TSNode n, const Scope &scope, const QStringList &templateParameters)
    {
        const auto t = ts::type(n);
        if (t == "namespace_definition") {
            Scope inner = scope;
            const QStringList parts = splitScope(simplified(m_tree, ts::field(n, fields().name)));
            inner.namespaces += parts;
            inner.path += parts;
            visitScope(ts::field(n, fields().body), inner);
        } else if (t == "template_declaration") {
            const QStringList params =
                templateParameterNames(m_tree, ts::field(n, fields().parameters));
            for (TSNode child : ts::namedChildren(n))
                if (!ts::is(child, "template_parameter_list"))
                    visitDeclaration(child, scope, params);
        } else if (t == "class_specifier" || t == "struct_specifier") {
            addClass(n, scope, templateParameters);
        } else if (t == "function_definition") {
            // A class the parser closed early can end up as the return type of what follows.
            const TSNode type = ts::field(n, fields().type);
            if (ts::is(type, "class_specifier") || ts::is(type, "struct_specifier"))
                addClass(type, scope, templateParameters);
            addFunction(n, scope, templateParameters);
        } else if (t == "alias_declaration") {
            addAlias(scope, m_tree.text(ts::field(n, fields().name)),
                     simplified(m_tree, ts::field(n, fields().type)));
        } else if (t == "type_definition") {
            const QString type = simplified(m_tree, ts::field(n, fields().type));
            for (TSNode c : ts::namedChildren(n)) {
                if (ts::is(c, "type_identifier") && !ts_node_eq(c, ts::field(n, fields().type)))
                    addAlias(scope, m_tree.text(c), type);
            }
        } else if (t == "using_declaration") {
            addUsing(n, scope);
        } else if (t == "field_declaration") {
            addField(n, scope);
        } else if (t == "declaration") {
            const TSNode type = ts::field(n, fields().type);
            if (ts::is(type, "class_specifier") || ts::is(type, "struct_specifier"))
                addClass(type, scope, templateParameters);
            else if (scope.classIndex < 0)
                addConstant(n);
            else
                addDeclaredDefaults(n, scope);
        } else if (t == "linkage_specification") {
            visitScope(ts::field(n, fields().body), scope);
        } else if (t == "preproc_if" || t == "preproc_ifdef" || t == "preproc_else" ||
                   t == "preproc_elif" || t == "preproc_elifdef" || t == "declaration_list" ||
                   t == "ERROR") {
            visitScope(n, scope);
        }
    }

private:
    void addClass(TSNode n, const Scope &scope, const QStringList &templateParameters)
    {
        const TSNode body = ts::field(n, fields().body);
        const TSNode nameNode = ts::field(n, fields().name);
        if (ts::isNull(body) || ts::isNull(nameNode))
            return;
        QStringList written = splitScope(withoutTemplateArguments(simplified(m_tree, nameNode)));
        if (written.isEmpty())
            return;
        CppClass c;
        c.name = written.takeLast();
        c.scope = scope.path + written;
        c.qualifiedName = (c.scope + QStringList{c.name}).join(QStringLiteral("::"));
        c.templateParameters = scope.templateParameters + templateParameters;
        c.evidence = m_tree.evidence(n);
        for (TSNode child : ts::namedChildren(n)) {
            if (!ts::is(child, "base_class_clause"))
                continue;
            for (TSNode base : ts::namedChildren(child)) {
                if (ts::is(base, "access_specifier") || ts::is(base, "comment"))
                    continue;
                QString text = simplified(m_tree, base);
                if (text.startsWith(QLatin1String("virtual ")))
                    text = text.mid(8);
                c.bases.append(text);
            }
        }
        const int index = int(m_facts.classes.size());
        m_facts.classes.append(c);
        Scope inner = scope;
        inner.path = c.scope + QStringList{c.name};
        inner.classIndex = index;
        inner.className = c.name;
        inner.templateParameters = c.templateParameters;
        visitScope(body, inner);
    }

    void addFunction(TSNode n, const Scope &scope, const QStringList &templateParameters)
    {
        CppFunctionExtractor::Context context;
        context.ownerClass = scope.classIndex;
        context.className = scope.className;
        context.namespaces = scope.namespaces;
        context.templateParameters = scope.templateParameters;
        if (scope.classIndex >= 0)
            context.classAliases = m_facts.classes.at(scope.classIndex).aliases;
        context.rclcppNodeInScope = m_rclcppNode;
        context.lifecycleNodeInScope = m_lifecycleNode;
        context.macros = &m_macros;
        CppFunctionExtractor extractor(m_tree, context);
        m_facts.functions.append(extractor.extract(n, templateParameters));
    }

    void addAlias(const Scope &scope, const QString &name, const QString &type)
    {
        if (name.isEmpty() || type.isEmpty())
            return;
        if (scope.classIndex >= 0)
            m_facts.classes[scope.classIndex].aliases.insert(name, type);
        else if (!m_facts.aliases.contains(name))
            m_facts.aliases.insert(name, type);
    }

    void addUsing(TSNode n, const Scope &scope)
    {
        bool isNamespace = false;
        for (TSNode c : ts::children(n))
            if (ts::is(c, "namespace"))
                isNamespace = true;
        TSNode target{};
        for (TSNode c : ts::namedChildren(n))
            if (!ts::is(c, "comment"))
                target = c;
        const QString name = simplified(m_tree, target);
        if (name.isEmpty())
            return;
        if (isNamespace) {
            if (!m_facts.usingNamespaces.contains(name))
                m_facts.usingNamespaces.append(name);
            return;
        }
        const QString last = lastSegment(name);
        if (!last.isEmpty() && last != name)
            addAlias(scope, last, name);
    }

    // A member: its type (helpers are found by it) and its in-class initializer.
    // `Relay(const std::string & in, const std::string & name = "relay");` in a class body: the
    // literal defaults, which the definition elsewhere does not repeat.
    void addDeclaredDefaults(TSNode n, const Scope &scope)
    {
        const TSNode declarator = ts::field(n, fields().declarator);
        if (!ts::is(declarator, "function_declarator"))
            return;
        QStringList defaults;
        bool any = false;
        for (TSNode p : ts::namedChildren(ts::field(declarator, fields().parameters))) {
            if (ts::is(p, "comment"))
                continue;
            QString value;
            any = stringLiteral(m_tree, ts::field(p, fields().defaultValue), &value) || any;
            defaults.append(value);
        }
        const QString name = m_tree.text(ts::field(declarator, fields().declarator));
        if (any && !name.isEmpty())
            m_facts.classes[scope.classIndex].declaredDefaults.insert(name, defaults);
    }

    void addField(TSNode n, const Scope &scope)
    {
        const TSNode type = ts::field(n, fields().type);
        if (ts::is(type, "class_specifier") || ts::is(type, "struct_specifier"))
            addClass(type, scope, {});
        if (scope.classIndex < 0)
            return;
        CppClass &c = m_facts.classes[scope.classIndex];
        const QString typeText = simplified(m_tree, type);
        for (TSNode child : ts::namedChildren(n)) {
            if (ts::is(child, "function_declarator"))
                return; // a method declaration
        }
        // `image_transport::SubscriberFilter depth_, intensity_;`: every name is of the type.
        const std::vector<TSNode> declarators = ts::fieldChildren(n, fields().declarator);
        for (TSNode more : declarators)
            if (const QString other = m_tree.text(declaredName(more)); !other.isEmpty())
                c.memberTypes.insert(other, typeText);
        const TSNode declarator = ts::field(n, fields().declarator);
        const QString name = m_tree.text(declaredName(declarator));
        if (name.isEmpty() || declarators.size() > 1)
            return; // a default value belongs to one of several names: not read
        c.memberTypes.insert(name, typeText);
        TSNode value = ts::field(n, fields().defaultValue);
        if (ts::isNull(value))
            return;
        if (ts::is(value, "initializer_list")) {
            const auto items = arguments(value);
            addMemberInstantiation(c, name, typeText, items, n);
            if (items.size() != 1)
                return;
            value = items.front();
        }
        c.memberInitializers.append({name, valueOf(value)});
    }

    // `Helper<T> member_{this, "name"};`: the helper is built with the node in the class body.
    void addMemberInstantiation(CppClass &c, const QString &member, const QString &type,
                                const std::vector<TSNode> &items, TSNode where) const
    {
        bool handsNode = false;
        QList<CppValue> arguments;
        for (TSNode item : items) {
            CppValue v = valueOf(item);
            if (ts::is(unwrap(m_tree, item), "this")) {
                v.kind = CppValue::Kind::SelfNode;
                handsNode = true;
            }
            arguments.append(v);
        }
        if (!handsNode)
            return;
        CppInstantiation inst;
        inst.className = type;
        inst.member = member;
        inst.arguments = arguments;
        inst.evidence = m_tree.evidence(where);
        c.memberInstantiations.append(inst);
    }

    // `const std::string kTopic = "x";` at namespace scope.
    void addConstant(TSNode n)
    {
        for (TSNode d : ts::namedChildren(n)) {
            if (!ts::is(d, "init_declarator"))
                continue;
            QString literal;
            TSNode value = ts::field(d, fields().value);
            if (ts::is(value, "initializer_list") || ts::is(value, "argument_list")) {
                const auto items = arguments(value);
                value = items.size() == 1 ? items.front() : TSNode{};
            }
            if (ts::isNull(value) || !stringLiteral(m_tree, unwrap(m_tree, value), &literal))
                continue;
            const QString name = m_tree.text(declaredName(ts::field(d, fields().declarator)));
            if (!name.isEmpty() && !m_facts.constants.contains(name))
                m_facts.constants.insert(name, literal);
        }
    }

    CppValue valueOf(TSNode value) const
    {
        CppValue v;
        v.text = simplified(m_tree, value);
        const TSNode n = unwrap(m_tree, value);
        QString literal;
        if (stringLiteral(m_tree, n, &literal)) {
            v.kind = CppValue::Kind::Literal;
            v.literal = literal;
        } else if (ts::is(n, "true") || ts::is(n, "false") || ts::is(n, "number_literal")) {
            v.kind = CppValue::Kind::Literal;
            v.literal = m_tree.text(n);
        } else if (ts::is(n, "identifier")) {
            v.kind = CppValue::Kind::Member;
            v.variable = m_tree.text(n);
        } else {
            v.kind = CppValue::Kind::Expression;
        }
        return v;
    }

    const SyntaxTree &m_tree;
    CppFileFacts &m_facts;
    const CppMacros &m_macros;
    bool m_rclcppNode = false;
    bool m_lifecycleNode = false;
};

QList<Diagnostic> syntaxErrors(const SyntaxTree &tree)
{
    const TSNode root = tree.root();
    if (ts::isNull(root) || !ts_node_has_error(root))
        return tree.syntaxErrors(1);
    const std::vector<TSNode> errors = CppErrorRecovery::realErrors(tree);
    if (errors.empty())
        return {};
    const TSNode first = errors.front();
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("syntax-error");
    d.evidence = tree.evidence(first);
    d.message = ts_node_is_missing(first)
                    ? QStringLiteral("Syntax error in %1 at line %2: missing %3; the rest of the "
                                     "file is still analysed.")
                          .arg(tree.file())
                          .arg(d.evidence.line)
                          .arg(QString::fromUtf8(ts_node_type(first)))
                    : QStringLiteral(
                          "Syntax error in %1 at line %2; the rest of the file is still analysed.")
                          .arg(tree.file())
                          .arg(d.evidence.line);
    return {d};
}

int lineOf(const QByteArray &source, qsizetype offset, int *column)
{
    int line = 1;
    qsizetype lineStart = 0;
    for (qsizetype i = 0; i < offset && i < source.size(); ++i) {
        if (source.at(i) == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    *column = int(offset - lineStart) + 1;
    return line;
}

// Calls of `macro(...)` found in the text, so that a macro the parser could not place still
// counts; comments and macro definitions are skipped. Calls back with the arguments (spaces
// removed) and where the call is.
template <typename F>
void scanMacroCalls(const SyntaxTree &tree, const QByteArray &macro, const QString &path, F found)
{
    const QByteArray &src = tree.source();
    qsizetype from = 0;
    while (true) {
        const qsizetype at = src.indexOf(macro, from);
        if (at < 0)
            break;
        from = at + macro.size();
        if (at > 0 && (std::isalnum(uchar(src.at(at - 1))) || src.at(at - 1) == '_'))
            continue;
        const TSNode here =
            ts_node_descendant_for_byte_range(tree.root(), uint32_t(at), uint32_t(from));
        if (ts::is(here, "comment") || ts::is(here, "string_content") ||
            !ts::isNull(ts::ancestor(here, {"preproc_def", "preproc_function_def", "comment"})))
            continue;
        qsizetype i = from;
        while (i < src.size() && std::isspace(uchar(src.at(i))))
            ++i;
        if (i >= src.size() || src.at(i) != '(')
            continue;
        const qsizetype close = src.indexOf(')', i);
        if (close < 0)
            continue;
        const QString inside = QString::fromUtf8(src.mid(i + 1, close - i - 1)).simplified();
        QStringList arguments = inside.split(u',');
        for (QString &a : arguments)
            a.remove(u' ');
        if (inside.isEmpty() || arguments.first().isEmpty())
            continue;
        Evidence evidence;
        evidence.file = path;
        evidence.line = lineOf(src, at, &evidence.column);
        evidence.endLine = lineOf(src, close + 1, &evidence.endColumn);
        found(arguments, evidence);
    }
}

// RCLCPP_COMPONENTS_REGISTER_NODE(ns::Class) and PLUGINLIB_EXPORT_CLASS(ns::Class, base::Iface).
void findRegistrations(const SyntaxTree &tree, CppFileFacts &facts)
{
    scanMacroCalls(tree, QByteArrayLiteral("RCLCPP_COMPONENTS_REGISTER_NODE"), facts.path,
                   [&](const QStringList &arguments, const Evidence &evidence) {
                       ComponentRegistration r;
                       r.file = facts.path;
                       r.pluginClass = arguments.join(QLatin1String(","));
                       r.evidence = evidence;
                       facts.registrations.append(r);
                   });
    scanMacroCalls(tree, QByteArrayLiteral("PLUGINLIB_EXPORT_CLASS"), facts.path,
                   [&](const QStringList &arguments, const Evidence &evidence) {
                       CppPluginExport e;
                       e.className = arguments.value(0);
                       e.baseClass = arguments.value(1);
                       e.evidence = evidence;
                       facts.pluginExports.append(e);
                   });
}

// `#define TOPIC "scan"`, also through other macros (`#define TOPIC PREFIX "scan"`).
void addMacroConstants(const CppMacros &macros, CppFileFacts &facts)
{
    for (auto it = macros.cbegin(); it != macros.cend(); ++it) {
        if (it->functionLike)
            continue;
        const QString name = QString::fromUtf8(it.key());
        if (facts.constants.contains(name))
            continue;
        const QString value = CppPreprocessor::constantValue(it->body, macros);
        if (!value.isNull())
            facts.constants.insert(name, value);
    }
}

} // namespace

CppFileFacts CppFileExtractor::extract(const SyntaxTree &tree, const QString &package,
                                       const CppMacros &macros)
{
    CppFileFacts facts;
    facts.path = tree.file();
    facts.package = package;
    facts.isHeader = isHeaderPath(tree.file());
    facts.diagnostics = syntaxErrors(tree);
    const TSNode root = tree.root();
    if (ts::isNull(root))
        return facts;
    Walker walker(tree, facts, macros);
    walker.visitScope(root, Scope());
    if (tree.source().contains("RCLCPP_COMPONENTS_REGISTER_NODE") ||
        tree.source().contains("PLUGINLIB_EXPORT_CLASS"))
        findRegistrations(tree, facts);
    addMacroConstants(macros, facts);
    return facts;
}

} // namespace rosarch
