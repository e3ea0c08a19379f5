#pragma once

#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cppconstructions.h"
#include "nodes/cpp/cppnameresolver.h"

namespace rosarch {

/// The name a node class gives itself: the literal its constructors hand rclcpp's node base,
/// through bases of the workspace that forward it (`Filter(name) : Node(name)`) or name the
/// node themselves (`TestActionServer(action) : Node("test_action_server")`).
class CppNodeNames
{
public:
    CppNodeNames(const CppClassIndex &index, const CppNameResolver &names,
                 const CppConstructions &constructions);

    /// The name of node class `cls`, "" when its instances decide it.
    QString of(int cls) const { return nodeNameOf(cls, 0); }
    /// The name `value` (a node's name argument) stands for when a literal decides it; "" for a
    /// constructor parameter or an expression.
    QString literalName(const CppValue &value, const CppLinkContext &ctx) const;
    /// The initializer by which a class of `lineage` before `base` hands arguments to the
    /// constructor of `lineage[base]`, with the constructor it is written in (`at`).
    const CppBaseInitializer *baseInitializer(const QList<int> &lineage, qsizetype base,
                                              CppLinkContext *at) const;

private:
    QString nodeNameOf(int index, int depth) const;
    int forwardedName(int cls, int argumentCount) const;

    const CppClassIndex &m_index;
    const CppNameResolver &m_names;
    const CppConstructions &m_constructions;
};

} // namespace rosarch
