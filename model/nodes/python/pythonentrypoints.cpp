#include "nodes/python/pythonentrypoints.h"

#include <QSet>

#include <algorithm>

namespace rosarch {

PythonEntryPoints::PythonEntryPoints(
    const PythonDefinitionIndex &index, std::function<bool(int)> isNode,
    std::function<QStringList(const PythonScopeFacts *)> procedurals,
    std::function<NodeConstruction(int, const PythonCall &)> construction)
    : m_index(index), m_isNode(std::move(isNode)), m_procedurals(std::move(procedurals)),
      m_construction(std::move(construction))
{
}

void PythonEntryPoints::addEntryPoints(LanguageAnalysis *out) const
{
    QSet<QPair<QString, int>> reported; // a call site is said once, whoever reaches it
    for (int id = 0; id < m_index.functionCount(); ++id) {
        const PythonFunctionFacts &function = m_index.functionFacts(id);
        if (function.name.isEmpty())
            continue;
        QList<int> visited;
        QList<Evidence> boundsHit;
        EntryPoint e;
        e.instantiatedClasses = startedNodes(id, 0, &visited, &boundsHit);
        for (const Evidence &at : std::as_const(boundsHit)) {
            if (reported.contains({at.file, at.line}))
                continue;
            reported.insert({at.file, at.line});
            Diagnostic d;
            d.severity = Diagnostic::Severity::Info;
            d.code = QStringLiteral("builder-depth");
            d.message = QStringLiteral("Stopped following the functions %1() calls here (bound: "
                                       "%2 calls deep); nodes built beyond it are not counted "
                                       "among those %1() starts.")
                            .arg(function.name)
                            .arg(kMaxBuilderDepth);
            d.evidence = at;
            out->diagnostics.append(d);
        }
        if (e.instantiatedClasses.isEmpty())
            continue;
        e.file = m_index.functionModule(id).file;
        e.function = function.name;
        e.evidence = function.evidence;
        visited.clear();
        addConstructions(id, 0, &visited, &e.constructions);
        out->entryPoints.append(e);
    }
}

bool PythonEntryPoints::buildsNode(int function) const
{
    const PythonFunctionFacts &facts = m_index.functionFacts(function);
    if (!m_procedurals(&facts).isEmpty())
        return true;
    return std::any_of(facts.calls.cbegin(), facts.calls.cend(), [&](const PythonCall &call) {
        const int cls = m_index.findClass(call.target);
        return cls >= 0 && (m_isNode(cls) || !m_procedurals(&m_index.classFacts(cls)).isEmpty());
    });
}

QStringList PythonEntryPoints::startedNodes(int function, int depth, QList<int> *visited,
                                            QList<Evidence> *boundsHit) const
{
    QStringList out;
    auto add = [&](const QString &name) {
        if (!out.contains(name))
            out.append(name);
    };
    visited->append(function);
    const PythonFunctionFacts &facts = m_index.functionFacts(function);
    for (const PythonCall &call : facts.calls) {
        const int cls = m_index.findClass(call.target);
        if (cls >= 0) {
            if (m_isNode(cls))
                add(m_index.classFacts(cls).qualifiedName);
            else
                for (const QString &name : m_procedurals(&m_index.classFacts(cls)))
                    add(name);
            continue;
        }
        const int callee = m_index.findFunction(call.target);
        if (callee < 0 || visited->contains(callee))
            continue;
        if (depth >= kMaxBuilderDepth) {
            if (buildsNode(callee))
                boundsHit->append(call.evidence);
            continue;
        }
        for (const QString &name : startedNodes(callee, depth + 1, visited, boundsHit))
            add(name);
    }
    for (const QString &name : m_procedurals(&facts))
        add(name);
    return out;
}

void PythonEntryPoints::addConstructions(int function, int depth, QList<int> *visited,
                                         QList<NodeConstruction> *out) const
{
    visited->append(function);
    for (const PythonCall &call : m_index.functionFacts(function).calls) {
        const int cls = m_index.findClass(call.target);
        if (cls >= 0 && m_isNode(cls)) {
            // `for zone in ZONES: Watcher(zone)`: one node per item
            const auto loop =
                std::find_if(call.arguments.cbegin(), call.arguments.cend(),
                             [](const PythonArgument &a) { return !a.items.isEmpty(); });
            if (loop == call.arguments.cend()) {
                out->append(m_construction(cls, call));
                continue;
            }
            for (const QString &item : loop->items) {
                PythonCall one = call;
                PythonArgument &a = one.arguments[loop - call.arguments.cbegin()];
                a.isString = true;
                a.value = item;
                a.origin = NameOrigin::Literal;
                out->append(m_construction(cls, one));
            }
            continue;
        }
        if (cls >= 0)
            continue;
        const int callee = depth < kMaxBuilderDepth ? m_index.findFunction(call.target) : -1;
        if (callee >= 0 && !visited->contains(callee))
            addConstructions(callee, depth + 1, visited, out);
    }
}

} // namespace rosarch
