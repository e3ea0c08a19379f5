#include "nodes/python/pythonimports.h"

#include "syntax/pythonsyntax.h"

#include <utility>

namespace rosarch {

PythonImports::PythonImports(const SyntaxTree &tree, const PythonScopeIndex &scopes,
                             QString modulePath)
    : m_modulePath(std::move(modulePath))
{
    py::walk(tree.root(), [&](TSNode n) {
        const std::string_view t = ts::type(n);
        if (t == "import_statement") {
            for (TSNode name : ts::fieldChildren(n, "name")) {
                if (ts::is(name, "dotted_name")) {
                    const QString full = tree.text(name);
                    const QString first = full.section(QLatin1Char('.'), 0, 0);
                    m_bindings.insert(first, first);
                } else if (ts::is(name, "aliased_import")) {
                    m_bindings.insert(tree.text(ts::field(name, "alias")),
                                      tree.text(ts::field(name, "name")));
                }
            }
            return false;
        }
        if (t == "import_from_statement") {
            TSNode module = ts::field(n, "module_name");
            const QString from = ts::is(module, "relative_import") ? resolveRelative(tree, module)
                                                                   : tree.text(module);
            const QString prefix = from.isEmpty() ? QString() : from + QLatin1Char('.');
            for (TSNode name : ts::fieldChildren(n, "name")) {
                if (ts::is(name, "dotted_name")) {
                    const QString text = tree.text(name);
                    m_bindings.insert(text, prefix + text);
                } else if (ts::is(name, "aliased_import")) {
                    m_bindings.insert(tree.text(ts::field(name, "alias")),
                                      prefix + tree.text(ts::field(name, "name")));
                }
            }
            for (TSNode c : ts::namedChildren(n))
                if (ts::is(c, "wildcard_import"))
                    m_wildcards.append(from);
            return false;
        }
        if (t == "class_definition") {
            m_definitions.insert(tree.text(ts::field(n, "name")));
        } else if (t == "function_definition") {
            if (scopes.isTopLevel(n))
                m_definitions.insert(tree.text(ts::field(n, "name")));
            return true;
        }
        return true;
    });
}

QString PythonImports::resolveRelative(const SyntaxTree &tree, TSNode relativeImport) const
{
    int dots = 0;
    QString rest;
    for (TSNode c : ts::children(relativeImport)) {
        if (ts::is(c, "import_prefix"))
            dots += int(tree.view(c).size());
        else if (ts::is(c, "dotted_name"))
            rest = tree.text(c);
    }
    QStringList base = m_modulePath.split(QLatin1Char('.'), Qt::SkipEmptyParts);
    for (int i = 0; i < dots && !base.isEmpty(); ++i)
        base.removeLast();
    if (!rest.isEmpty())
        base.append(rest);
    return base.join(QLatin1Char('.'));
}

QString PythonImports::qualify(const QString &dotted) const
{
    const qsizetype dot = dotted.indexOf(QLatin1Char('.'));
    const QString first = dot < 0 ? dotted : dotted.left(dot);
    const QString rest = dot < 0 ? QString() : dotted.mid(dot);
    if (m_definitions.contains(first))
        return m_modulePath.isEmpty() ? dotted : m_modulePath + QLatin1Char('.') + dotted;
    const auto it = m_bindings.constFind(first);
    if (it != m_bindings.constEnd())
        return it.value() + rest;
    if (m_wildcards.size() == 1 && !first.isEmpty() && first.at(0).isUpper())
        return m_wildcards.first() + QLatin1Char('.') + dotted;
    return dotted;
}

} // namespace rosarch
