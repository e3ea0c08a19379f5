#pragma once

#include "nodes/cpp/cppfacts.h"
#include "nodes/cpp/cppvalueevaluator.h"
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"

#include <vector>

namespace rosarch {

/// Reads a call that declares a ROS parameter (blueprint §1, "Parameters of a class"): its
/// name, type, default, and what the `ParameterDescriptor` handed to it says (read-only,
/// description, range, dynamic typing) by the descriptor's last assignments before the call.
class CppParameterReader
{
public:
    CppParameterReader(const SyntaxTree &tree, const CppValueEvaluator &values);

    /// The declaration `call` makes, or one with an empty `via` when the call declares none:
    /// `declare_parameter` (each overload), nav2_util's `declare_parameter_if_not_declared`
    /// and `declare_or_get_parameter`, `get_parameter_or`, `undeclare_parameter`, and a
    /// project's own `declare...parameter` helper. `definition` is the enclosing function.
    CppParameterDeclaration read(TSNode call, const cppsyntax::CallShape &shape,
                                 const std::vector<TSNode> &args, TSNode definition) const;

    /// The declarations of `declare_parameters(prefix, {{"a", 1}, {"b", 2}})` (a map written
    /// in place; one written elsewhere declares names the call does not show, given as
    /// `prefix.{map}`). Empty for any other call.
    QList<CppParameterDeclaration> readMany(TSNode call, const cppsyntax::CallShape &shape,
                                            const std::vector<TSNode> &args) const;

    /// The declaration of a call through a getter a parameters handler hands out:
    /// `auto getParam = handler->getParamGetter(ns); getParam(member, "name", default);`
    /// declares `ns.name` (`name` when `ns` is empty) with the default's type. `getter` is the
    /// local's value; an empty `via` when it is no such getter.
    CppParameterDeclaration readGetterCall(TSNode call, const std::vector<TSNode> &args,
                                           TSNode getter) const;

    /// The ROS parameter type of a default value as written ("" when open).
    QString typeOfValue(TSNode value, bool *isTypeOnly = nullptr, int depth = 0) const;

private:
    void readDescriptor(const QString &variable, TSNode call, TSNode definition,
                        CppParameterDeclaration *decl) const;

    const SyntaxTree &m_tree;
    const CppValueEvaluator &m_values;
};

} // namespace rosarch
