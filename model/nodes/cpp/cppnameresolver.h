#pragma once

#include "core/port.h"
#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cpplinkcontext.h"
#include "nodes/cpp/cppsharednames.h"

#include <QHash>
#include <QStringList>

#include <vector>

namespace rosarch {

/// A parameter type that holds a node: `rclcpp::Node::SharedPtr`, `nav2::LifecycleNode::WeakPtr`,
/// `std::shared_ptr<rclcpp::Node> &`, `rclcpp_lifecycle::LifecycleNode *`.
bool isNodeHandleType(const QString &type);

/// Resolves what the C++ facts leave symbolic, in the context of a class and function: port
/// names through members, locals, declared parameters and helper arguments; interface types
/// through aliases and helper template arguments; guards to the parameters they test.
class CppNameResolver
{
public:
    /// The resolver keeps references: `facts` (by class) and `interfaceAliases` may be
    /// filled after construction, before the first resolution.
    CppNameResolver(const CppClassIndex &index, const std::vector<CppMemberFacts> &facts,
                    const QHash<QString, QHash<QString, QString>> &interfaceAliases,
                    const CppSharedNames &shared);

    /// A port call as a Port: its name, type, callback and guard resolved in `ctx`.
    Port port(const CppPortCall &call, const CppLinkContext &ctx) const;
    CppResolvedName resolve(const CppValue &value, const CppLinkContext &ctx, int depth = 0) const;
    /// The declared default of `parameter` in the class of `ctx` (null when undeclared).
    QString parameterDefault(const QString &parameter, const CppLinkContext &ctx, int depth) const;
    /// The parameter a guard's value reads ("" when none).
    QString guardParameter(const CppValue &value, const CppLinkContext &ctx) const;
    /// True when `value` is the node (`this`, `shared_from_this()`, a node parameter, ...).
    bool isNodeHandle(const CppValue &value, const CppLinkContext &ctx, int depth = 0) const;
    /// As isNodeHandle, and where the node is: the context of the class whose `this` it is.
    bool nodeHandleAt(const CppValue &value, const CppLinkContext &ctx, CppLinkContext *at,
                      int depth = 0) const;
    /// The canonical interface type of a written type ("pkg/msg/T", or as written).
    QString resolveType(const QString &written, const CppLinkContext &ctx) const;
    /// `written` with namespace-level and member aliases expanded.
    QString expandAliases(const QString &written, const CppLinkContext &ctx) const;
    /// The scope names are looked up in: the class's, else the function's namespaces.
    QStringList scopeOf(const CppLinkContext &ctx) const;
    const CppMemberFacts &facts(int cls) const;

    /// `name()` called on the object of `ctx`: the most derived definition with a single
    /// return statement, as a context (fn null when none).
    CppLinkContext selfMethod(const QString &name, const CppLinkContext &ctx) const;

private:
    CppResolvedName resolveBuiltParameter(const CppValue &value, const CppLinkContext &ctx,
                                          int depth) const;
    CppResolvedName resolveConcatenation(const CppValue &value, const CppLinkContext &ctx,
                                         int depth) const;
    bool isPluginNameParameter(const CppValue &value, const CppLinkContext &ctx) const;
    const CppValue *ownCallArgument(int index, const CppLinkContext &ctx,
                                    CppLinkContext *caller) const;
    CppResolvedName resolveMember(const QString &member, const QString &text,
                                  const CppLinkContext &ctx, int depth) const;
    CppResolvedName resolveField(const CppValue &value, const CppLinkContext &ctx, int depth) const;
    CppResolvedName resolveConstant(const CppValue &value, const CppLinkContext &ctx,
                                    int depth) const;
    QString packageOf(const CppLinkContext &ctx) const;
    bool namesTheNode(int index, const CppLinkContext &ctx) const;
    bool holdsTheNodeName(const CppBinding &b, int cls) const;
    CppBinding outBinding(const QString &function, int index, const CppLinkContext &ctx) const;

    const CppClassIndex &m_index;
    const std::vector<CppMemberFacts> &m_facts;
    /// Namespace-level aliases of interface types from any file (typedefs in included
    /// headers): package -> alias -> target, and "" -> alias -> target for the workspace.
    const QHash<QString, QHash<QString, QString>> &m_interfaceAliases;
    const CppSharedNames &m_shared;
};

} // namespace rosarch
