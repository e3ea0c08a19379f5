#include "nodes/python/pythonparameterreader.h"

#include "nodes/python/pythonresolver.h"
#include "syntax/pythonsyntax.h"

namespace rosarch {

PythonParameterReader::PythonParameterReader(const SyntaxTree &tree) : m_tree(tree) {}

QList<ParameterDeclaration> PythonParameterReader::read(TSNode scope) const
{
    QList<ParameterDeclaration> out;
    static const ts::TypeSet call(SyntaxTree::Grammar::Python, {"call"});
    py::walk(scope, [&](TSNode n) {
        if (!call.contains(n))
            return true;
        const std::string_view callee = py::calleeName(m_tree, n);
        if (callee == "declare_parameter") {
            add(n, nameText(py::argument(m_tree, n, 0, "name")),
                py::argument(m_tree, n, 1, "value"), py::argument(m_tree, n, 2, "descriptor"),
                &out);
        } else if (callee == "declare_parameters") {
            QString ns;
            PythonResolver::stringLiteral(m_tree, py::argument(m_tree, n, 0, "namespace"), &ns);
            for (TSNode item : ts::namedChildren(py::argument(m_tree, n, 1, "parameters"))) {
                if (!ts::is(item, "tuple"))
                    continue;
                const auto parts = ts::namedChildren(item);
                if (parts.empty())
                    continue;
                const QString name = nameText(parts.front());
                add(n, ns.isEmpty() ? name : ns + QLatin1Char('.') + name,
                    parts.size() > 1 ? parts[1] : TSNode{}, parts.size() > 2 ? parts[2] : TSNode{},
                    &out);
            }
        }
        return true;
    });
    return out;
}

bool PythonParameterReader::acceptsUndeclared(TSNode scope) const
{
    bool accepts = false;
    static const ts::TypeSet keyword(SyntaxTree::Grammar::Python, {"keyword_argument"});
    py::walk(scope, [&](TSNode n) {
        if (accepts || !keyword.contains(n))
            return !accepts;
        const QString name = m_tree.text(ts::field(n, "name"));
        if ((name == QLatin1String("allow_undeclared_parameters") ||
             name == QLatin1String("automatically_declare_parameters_from_overrides")) &&
            m_tree.text(ts::field(n, "value")) == QLatin1String("True"))
            accepts = true;
        return false;
    });
    return accepts;
}

QString PythonParameterReader::nameText(TSNode name) const
{
    if (ts::isNull(name))
        return {};
    QString literal;
    if (PythonResolver::stringLiteral(m_tree, name, &literal))
        return literal;
    return QStringLiteral("{%1}").arg(m_tree.text(name));
}

void PythonParameterReader::add(TSNode call, const QString &name, TSNode value, TSNode descriptor,
                                QList<ParameterDeclaration> *out) const
{
    if (name.isEmpty())
        return;
    ParameterDeclaration p;
    p.name = name;
    p.via = QStringLiteral("declare_parameter");
    p.evidence = m_tree.evidence(call);
    for (TSNode up = ts_node_parent(call); !ts::isNull(up); up = ts_node_parent(up)) {
        if (ts::is(up, "function_definition") || ts::is(up, "class_definition"))
            break;
        if (ts::is(up, "try_statement") || ts::is(up, "if_statement")) {
            p.guard = QStringLiteral("%1").arg(ts::is(up, "try_statement") ? "try" : "if");
            break;
        }
    }
    bool typeOnly = false;
    p.type = typeOf(value, &typeOnly);
    p.hasDefault = !ts::isNull(value) && !typeOnly && !ts::is(value, "none");
    if (p.hasDefault) {
        QString literal;
        p.defaultValue = PythonResolver::stringLiteral(m_tree, value, &literal)
                             ? literal
                             : m_tree.text(value).simplified();
        // a list reads as ROS 2 lists it, as C++ defaults do: [a, b], no quotes on its items
        if (ts::is(value, "list")) {
            QStringList items;
            for (uint32_t i = 0; i < ts_node_named_child_count(value); ++i) {
                const TSNode item = ts_node_named_child(value, i);
                if (ts::is(item, "comment"))
                    continue;
                items << (PythonResolver::stringLiteral(m_tree, item, &literal)
                              ? literal
                              : m_tree.text(item).simplified());
            }
            p.defaultValue = QLatin1Char('[') + items.join(QStringLiteral(", ")) + QLatin1Char(']');
        }
    }
    if (ts::is(descriptor, "call")) {
        QString description;
        if (PythonResolver::stringLiteral(m_tree, py::keyword(m_tree, descriptor, "description"),
                                          &description))
            p.description = description;
        p.readOnly =
            m_tree.text(py::keyword(m_tree, descriptor, "read_only")) == QLatin1String("True");
        p.dynamicTyping =
            m_tree.text(py::keyword(m_tree, descriptor, "dynamic_typing")) == QLatin1String("True");
        for (const char *kind : {"floating_point_range", "integer_range"}) {
            const TSNode ranges = py::keyword(m_tree, descriptor, kind);
            const auto items = ts::namedChildren(ranges);
            if (items.empty() || !ts::is(items.front(), "call"))
                continue;
            const TSNode r = items.front();
            const QString from = m_tree.text(py::argument(m_tree, r, 0, "from_value"));
            const QString to = m_tree.text(py::argument(m_tree, r, 1, "to_value"));
            if (from.isEmpty() || to.isEmpty())
                continue;
            p.range = QStringLiteral("[%1, %2]").arg(from, to);
            const QString step = m_tree.text(py::argument(m_tree, r, 2, "step"));
            if (!step.isEmpty() && step != QLatin1String("0") && step != QLatin1String("0.0"))
                p.range += QStringLiteral(" step ") + step;
        }
    }
    out->append(p);
}

QString PythonParameterReader::typeOf(TSNode value, bool *typeOnly) const
{
    if (ts::isNull(value))
        return {};
    const std::string_view t = ts::type(value);
    if (t == "string" || t == "concatenated_string")
        return QStringLiteral("string");
    if (t == "integer")
        return QStringLiteral("integer");
    if (t == "float")
        return QStringLiteral("double");
    if (t == "true" || t == "false")
        return QStringLiteral("bool");
    if (t == "unary_operator")
        return typeOf(ts::field(value, "argument"), typeOnly);
    if (t == "list" || t == "tuple") {
        const auto items = ts::namedChildren(value);
        if (items.empty())
            return {};
        bool ignored = false;
        const QString element = typeOf(items.front(), &ignored);
        return element.isEmpty() ? QString() : element + QStringLiteral("_array");
    }
    if (t == "attribute") {
        // Parameter.Type.DOUBLE, ParameterType.PARAMETER_DOUBLE: a type and no value
        const QString text = m_tree.text(value);
        const QString last = text.section(QLatin1Char('.'), -1);
        QString type = parameterTypeOfWritten(QStringLiteral("PARAMETER_") +
                                              QString(last).remove(QStringLiteral("PARAMETER_")));
        if (!type.isEmpty() &&
            (text.contains(QLatin1String("Type.")) || text.contains(QLatin1String("PARAMETER_")))) {
            *typeOnly = true;
            return type;
        }
    }
    return {};
}

} // namespace rosarch
