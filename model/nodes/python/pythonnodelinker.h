#pragma once

#include "languageanalysis.h"
#include "pythondefinitionindex.h"
#include "pythonmodulefacts.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

/// Resolves the facts of all Python files together: which classes are nodes (directly or
/// through project base classes), the ports they inherit or create through helpers, their
/// node names, the procedural nodes, and the node classes each function starts.
class PythonNodeLinker
{
public:
    explicit PythonNodeLinker(const QList<PythonModuleFacts> &modules);

    /// Appends the nodes (sorted by package and class) and the entry points.
    void link(LanguageAnalysis *out) const;

private:
    enum NodeKind
    {
        NotANode = 0,
        PlainNode = 1,
        LifecycleNode = 2
    };
    struct ScopedPort
    {
        Port port;
        QString method;
        int parameter = -1; ///< the name is still this constructor parameter of the class
        QString parameterName;
    };
    struct NameInfo
    {
        enum class Kind
        {
            None,
            Literal,
            Parameter,
            Expression
        };
        Kind kind = Kind::None;
        QString text;
        int index = -1; ///< Parameter: position among the owner's constructor parameters
        int owner = -1; ///< Parameter: the class whose constructor has it
    };
    struct Procedural
    {
        const PythonModuleFacts *module;
        const PythonScopeFacts *scope;
        int index;
        QString label; ///< the class or function it is built in
        QString className;
        QString qualifiedName;
    };

    /// A workspace class built while a node's tree (or helper) is made, and how it is reached.
    struct Instantiation
    {
        int id = -1;
        QList<PythonArgument> arguments;
        QList<Evidence> chain; ///< call sites from the node's scope to the instantiation
    };
    struct Reach
    {
        QList<Instantiation> found;
        QList<const PythonScopeFacts *> open; ///< scopes being followed (cycles)
        int visits = 0;        ///< scopes followed so far (a call graph can fan out widely)
        bool reported = false; ///< a bound was hit (one diagnostic per setup call)
        bool stopped = false;  ///< a budget ran out: follow nothing more
    };

    int nodeKind(int id, int depth = 0) const;
    QList<ScopedPort> classPorts(int id, int depth) const;
    QList<Port> helperPorts(const PythonHandoff &handoff, const PythonScopeFacts &from,
                            int depth) const;
    QList<Port> methodPorts(const PythonHandoff &handoff, int depth) const;
    QList<Port> scopePorts(const PythonScopeFacts &scope, const PythonHandle &handle,
                           const QString &via, int depth,
                           const QList<PythonArgument> *arguments = nullptr,
                           const QList<PythonParameter> *parameters = nullptr) const;
    /// Ports of the objects built in `from` that receive the node through `setup(node=...)`.
    QList<Port> setupPorts(const PythonHandoff &handoff, const PythonScopeFacts &from,
                           int depth) const;
    QList<ScopedPort> setupClassPorts(int id, const QList<PythonArgument> &arguments,
                                      int depth) const;
    void reachInstantiations(const PythonScopeFacts &scope, const QList<PythonArgument> *bound,
                             const QList<PythonParameter> *parameters, const QList<Evidence> &chain,
                             int depth, Reach *reach) const;
    void reportBound(const Evidence &at, const QString &what) const;
    /// The value all instantiations of a class pass for a constructor parameter, if they agree.
    bool agreedArgument(int id, int index, const QString &name, const QString &fallback,
                        PythonArgument *agreed) const;
    NameInfo nameInfo(int id, int depth) const;
    QString nodeName(int id) const;
    QStringList startedNodes(int function, int depth, QList<int> *visited) const;
    void nameProcedurals();

    const QList<PythonModuleFacts> &m_modules;
    PythonDefinitionIndex m_index;
    QHash<int, QList<const PythonCall *>> m_instantiations; ///< by class id
    QList<Procedural> m_procedurals;
    mutable QHash<int, int> m_kinds;
    mutable QList<Diagnostic> m_diagnostics; ///< bounds hit while following helpers
};

} // namespace rosarch
