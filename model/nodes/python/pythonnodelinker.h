#pragma once

#include "core/languageanalysis.h"
#include "nodes/python/pythondefinitionindex.h"
#include "nodes/python/pythonmodulefacts.h"
#include "nodes/python/pythonsetupprotocol.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

/// Resolves the facts of all Python files together: which classes are nodes (directly or
/// through project base classes), the ports they inherit or create through helpers, their
/// node names, the procedural nodes, and (PythonEntryPoints) the nodes each function starts.
class PythonNodeLinker
{
public:
    explicit PythonNodeLinker(const QList<PythonModuleFacts> &modules);
    Q_DISABLE_COPY_MOVE(PythonNodeLinker) // the setup protocol calls back into this linker

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
        /// The class's own fact of the port (null for a helper's or a base's): a name built
        /// from constructor parameters (`zone + '/occupied'`) that a construction decides.
        const PythonPortFact *fact = nullptr;
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

    int nodeKind(int id, int depth = 0) const;
    /// The class's declared parameters, then those its project bases declare (inherited).
    QList<ParameterDeclaration> declaredParameters(int id) const;
    bool acceptsUndeclared(int id, int depth) const;
    QList<ScopedPort> classPorts(int id, int depth) const;
    QList<Port> helperPorts(const PythonHandoff &handoff, const PythonScopeFacts &from,
                            int depth) const;
    QList<Port> methodPorts(const PythonHandoff &handoff, int depth) const;
    QList<Port> scopePorts(const PythonScopeFacts &scope, const PythonHandle &handle,
                           const QString &via, int depth,
                           const QList<PythonArgument> *arguments = nullptr,
                           const QList<PythonParameter> *parameters = nullptr) const;
    /// The value all instantiations of a class pass for a constructor parameter, if they agree.
    bool agreedArgument(int id, int index, const QString &name, const QString &fallback,
                        PythonArgument *agreed) const;
    NameInfo nameInfo(int id, int depth) const;
    QString nodeName(int id) const;
    /// Class `cls` built by `call`: the node name and port names its arguments decide.
    NodeConstruction construction(int cls, const PythonCall &call) const;
    void nameProcedurals();

    const QList<PythonModuleFacts> &m_modules;
    PythonDefinitionIndex m_index;
    QHash<int, QList<const PythonCall *>> m_instantiations; ///< by class id
    QList<Procedural> m_procedurals;
    mutable QHash<int, int> m_kinds;
    PythonSetupProtocol m_setup; ///< follows `setup(node=...)`; keeps the bounds hit
};

} // namespace rosarch
