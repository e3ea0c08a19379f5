#pragma once

#include "nodes/python/pythonmodulefacts.h"

#include <QHash>
#include <QList>
#include <QString>

#include <utility>
#include <vector>

namespace rosarch {

/// The workspace's Python symbol table: every class and module-level function by id, found
/// by the dotted name a call or base class resolves to.
class PythonDefinitionIndex
{
public:
    explicit PythonDefinitionIndex(const QList<PythonModuleFacts> &modules);

    int classCount() const { return int(m_classRefs.size()); }
    int functionCount() const { return int(m_functionRefs.size()); }
    const PythonClassFacts &classFacts(int id) const;
    const PythonModuleFacts &classModule(int id) const;
    const PythonFunctionFacts &functionFacts(int id) const;
    const PythonModuleFacts &functionModule(int id) const;

    /// The class a qualified name denotes; when no module path matches exactly, the one class
    /// whose qualified name ends with the same segments (at least two). -1 if none or ambiguous.
    int findClass(const QString &target) const;
    /// Same for module-level functions.
    int findFunction(const QString &target) const;
    /// The workspace classes among a class's direct bases.
    QList<int> projectBases(int id) const;

private:
    const QList<PythonModuleFacts> &m_modules;
    std::vector<std::pair<int, int>> m_classRefs;    ///< (module, class) per class id
    std::vector<std::pair<int, int>> m_functionRefs; ///< (module, function) per function id
    QHash<QString, int> m_classes;                   ///< by qualified name
    QHash<QString, int> m_functions;
    QHash<QString, QList<int>> m_classesByName; ///< by simple name
    QHash<QString, QList<int>> m_functionsByName;
};

} // namespace rosarch
