#pragma once

#include "cppclassindex.h"
#include "cppfacts.h"
#include "languageanalysis.h"

#include <QHash>

namespace rosarch {

/// Phase 2 of the C++ analysis (single-threaded): links the per-file facts into node classes,
/// procedural nodes, entry points and component registrations. Resolves port names through
/// members and declared parameters, types through aliases, ports of project base classes and
/// of helper classes that receive the node.
class CppNodeLinker
{
public:
    explicit CppNodeLinker(const QList<CppFileFacts> &files);

    LanguageAnalysis link() const;

private:
    static constexpr int kMaxDepth = 6; ///< bound for alias, member and helper chains
    struct Substitution;
    struct Context
    {
        int cls = -1;
        const CppFunction *fn = nullptr;
        const CppFileFacts *file = nullptr;
        const Substitution *subst = nullptr; ///< arguments of the helper's instantiation
    };
    struct Substitution
    {
        QList<CppValue> arguments;
        Context outer;
        QHash<QString, QString> templateArguments; ///< helper template parameter -> type
        const CppFunction *function = nullptr;     ///< free helper function; null: the constructors
    };
    struct Resolved
    {
        NameOrigin origin = NameOrigin::Expression;
        QString name;
        QString expression;
        QString parameter;
    };
    struct Binding
    {
        CppValue value;
        const CppFunction *fn = nullptr;
        const CppFileFacts *file = nullptr;
    };
    struct MemberFacts
    {
        QHash<QString, QList<Binding>> bindings;
        QHash<QString, CppParameterDeclaration> parameters;
    };

    AtomicNode classNode(int index, const CppProceduralNode *ownedNode = nullptr) const;
    const CppProceduralNode *ownedNode(int cls) const;
    QString nodeNameOf(int index, int depth) const;
    bool constructorApplies(const CppFunction &fn, const QList<CppValue> &arguments,
                            const QList<const CppFunction *> &constructors) const;
    QList<Port> portsOf(int cls, bool inherited) const;
    QList<Port> helperPorts(int helper, const QList<CppValue> &arguments,
                            const QStringList &templateArguments, const Context &outer,
                            int depth) const;
    void addHelperPorts(const CppInstantiation &inst, const Context &ctx, int depth,
                        QList<Port> *ports) const;
    void addFreeCallPorts(const CppFreeCall &call, const Context &ctx, int depth,
                          QList<Port> *ports) const;
    static bool substitutes(const Context &ctx);
    int helperClass(const CppInstantiation &inst, const Context &ctx,
                    QStringList *templateArguments) const;
    Port makePort(const CppPortCall &call, const Context &ctx) const;
    void addProceduralNodes(const CppClassIndex::FunctionRef &ref, QList<AtomicNode> *nodes,
                            QHash<QString, int> *stems) const;
    void addEntryPoint(const CppClassIndex::FunctionRef &ref, const QList<AtomicNode> &procedural,
                       QList<EntryPoint> *entryPoints) const;

    Resolved resolve(const CppValue &value, const Context &ctx, int depth = 0) const;
    Resolved resolveMember(const QString &member, const QString &text, const Context &ctx,
                           int depth) const;
    QString parameterDefault(const QString &parameter, const Context &ctx, int depth) const;
    QString guardParameter(const CppValue &value, const Context &ctx) const;
    bool isNodeHandle(const CppValue &value, const Context &ctx, int depth = 0) const;
    QString resolveType(const QString &written, const Context &ctx) const;
    QString expandAliases(const QString &written, const Context &ctx) const;
    QStringList scopeOf(const Context &ctx) const;
    const MemberFacts &facts(int cls) const;

    const QList<CppFileFacts> &m_files;
    CppClassIndex m_index;
    std::vector<MemberFacts> m_facts; ///< by class, built up front (resolution keeps pointers)
    std::vector<const CppProceduralNode *> m_ownedNodes;
    QHash<QString, QList<CppClassIndex::FunctionRef>> m_freeFunctionsByName;
    /// Namespace-level aliases of interface types from any file (typedefs in included
    /// headers): package -> alias -> target, and "" -> alias -> target for the workspace.
    QHash<QString, QHash<QString, QString>> m_interfaceAliases; ///< node-like components, by class
};

} // namespace rosarch
