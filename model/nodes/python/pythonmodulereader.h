#pragma once

#include "nodes/python/pythonmodulefacts.h"
#include "nodes/python/pythonportreader.h"
#include "nodes/python/pythonresolver.h"

#include <QHash>

namespace rosarch {

/// Extracts the facts of one parsed Python file: classes with their bases, constructor
/// arguments and the ports they create on each node handle, functions, procedural nodes,
/// hand-offs of node handles to helpers, and calls that may instantiate classes.
class PythonModuleReader
{
public:
    PythonModuleReader(const SyntaxTree &tree, QString modulePath);

    PythonModuleFacts read(const QString &package) const;

private:
    using Receivers = QHash<QString, PythonHandle>;
    struct ScopeNodes;

    PythonClassFacts readClass(TSNode cls) const;
    PythonFunctionFacts readFunction(TSNode function) const;
    PythonFunctionFacts readModuleStatements() const;
    void findAliases(const ScopeNodes &body, Receivers *receivers, bool members,
                     const QString &function, TSNode evidence, PythonScopeFacts *facts,
                     const Receivers &visible) const;
    void scan(const ScopeNodes &body, const Receivers &receivers, const QString &method,
              const QStringList &parameterNames, PythonScopeFacts *facts) const;
    bool proceduralNode(TSNode expr, PythonProcedural *procedural) const;
    QList<PythonArgument> arguments(TSNode call, const QStringList &parameterNames,
                                    bool skipFirst) const;
    QList<PythonParameter> parameters(TSNode function, bool skipSelf) const;
    QString key(TSNode expr) const;
    bool nameParts(TSNode expr, int depth, QList<PythonNamePart> *parts) const;
    bool formatParts(TSNode call, int depth, QList<PythonNamePart> *parts) const;
    /// `self.get_name()` and its kin as a name part: `{node}`, `{namespace}`,
    /// `{namespace}/{node}`; "" for any other call.
    QString ownNamePart(TSNode call) const;
    PythonParameterRef parameterOf(TSNode identifier) const;

    const SyntaxTree &m_tree;
    PythonResolver m_resolver;
    PythonPortReader m_ports;
};

} // namespace rosarch
