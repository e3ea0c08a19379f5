#include "nodes/python/pythonmodulereader.h"

#include "core/port.h"
#include "core/rosnames.h"
#include "syntax/pythonsyntax.h"

// PythonModuleReader's reading of port names: a parameter that a name comes from, and names
// built from parts (f-strings, `.format`, `+`, `str()`).

namespace rosarch {

PythonParameterRef PythonModuleReader::parameterOf(TSNode identifier) const
{
    const PythonScopeIndex &scopes = m_resolver.scopes();
    TSNode f = scopes.enclosingFunction(identifier);
    if (ts::isNull(f))
        return {};
    // parameters of a top-level function or of a method; a nested function's are not passed in
    // from a call site that the linker sees
    const bool topLevel = scopes.isTopLevel(f);
    const bool method = !topLevel && ts::isNull(scopes.enclosingFunction(f)) &&
                        !ts::isNull(scopes.enclosingClass(f));
    if (!topLevel && !method)
        return {};
    const QString name = m_tree.text(identifier);
    const auto params = py::parameters(m_tree, f);
    const size_t skip = method ? 1 : 0;
    for (size_t i = skip; i < params.size(); ++i) {
        if (params[i].name != name)
            continue;
        const QString function = m_tree.text(ts::field(f, "name"));
        const bool init = !method || function == QLatin1String("__init__");
        return {int(i - skip), name, init ? QString() : function};
    }
    return {};
}

QString PythonModuleReader::ownNamePart(TSNode call) const
{
    if (m_tree.view(py::calleeObject(call)) != "self" || !ts::isNull(py::positional(call, 0)))
        return {};
    const std::string_view callee = py::calleeName(m_tree, call);
    if (callee == "get_name")
        return QLatin1String(kNodeNamePlaceholder);
    if (callee == "get_namespace")
        return QLatin1String(RosNames::kNamespacePlaceholder);
    if (callee == "get_fully_qualified_name")
        return QStringLiteral("%1/%2").arg(QLatin1String(RosNames::kNamespacePlaceholder),
                                           QLatin1String(kNodeNamePlaceholder));
    return {};
}

bool PythonModuleReader::nameParts(TSNode expr, int depth, QList<PythonNamePart> *parts) const
{
    if (ts::isNull(expr) || depth > 8)
        return false;
    QString literal;
    if (PythonResolver::stringLiteral(m_tree, expr, &literal)) {
        parts->append({literal, {}});
        return true;
    }
    const std::string_view t = ts::type(expr);
    if (t == "parenthesized_expression" && ts_node_named_child_count(expr) == 1)
        return nameParts(ts_node_named_child(expr, 0), depth + 1, parts);
    if (t == "string") { // an f-string
        for (TSNode c : ts::namedChildren(expr)) {
            const std::string_view ct = ts::type(c);
            if (ct == "string_start") {
                if (m_tree.view(c).find_first_of("bB") != std::string_view::npos)
                    return false;
            } else if (ct == "string_content") {
                parts->append({m_tree.text(c), {}});
            } else if (ct == "interpolation") {
                // a conversion or format spec (`{x!r}`, `{x:>4}`) changes the text
                if (ts_node_named_child_count(c) != 1 ||
                    !nameParts(ts::field(c, "expression"), depth + 1, parts))
                    return false;
            } else if (ct != "string_end") {
                return false;
            }
        }
        return true;
    }
    if (t == "concatenated_string") {
        for (TSNode c : ts::namedChildren(expr))
            if (!nameParts(c, depth + 1, parts))
                return false;
        return true;
    }
    if (t == "binary_operator") {
        return m_tree.view(ts::field(expr, "operator")) == "+" &&
               nameParts(ts::field(expr, "left"), depth + 1, parts) &&
               nameParts(ts::field(expr, "right"), depth + 1, parts);
    }
    if (t == "call") {
        const std::string_view callee = py::calleeName(m_tree, expr);
        TSNode function = ts::field(expr, "function");
        if (callee == "format" && ts::is(function, "attribute"))
            return formatParts(expr, depth, parts);
        if (callee == "str" && ts::is(function, "identifier"))
            return nameParts(py::positional(expr, 0), depth + 1, parts);
        // the node's own name and namespace, which each instance fills in
        const QString own = ownNamePart(expr);
        if (!own.isEmpty()) {
            parts->append({own, {}});
            return true;
        }
    }
    if (t == "identifier" || t == "attribute") {
        TSNode assigned = m_resolver.assignedExpression(expr);
        if (!ts::isNull(assigned))
            return nameParts(assigned, depth + 1, parts);
        if (t == "identifier") {
            const PythonParameterRef ref = parameterOf(expr);
            if (ref.isValid()) {
                parts->append({QString(), ref});
                return true;
            }
        }
    }
    // a known string; one from a declared parameter stays an expression, since launch files
    // may set the parameter and the rest of the name would be lost
    const PythonValue v = m_resolver.value(expr);
    if (v.origin == NameOrigin::Expression || !v.parameter.isEmpty())
        return false;
    parts->append({v.value, {}});
    return true;
}

bool PythonModuleReader::formatParts(TSNode call, int depth, QList<PythonNamePart> *parts) const
{
    QString format;
    if (!PythonResolver::stringLiteral(m_tree, py::calleeObject(call), &format))
        return false;
    QString text;
    int next = 0;
    for (qsizetype i = 0; i < format.size(); ++i) {
        const QChar c = format.at(i);
        const bool doubled = i + 1 < format.size() && format.at(i + 1) == c;
        if (c == QLatin1Char('}')) {
            text += c;
            i += doubled ? 1 : 0;
            continue;
        }
        if (c != QLatin1Char('{')) {
            text += c;
            continue;
        }
        if (doubled) {
            text += c;
            ++i;
            continue;
        }
        const qsizetype close = format.indexOf(QLatin1Char('}'), i);
        if (close < 0)
            return false;
        const QString field = format.mid(i + 1, close - i - 1);
        bool isIndex = false;
        const int index = field.toInt(&isIndex);
        TSNode argument{};
        if (field.isEmpty()) {
            argument = py::positional(call, next++);
        } else if (isIndex) {
            argument = py::positional(call, index);
        } else if (!field.contains(QLatin1Char(':')) && !field.contains(QLatin1Char('!')) &&
                   !field.contains(QLatin1Char('.')) && !field.contains(QLatin1Char('['))) {
            const std::string keyword = field.toStdString();
            argument = py::keyword(m_tree, call, keyword);
        }
        if (!text.isEmpty())
            parts->append({text, {}});
        text.clear();
        if (!nameParts(argument, depth + 1, parts))
            return false;
        i = close;
    }
    if (!text.isEmpty())
        parts->append({text, {}});
    return true;
}

} // namespace rosarch
