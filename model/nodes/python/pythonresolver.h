#pragma once

#include "core/port.h"
#include "nodes/python/pythonimports.h"
#include "nodes/python/pythonscopeindex.h"
#include "syntax/syntaxtree.h"

#include <QHash>
#include <QSet>
#include <QString>
#include <QStringList>

namespace rosarch {

/// What an expression evaluates to, as far as a static reader can tell.
struct PythonValue
{
    NameOrigin origin = NameOrigin::Expression;
    QString value;     ///< the string it holds; the expression text when origin is Expression
    QString parameter; ///< the declared parameter it derives from, when known
};

/// Name resolution inside one parsed Python file: imports, string values of locals, members
/// and declared parameters, interface types, callbacks and guards.
class PythonResolver
{
public:
    PythonResolver(const SyntaxTree &tree, QString modulePath);

    const SyntaxTree &tree() const { return m_tree; }
    const PythonScopeIndex &scopes() const { return m_scopes; }
    const QString &modulePath() const { return m_modulePath; }

    /// Qualifies a dotted name through the imports and the file's own definitions.
    QString qualify(const QString &dotted) const;
    /// The qualified name of an identifier or attribute chain; "" for anything else.
    QString qualifiedName(TSNode expr) const;
    /// Canonical "pkg/msg/T" for a type expression; the text as written when unresolvable.
    QString interfaceType(TSNode expr) const;
    /// The string the expression holds and where it comes from.
    PythonValue value(TSNode expr) const;
    /// The expression a local (`x`) or member (`self.x`) is assigned: the last local assignment
    /// before the use, or a member's only assignment other than `None`. Null if none or unclear.
    TSNode assignedExpression(TSNode expr) const;
    /// `zone` in `for zone in ['dock', 'gate']:` (or over a local or module-level list of
    /// string literals): the strings it takes in turn; empty when it is no such loop variable.
    QStringList loopItems(TSNode identifier) const;
    /// "listener_callback" for self.listener_callback, "lambda" for a lambda, ...
    QString callbackName(TSNode expr) const;
    /// The conditions of the enclosing ifs (same function), and the parameter they test.
    /// `*guardDefault`: the declared default of the parameter the guard tests, when known.
    void guard(TSNode node, QString *guard, QString *guardParameter, QString *guardDefault) const;

    /// True for a plain (non-f) string literal or a concatenation of them.
    static bool stringLiteral(const SyntaxTree &tree, TSNode node, QString *value);

private:
    struct Assignment
    {
        uint32_t byte = 0;
        TSNode right{};
    };
    using AssignmentIndex = QHash<QString, QList<Assignment>>;

    PythonValue valueAt(TSNode expr, int depth) const;
    PythonValue identifierValue(TSNode expr, int depth) const;
    PythonValue memberValue(TSNode expr, int depth) const;
    PythonValue parameterValue(TSNode call, TSNode whole, int depth) const;
    TSNode parameterCall(TSNode expr) const;
    TSNode declaredDefault(TSNode at, const QString &parameter, bool *found) const;
    const AssignmentIndex &locals(TSNode scope) const;
    const AssignmentIndex &members(TSNode classNode) const;
    void indexParameters() const;
    QString interfaceTypeAt(TSNode expr, int depth) const;

    const SyntaxTree &m_tree;
    PythonScopeIndex m_scopes;
    QString m_modulePath;
    PythonImports m_imports;
    mutable QHash<uint32_t, AssignmentIndex> m_locals;  ///< by scope start byte (+1; 0 = module)
    mutable QHash<uint32_t, AssignmentIndex> m_members; ///< by class start byte
    mutable bool m_parametersIndexed = false;
    mutable QHash<uint32_t, QHash<QString, TSNode>> m_classParameters; ///< by class start byte
    mutable QHash<QString, TSNode> m_fileParameters;
};

} // namespace rosarch
