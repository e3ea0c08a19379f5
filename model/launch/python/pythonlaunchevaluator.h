#pragma once

#include "launch/python/pythonlaunchapi.h"
#include "launch/python/pythonlaunchbuiltins.h"
#include "launch/python/pythonlaunchcontext.h"
#include "launch/python/pythonlaunchexpressions.h"
#include "launch/python/pythonlaunchvalue.h"
#include "syntax/syntaxtree.h"

#include <QList>
#include <QSet>
#include <QString>

#include <optional>
#include <vector>

namespace rosarch::pylaunch {

/// A small symbolic Python interpreter for launch files: runs the module's top level and
/// generate_launch_description() statement by statement over Values. Nothing is executed;
/// undecidable branches are kept. Bounded in call depth, loop unrolling and total steps, so it
/// always terminates. Expressions are PythonLaunchExpressions' job, Python's builtins
/// PythonLaunchBuiltins', the launch API PythonLaunchApi's; they share a PythonLaunchContext.
class PythonLaunchEvaluator
{
public:
    explicit PythonLaunchEvaluator(const SyntaxTree &tree);
    PythonLaunchEvaluator(const PythonLaunchEvaluator &) = delete;
    PythonLaunchEvaluator &operator=(const PythonLaunchEvaluator &) = delete;

    /// The actions of the LaunchDescription that generate_launch_description() returns.
    QList<LaunchAction> run();
    /// One expression of the tree on its own, in a module scope holding `names`; the context
    /// then says whether a bound or a guess stands in the value.
    Value evaluate(TSNode expression, const QHash<QString, Value> &names);
    const PythonLaunchContext &context() const { return m_ctx; }
    const QList<Diagnostic> &diagnostics() const { return m_ctx.diagnostics; }

private:
    // The parts call back into the interpreter: calls in expressions, an OpaqueFunction's body.
    friend class PythonLaunchExpressions;
    friend class PythonLaunchApi;

    void execBlock(TSNode block);
    void execStatement(TSNode statement);
    void execIf(TSNode ifStatement);
    void execIfChain(const QList<TSNode> &clauses, qsizetype from);
    void execFor(TSNode forStatement);
    void execImport(TSNode statement);
    void assign(TSNode target, const Value &value);
    void bind(const QString &name, const Value &value);
    /// A call expression: user functions run here, the rest goes to the builtins or the API.
    Value evalCall(TSNode call);
    Value callFunction(const Value &function, const CallArgs &args, TSNode call);
    Value combineReturns(const GuardPtr &guard, const Value &taken, const Value &other);

    PythonLaunchContext m_ctx; ///< first: the parts below refer to it
    PythonLaunchBuiltins m_builtins;
    PythonLaunchApi m_api;
    PythonLaunchExpressions m_expressions;
};

} // namespace rosarch::pylaunch
