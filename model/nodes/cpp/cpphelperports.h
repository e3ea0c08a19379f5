#pragma once

#include "core/port.h"
#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cpplinkcontext.h"
#include "nodes/cpp/cppnameresolver.h"

#include <QHash>
#include <QList>
#include <QMutex>

#include <vector>

namespace rosarch {

/// Finds the ports a node creates through helpers: classes it instantiates with the node
/// (`this`, `shared_from_this()`, a procedural node) and free functions it hands the node to,
/// followed to a bounded depth, with the helper's parameters standing for the arguments.
class CppHelperPorts
{
public:
    /// Keeps references: `freeFunctions` and `ownedNodes` may be filled after construction.
    CppHelperPorts(const CppClassIndex &index, const CppNameResolver &names,
                   const QHash<QString, QList<CppClassIndex::FunctionRef>> &freeFunctions,
                   const std::vector<const CppProceduralNode *> &ownedNodes);

    /// Ports of the helper class `inst` creates, when it is handed the node.
    void addHelperPorts(const CppInstantiation &inst, const CppLinkContext &ctx, int depth,
                        QList<Port> *ports) const;
    /// `setup_publishers(node)`: the ports a free function creates on the node it is handed.
    void addFreeCallPorts(const CppFreeCall &call, const CppLinkContext &ctx, int depth,
                          QList<Port> *ports) const;

    /// `debug_->publish<T>("debug/time", v)`: the ports a method of a helper the class built
    /// with the node creates at this call (a lazily created publisher, keyed by its name).
    void addMethodCallPorts(const CppMethodCall &call, const CppLinkContext &ctx, int depth,
                            QList<Port> *ports) const;
    /// What `fn` hands the node to: helpers it builds, functions it calls with the node, and
    /// methods it calls on helpers (lazily made ports).
    void addCallPorts(const CppFunction &fn, const CppLinkContext &ctx, int depth,
                      QList<Port> *ports) const;
    /// The ports of class `cls` (a node class) constructed with `arguments` in `outer`: its
    /// constructors' ports with their parameters standing for the arguments, and its template
    /// parameters for `templateArguments` (`PassStage<sensor_msgs::msg::LaserScan>`).
    QList<Port> constructedPorts(int cls, const QList<CppValue> &arguments,
                                 const CppLinkContext &outer,
                                 const QStringList &templateArguments = {}) const
    {
        return helperPorts(cls, arguments, templateArguments, outer, 1);
    }
    /// Ports of the helpers built in the class body (`Helper<T> member_{this, "name"};`).
    void addMemberHelperPorts(int cls, int self, QList<Port> *ports) const;
    /// Subscriptions of the class's `message_filters::Subscriber<T>` members, made in `ref`.
    void addMessageFilterPorts(int cls, const CppClassIndex::FunctionRef &ref,
                               QList<Port> *ports) const;

    /// Helper chains are followed this deep; what lies deeper is not given to the node.
    static constexpr int kMaxHelperDepth = 3;
    /// Where the depth bound was hit on this thread since its last call (the deepest call site
    /// not followed), cleared by the call: the linker links classes in parallel.
    QList<Evidence> takeBoundsHit() const;
    /// Records that following stopped at `where` (the parameter linker shares the bound).
    void boundHit(const Evidence &where) const;

private:
    void addFreeCallPortsAt(const CppFreeCall &call, const CppLinkContext &ctx, int depth,
                            QList<Port> *ports) const;
    bool handsNode(const QList<CppValue> &arguments, const CppLinkContext &ctx) const;
    int helperClass(const CppInstantiation &inst, const CppLinkContext &ctx,
                    QStringList *templateArguments) const;
    QList<Port> helperPorts(int helper, const QList<CppValue> &arguments,
                            const QStringList &templateArguments, const CppLinkContext &outer,
                            int depth) const;
    bool constructorApplies(const CppFunction &fn, const QList<CppValue> &arguments,
                            const QList<const CppFunction *> &constructors) const;
    /// A class that owns a node of its own (a member node): its ports are its node's.
    bool isOwner(int cls) const;

    const CppClassIndex &m_index;
    const CppNameResolver &m_names;
    const QHash<QString, QList<CppClassIndex::FunctionRef>> &m_freeFunctionsByName;
    const std::vector<const CppProceduralNode *> &m_ownedNodes;

    mutable QMutex m_boundsMutex; ///< the bounds are hit rarely: one lock for all threads
    mutable QHash<Qt::HANDLE, QList<Evidence>> m_boundsHit; ///< by thread
};

} // namespace rosarch
