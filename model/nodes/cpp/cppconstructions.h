#pragma once

#include "core/atomicnode.h"
#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cpphelperports.h"
#include "nodes/cpp/cpplinkcontext.h"
#include "nodes/cpp/cppnameresolver.h"

namespace rosarch {

/// What constructing a node class decides (blueprint §1, "Child nodes" and "Nodes built in
/// code"): the node's name and namespace, from the arguments its constructor hands to its base
/// class, and the names of the ports that its constructor's parameters name.
class CppConstructions
{
public:
    CppConstructions(const CppClassIndex &index, const CppNameResolver &names,
                     const CppHelperPorts &helpers);

    /// A node of class `cls` that another node creates inside itself at `inst` (in `ctx`);
    /// `ownName` is the name the class gives itself.
    ChildNode child(int cls, const CppInstantiation &inst, const CppLinkContext &ctx,
                    const QString &ownName) const;
    /// A node of class `cls` that an executable's own code builds at `inst` (in `ctx`), with
    /// the ports of its constructor as these arguments name them (ids not yet given).
    NodeConstruction construction(int cls, const CppInstantiation &inst, const CppLinkContext &ctx,
                                  const QString &ownName) const;

private:
    QString parameterDefault(int cls, const CppFunction &fn, int index) const;

    const CppClassIndex &m_index;
    const CppNameResolver &m_names;
    const CppHelperPorts &m_helpers;
};

} // namespace rosarch
