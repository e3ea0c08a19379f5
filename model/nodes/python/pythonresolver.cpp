#include "nodes/python/pythonresolver.h"

#include "syntax/pythonsyntax.h"

namespace rosarch {

namespace {
constexpr int kMaxDepth = 8;
constexpr uint32_t kModuleScope = 0xffffffffu;

bool isParameterAccessor(std::string_view name)
{
    return name == "value" || (name.size() > 6 && name.substr(name.size() - 6) == "_value");
}

bool isParameterGetter(std::string_view name)
{
    return name == "get_parameter" || name == "declare_parameter" || name == "get_parameter_or";
}

QString canonicalInterface(const QString &qualified)
{
    const QStringList segs = qualified.split(QLatin1Char('.'));
    for (qsizetype k = segs.size() - 2; k >= 1; --k) {
        const QString &s = segs.at(k);
        if (s == QLatin1String("msg") || s == QLatin1String("srv") || s == QLatin1String("action"))
            return segs.at(k - 1) + QLatin1Char('/') + s + QLatin1Char('/') + segs.last();
    }
    return {};
}
} // namespace

PythonResolver::PythonResolver(const SyntaxTree &tree, QString modulePath)
    : m_tree(tree), m_scopes(tree), m_modulePath(std::move(modulePath)),
      m_imports(tree, m_scopes, m_modulePath)
{
}

bool PythonResolver::stringLiteral(const SyntaxTree &tree, TSNode node, QString *value)
{
    if (ts::is(node, "parenthesized_expression") && ts_node_named_child_count(node) == 1)
        return stringLiteral(tree, ts_node_named_child(node, 0), value);
    if (ts::is(node, "concatenated_string")) {
        QString all;
        for (TSNode part : ts::namedChildren(node)) {
            QString v;
            if (!stringLiteral(tree, part, &v))
                return false;
            all += v;
        }
        *value = all;
        return true;
    }
    if (!ts::is(node, "string"))
        return false;
    QString content;
    for (TSNode c : ts::namedChildren(node)) {
        const std::string_view t = ts::type(c);
        if (t == "string_start") {
            const std::string_view prefix = tree.view(c);
            if (prefix.find_first_of("fFbB") != std::string_view::npos)
                return false;
        } else if (t == "string_content") {
            content += tree.text(c);
        } else if (t == "interpolation") {
            return false;
        }
    }
    *value = content;
    return true;
}

QString PythonResolver::qualify(const QString &dotted) const
{
    return m_imports.qualify(dotted);
}

QString PythonResolver::qualifiedName(TSNode expr) const
{
    if (!py::isDottedName(expr))
        return {};
    QString text = m_tree.text(expr);
    text.remove(QLatin1Char(' '));
    return qualify(text);
}

QString PythonResolver::interfaceType(TSNode expr) const
{
    return interfaceTypeAt(expr, 0);
}

QString PythonResolver::interfaceTypeAt(TSNode expr, int depth) const
{
    const QString written = m_tree.text(expr);
    if (!py::isDottedName(expr))
        return written;
    const QString canonical = canonicalInterface(qualifiedName(expr));
    if (!canonical.isEmpty())
        return canonical;
    if (depth < kMaxDepth && ts::is(expr, "identifier")) {
        // `msg_type = String` earlier in the function
        const QString &name = written;
        for (TSNode f = m_scopes.enclosingFunction(expr); !ts::isNull(f);
             f = m_scopes.enclosingFunction(f)) {
            const auto &index = locals(f);
            const auto it = index.constFind(name);
            if (it != index.constEnd() && !it->isEmpty() && !ts::isNull(it->last().right))
                return interfaceTypeAt(it->last().right, depth + 1);
        }
    }
    return written;
}

PythonValue PythonResolver::value(TSNode expr) const
{
    PythonValue v = valueAt(expr, 0);
    if (v.origin == NameOrigin::Expression)
        v.value = m_tree.text(expr);
    return v;
}

PythonValue PythonResolver::valueAt(TSNode expr, int depth) const
{
    PythonValue v;
    if (ts::isNull(expr) || depth > kMaxDepth)
        return v;
    QString literal;
    if (stringLiteral(m_tree, expr, &literal)) {
        v.origin = NameOrigin::Literal;
        v.value = literal;
        return v;
    }
    const std::string_view t = ts::type(expr);
    if (t == "parenthesized_expression" && ts_node_named_child_count(expr) == 1)
        return valueAt(ts_node_named_child(expr, 0), depth + 1);
    if (t == "identifier")
        return identifierValue(expr, depth);
    if (t == "attribute" || t == "call") {
        TSNode call = parameterCall(expr);
        if (!ts::isNull(call))
            return parameterValue(call, expr, depth);
        if (t == "attribute")
            return memberValue(expr, depth);
        if (py::calleeName(m_tree, expr) == "str" &&
            ts::is(ts::field(expr, "function"), "identifier"))
            return valueAt(py::positional(expr, 0), depth + 1);
    }
    return v;
}

PythonValue PythonResolver::identifierValue(TSNode expr, int depth) const
{
    const QString name = m_tree.text(expr);
    const uint32_t at = ts_node_start_byte(expr);
    auto fromAssignments = [&](const QList<Assignment> &list) {
        // the last assignment before the use, else the first one after it
        const Assignment *pick = nullptr;
        for (const Assignment &a : list)
            if (a.byte < at)
                pick = &a;
        if (!pick)
            pick = &list.first();
        PythonValue v = valueAt(pick->right, depth + 1);
        if (v.origin == NameOrigin::Literal)
            v.origin = NameOrigin::Local;
        return v;
    };
    for (TSNode f = m_scopes.enclosingFunction(expr); !ts::isNull(f);
         f = m_scopes.enclosingFunction(f)) {
        const auto &index = locals(f);
        const auto it = index.constFind(name);
        if (it != index.constEnd() && !it->isEmpty())
            return fromAssignments(*it);
        for (const py::Parameter &p : py::parameters(m_tree, f)) {
            if (p.name != name)
                continue;
            PythonValue v = valueAt(p.defaultValue, depth + 1);
            if (v.origin == NameOrigin::Literal)
                v.origin = NameOrigin::Local;
            return v;
        }
    }
    const auto &module = locals(TSNode{});
    const auto it = module.constFind(name);
    if (it != module.constEnd() && !it->isEmpty())
        return fromAssignments(*it);
    return {};
}

PythonValue PythonResolver::memberValue(TSNode expr, int depth) const
{
    if (m_tree.view(ts::field(expr, "object")) != "self")
        return {};
    TSNode cls = m_scopes.enclosingClass(expr);
    if (ts::isNull(cls))
        return {};
    const auto &index = members(cls);
    const auto it = index.constFind(m_tree.text(ts::field(expr, "attribute")));
    if (it == index.constEnd())
        return {};
    PythonValue fallback;
    for (const Assignment &a : *it) {
        PythonValue v = valueAt(a.right, depth + 1);
        if (v.origin == NameOrigin::Literal || v.origin == NameOrigin::Local)
            v.origin = NameOrigin::Member;
        if (v.origin != NameOrigin::Expression)
            return v;
        if (fallback.parameter.isEmpty())
            fallback = v;
    }
    return fallback;
}

TSNode PythonResolver::parameterCall(TSNode expr) const
{
    for (int guard = 0; guard < 6; ++guard) {
        if (ts::is(expr, "attribute")) {
            if (!isParameterAccessor(m_tree.view(ts::field(expr, "attribute"))))
                return TSNode{};
            expr = ts::field(expr, "object");
        } else if (ts::is(expr, "call")) {
            const std::string_view name = py::calleeName(m_tree, expr);
            if (isParameterGetter(name) && ts::is(ts::field(expr, "function"), "attribute"))
                return expr;
            if (name != "get_parameter_value")
                return TSNode{};
            expr = py::calleeObject(expr);
        } else {
            return TSNode{};
        }
    }
    return TSNode{};
}

PythonValue PythonResolver::parameterValue(TSNode call, TSNode whole, int depth) const
{
    PythonValue v;
    const PythonValue name = valueAt(py::argument(m_tree, call, 0, "name"), depth + 1);
    if (name.origin == NameOrigin::Expression)
        return v;
    v.parameter = name.value;
    bool found = false;
    TSNode defaultValue{};
    if (py::calleeName(m_tree, call) == "declare_parameter") {
        defaultValue = py::argument(m_tree, call, 1, "value");
        found = true;
    } else {
        defaultValue = declaredDefault(call, name.value, &found);
    }
    if (found && !ts::isNull(defaultValue)) {
        const PythonValue d = valueAt(defaultValue, depth + 1);
        if (d.origin != NameOrigin::Expression) {
            v.origin = NameOrigin::Parameter;
            v.value = d.value;
            return v;
        }
    }
    v.value = m_tree.text(whole);
    return v;
}

TSNode PythonResolver::declaredDefault(TSNode at, const QString &parameter, bool *found) const
{
    indexParameters();
    TSNode cls = m_scopes.enclosingClass(at);
    if (!ts::isNull(cls)) {
        const auto &map = m_classParameters[ts_node_start_byte(cls)];
        const auto it = map.constFind(parameter);
        if (it != map.constEnd()) {
            *found = true;
            return it.value();
        }
    }
    const auto it = m_fileParameters.constFind(parameter);
    *found = it != m_fileParameters.constEnd();
    return *found ? it.value() : TSNode{};
}

void PythonResolver::indexParameters() const
{
    if (m_parametersIndexed)
        return;
    m_parametersIndexed = true;
    auto record = [&](TSNode at, const QString &name, TSNode defaultValue) {
        TSNode cls = m_scopes.enclosingClass(at);
        if (!ts::isNull(cls)) {
            auto &map = m_classParameters[ts_node_start_byte(cls)];
            if (!map.contains(name))
                map.insert(name, defaultValue);
        }
        if (!m_fileParameters.contains(name))
            m_fileParameters.insert(name, defaultValue);
    };
    static const ts::TypeSet call(SyntaxTree::Grammar::Python, {"call"});
    py::walk(m_tree.root(), [&](TSNode n) {
        if (!call.contains(n))
            return true;
        const std::string_view callee = py::calleeName(m_tree, n);
        QString name;
        if (callee == "declare_parameter") {
            if (stringLiteral(m_tree, py::argument(m_tree, n, 0, "name"), &name))
                record(n, name, py::argument(m_tree, n, 1, "value"));
        } else if (callee == "declare_parameters") {
            QString ns;
            stringLiteral(m_tree, py::argument(m_tree, n, 0, "namespace"), &ns);
            TSNode list = py::argument(m_tree, n, 1, "parameters");
            for (TSNode item : ts::namedChildren(list)) {
                if (!ts::is(item, "tuple"))
                    continue;
                const auto parts = ts::namedChildren(item);
                if (parts.empty() || !stringLiteral(m_tree, parts.front(), &name))
                    continue;
                record(n, ns.isEmpty() ? name : ns + QLatin1Char('.') + name,
                       parts.size() > 1 ? parts[1] : TSNode{});
            }
        }
        return true;
    });
}

const PythonResolver::AssignmentIndex &PythonResolver::locals(TSNode scope) const
{
    const uint32_t key = ts::isNull(scope) ? kModuleScope : ts_node_start_byte(scope);
    auto it = m_locals.find(key);
    if (it != m_locals.end())
        return *it;
    AssignmentIndex &index = m_locals[key];
    TSNode body = ts::isNull(scope) ? m_tree.root() : ts::field(scope, "body");
    enum
    {
        Function,
        Class,
        Lambda,
        For,
        Assignment
    };
    static const ts::TypeSet kinds(
        SyntaxTree::Grammar::Python,
        {"function_definition", "class_definition", "lambda", "for_statement", "assignment"});
    py::walk(body, [&](TSNode n) {
        const int t = kinds.index(n);
        if (t == Function || t == Class || t == Lambda)
            return false;
        if (t == For) {
            TSNode left = ts::field(n, "left");
            if (ts::is(left, "identifier"))
                index[m_tree.text(left)].append({ts_node_start_byte(n), TSNode{}});
            return true;
        }
        if (t != Assignment)
            return true;
        TSNode right = ts::field(n, "right");
        while (ts::is(right, "assignment"))
            right = ts::field(right, "right");
        for (TSNode a = n; ts::is(a, "assignment"); a = ts::field(a, "right")) {
            TSNode left = ts::field(a, "left");
            if (ts::is(left, "identifier"))
                index[m_tree.text(left)].append({ts_node_start_byte(n), right});
        }
        return true;
    });
    return index;
}

const PythonResolver::AssignmentIndex &PythonResolver::members(TSNode classNode) const
{
    const uint32_t key = ts_node_start_byte(classNode);
    auto it = m_members.find(key);
    if (it != m_members.end())
        return *it;
    AssignmentIndex &index = m_members[key];
    TSNode body = ts::field(classNode, "body");
    static const ts::TypeSet kinds(SyntaxTree::Grammar::Python, {"class_definition", "assignment"});
    py::walk(body, [&](TSNode n) {
        const int t = kinds.index(n);
        if (t == 0)
            return false;
        if (t != 1)
            return true;
        TSNode right = ts::field(n, "right");
        while (ts::is(right, "assignment"))
            right = ts::field(right, "right");
        const bool classBody = ts::isNull(m_scopes.enclosingFunction(n));
        for (TSNode a = n; ts::is(a, "assignment"); a = ts::field(a, "right")) {
            TSNode left = ts::field(a, "left");
            if (classBody && ts::is(left, "identifier"))
                index[m_tree.text(left)].append({ts_node_start_byte(n), right});
            else if (ts::is(left, "attribute") && m_tree.view(ts::field(left, "object")) == "self")
                index[m_tree.text(ts::field(left, "attribute"))].append(
                    {ts_node_start_byte(n), right});
        }
        return true;
    });
    return index;
}

QStringList PythonResolver::loopItems(TSNode identifier) const
{
    if (!ts::is(identifier, "identifier"))
        return {};
    const QString name = m_tree.text(identifier);
    TSNode loop{};
    for (TSNode p = ts_node_parent(identifier); !ts::isNull(p); p = ts_node_parent(p)) {
        const std::string_view t = ts::type(p);
        if (t == "function_definition" || t == "class_definition" || t == "lambda")
            break;
        if (t == "for_statement" && m_tree.text(ts::field(p, "left")) == name) {
            loop = p;
            break;
        }
    }
    if (ts::isNull(loop))
        return {};
    TSNode list = ts::field(loop, "right");
    if (ts::is(list, "identifier")) { // `for zone in ZONES:`, the last assignment before
        const QString listName = m_tree.text(list);
        const uint32_t at = ts_node_start_byte(loop);
        const TSNode function = m_scopes.enclosingFunction(loop);
        TSNode assigned{};
        for (const TSNode scope : {function, TSNode{}}) {
            const auto &index = locals(scope);
            const auto it = index.constFind(listName);
            if (it == index.constEnd())
                continue;
            for (const Assignment &a : *it)
                if (a.byte < at || ts::isNull(scope))
                    assigned = a.right;
            if (!ts::isNull(assigned) || !ts::isNull(function))
                break;
        }
        list = assigned;
    }
    if (!ts::is(list, "list") && !ts::is(list, "tuple"))
        return {};
    QStringList items;
    constexpr qsizetype kMaxItems = 64;
    for (TSNode item : ts::namedChildren(list)) {
        QString literal;
        if (ts::is(item, "comment"))
            continue;
        if (!stringLiteral(m_tree, item, &literal) || items.size() >= kMaxItems)
            return {}; // not a list of names written out
        items.append(literal);
    }
    return items;
}

TSNode PythonResolver::assignedExpression(TSNode expr) const
{
    if (ts::is(expr, "identifier")) {
        const QString name = m_tree.text(expr);
        const uint32_t at = ts_node_start_byte(expr);
        for (TSNode f = m_scopes.enclosingFunction(expr); !ts::isNull(f);
             f = m_scopes.enclosingFunction(f)) {
            const auto &index = locals(f);
            const auto it = index.constFind(name);
            if (it == index.constEnd() || it->isEmpty())
                continue;
            TSNode pick{};
            for (const Assignment &a : *it)
                if (a.byte < at)
                    pick = a.right;
            return pick;
        }
        return TSNode{};
    }
    if (!ts::is(expr, "attribute") || m_tree.view(ts::field(expr, "object")) != "self")
        return TSNode{};
    TSNode cls = m_scopes.enclosingClass(expr);
    if (ts::isNull(cls))
        return TSNode{};
    const auto &index = members(cls);
    const auto it = index.constFind(m_tree.text(ts::field(expr, "attribute")));
    if (it == index.constEnd())
        return TSNode{};
    TSNode found{};
    for (const Assignment &a : *it) {
        if (ts::isNull(a.right) || ts::is(a.right, "none"))
            continue;
        if (!ts::isNull(found))
            return TSNode{};
        found = a.right;
    }
    return found;
}

QString PythonResolver::callbackName(TSNode expr) const
{
    for (int depth = 0; depth < 4 && !ts::isNull(expr); ++depth) {
        const std::string_view t = ts::type(expr);
        if (t == "lambda")
            return QStringLiteral("lambda");
        if (t == "attribute")
            return m_tree.text(ts::field(expr, "attribute"));
        if (t == "call") {
            const std::string_view callee = py::calleeName(m_tree, expr);
            if (callee != "partial")
                break;
            expr = py::positional(expr, 0);
            continue;
        }
        if (t == "identifier") {
            // a local holding a lambda or a bound method
            TSNode f = m_scopes.enclosingFunction(expr);
            if (!ts::isNull(f)) {
                const auto &index = locals(f);
                const auto it = index.constFind(m_tree.text(expr));
                if (it != index.constEnd() && it->size() == 1 && !ts::isNull(it->first().right)) {
                    const std::string_view rt = ts::type(it->first().right);
                    if (rt == "lambda" || rt == "attribute" || rt == "call") {
                        expr = it->first().right;
                        continue;
                    }
                }
            }
            return m_tree.text(expr);
        }
        break;
    }
    return m_tree.text(expr);
}

void PythonResolver::guard(TSNode node, QString *guard, QString *guardParameter,
                           QString *guardDefault) const
{
    QStringList conditions;
    QString parameter;
    auto testedParameter = [&](TSNode condition) {
        QString found;
        py::walk(condition, [&](TSNode n) {
            if (!found.isEmpty())
                return false;
            const std::string_view t = ts::type(n);
            if (t == "identifier" || t == "attribute" || t == "call") {
                const PythonValue v = valueAt(n, 0);
                if (!v.parameter.isEmpty()) {
                    found = v.parameter;
                    return false;
                }
            }
            return true;
        });
        return found;
    };
    auto add = [&](TSNode condition, bool negate) {
        const QString text = m_tree.text(condition);
        if (text.contains(QLatin1String("__name__")))
            return; // `if __name__ == '__main__':` is how scripts start, not a condition on ports
        conditions.prepend(negate ? QStringLiteral("not (%1)").arg(text) : text);
        if (parameter.isEmpty())
            parameter = testedParameter(condition);
    };
    // the statements between the enclosing function (or the module) and the node
    TSNode scope = m_scopes.enclosingFunction(node);
    const std::vector<TSNode> path =
        PythonScopeIndex::pathBetween(ts::isNull(scope) ? m_tree.root() : scope, node);
    // `if self.pub is None: self.pub = create_publisher(...)` creates the port lazily: the
    // condition says when, not whether
    QString lazyTarget;
    for (size_t i = path.size(); i-- > 0 && lazyTarget.isEmpty();) {
        const std::string_view t = ts::type(path[i]);
        if (t == "assignment")
            lazyTarget = m_tree.text(ts::field(path[i], "left")).remove(QLatin1Char(' '));
        else if (t == "block" || t == "function_definition")
            break;
    }
    auto isLazyCheck = [&](TSNode condition) {
        if (lazyTarget.isEmpty())
            return false;
        QString text = m_tree.text(condition);
        text.remove(QLatin1Char(' '));
        return text == lazyTarget + QLatin1String("isNone") ||
               text == QLatin1String("not") + lazyTarget;
    };
    for (size_t i = path.size() - 1; i-- > 0;) {
        const TSNode p = path[i];
        const TSNode child = path[i + 1];
        const std::string_view t = ts::type(p);
        if (t == "class_definition")
            break;
        if (t == "if_statement" || t == "elif_clause") {
            if (ts_node_eq(child, ts::field(p, "consequence")) &&
                !isLazyCheck(ts::field(p, "condition")))
                add(ts::field(p, "condition"), false);
        } else if (t == "else_clause" && i > 0 && ts::is(path[i - 1], "if_statement")) {
            add(ts::field(path[i - 1], "condition"), true);
        }
    }
    *guard = conditions.join(QStringLiteral(" and "));
    *guardParameter = parameter;
    guardDefault->clear();
    bool declared = false;
    if (!parameter.isEmpty())
        if (const TSNode d = declaredDefault(node, parameter, &declared); declared)
            *guardDefault = m_tree.text(d);
}

} // namespace rosarch
