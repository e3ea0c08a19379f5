#pragma once

#include "core/parameter.h"
#include "syntax/syntaxtree.h"

#include <QList>

namespace rosarch {

/// The parameters a Python scope (a node class, a function building a node) declares through
/// rclpy (blueprint §1, "Parameters of a class"): `declare_parameter(name, value, descriptor)`
/// and `declare_parameters(namespace, [(name, value, descriptor), ...])`, with the type of
/// the value and what an inline `ParameterDescriptor(...)` says.
class PythonParameterReader
{
public:
    explicit PythonParameterReader(const SyntaxTree &tree);

    QList<ParameterDeclaration> read(TSNode scope) const;
    /// Whether the scope lets its node take parameters nobody declares
    /// (`allow_undeclared_parameters=True`,
    /// `automatically_declare_parameters_from_overrides=True`).
    bool acceptsUndeclared(TSNode scope) const;

private:
    void add(TSNode call, const QString &name, TSNode value, TSNode descriptor,
             QList<ParameterDeclaration> *out) const;
    QString typeOf(TSNode value, bool *typeOnly) const;
    QString nameText(TSNode name) const;

    const SyntaxTree &m_tree;
};

} // namespace rosarch
