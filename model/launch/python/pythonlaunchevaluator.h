#pragma once

#include "pythonlaunchvalue.h"
#include "syntaxtree.h"

#include <QList>
#include <QSet>
#include <QString>

#include <optional>
#include <vector>

namespace rosarch::pylaunch {

/// A small symbolic Python interpreter for launch files: runs the module's top level and
/// generate_launch_description() statement by statement over Values, mapping launch API calls
/// to LaunchActions and Substitutions. Nothing is executed; undecidable branches are kept.
/// Bounded in call depth, loop unrolling and total steps, so it always terminates.
class PythonLaunchEvaluator
{
public:
    explicit PythonLaunchEvaluator(const SyntaxTree &tree);
    ~PythonLaunchEvaluator();
    PythonLaunchEvaluator(const PythonLaunchEvaluator &) = delete;
    PythonLaunchEvaluator &operator=(const PythonLaunchEvaluator &) = delete;

    /// The actions of the LaunchDescription that generate_launch_description() returns.
    QList<LaunchAction> run();
    const QList<Diagnostic> &diagnostics() const { return m_diagnostics; }

    /// The module-level generate_launch_description definition, or a null node.
    static TSNode launchFunction(const SyntaxTree &tree);

private:
    struct Frame
    {
        std::shared_ptr<Scope> scope;
        QSet<QString> globals;
        bool returned = false;
        bool breaking = false;
        bool continuing = false;
        Value returnValue = Value::none();
        QList<QPair<GuardPtr, Value>> pendingReturns; ///< returns inside undecided ifs
    };
    struct CallArgs
    {
        QList<Value> positional;
        QList<TSNode> positionalNodes;
        QList<QPair<QString, Value>> keywords;
        QList<TSNode> keywordNodes;
        /// The argument at `index` or under one of `names` (null when absent).
        const Value *get(int index, std::initializer_list<const char *> names = {}) const;
        TSNode node(int index, std::initializer_list<const char *> names = {}) const;
    };

    // Statements and functions (pythonlaunchevaluator.cpp)
    void execBlock(TSNode block);
    void execStatement(TSNode statement);
    void execIf(TSNode ifStatement);
    void execIfChain(const QList<TSNode> &clauses, qsizetype from);
    void execFor(TSNode forStatement);
    void execImport(TSNode statement);
    void assign(TSNode target, const Value &value);
    void bind(const QString &name, const Value &value);
    Value callFunction(const Value &function, const CallArgs &args, TSNode call);
    bool stopped() const;
    bool step();
    Value combineReturns(const GuardPtr &guard, const Value &taken, const Value &other);

    // Expressions (pythonlaunchexpressions.cpp)
    Value eval(TSNode node);
    Value evalNode(TSNode node);
    Value evalString(TSNode node);
    Value evalNumber(TSNode node);
    Value evalBinary(TSNode node);
    Value evalBoolean(TSNode node);
    Value evalComparison(TSNode node);
    Value evalSubscript(TSNode node);
    Value evalAttribute(TSNode node);
    Value evalComprehension(TSNode node);
    Value evalCall(TSNode node);
    Value lookup(TSNode identifier);
    CallArgs evalArguments(TSNode call);
    QList<Value> iterate(const Value &value, bool *known) const;
    Value newList(QList<Value> items, bool tuple = false);
    Value newDict();
    std::shared_ptr<Scope> newScope(std::shared_ptr<Scope> parent);
    void append(const Value &list, const Value &item);
    Value unknownAt(TSNode node) const;

    // Builtins and methods of plain Python values (pythonlaunchbuiltins.cpp)
    std::optional<Value> callBuiltin(const QString &dotted, const CallArgs &args, TSNode call);
    Value callMethod(const Value &object, const QString &method, const CallArgs &args, TSNode call);
    Value formatString(const QString &format, const QList<Value> &positional,
                       const QList<QPair<QString, Value>> &keywords, bool percent, TSNode node);

    // Launch API (pythonlaunchapi.cpp)
    std::optional<Value> callLaunchApi(const QString &name, const CallArgs &args, TSNode call);
    std::optional<Value> callSubstitutionApi(const QString &name, const CallArgs &args,
                                             TSNode call);
    Value makeNode(const QString &name, const CallArgs &args, TSNode call);
    Value makeInclude(const CallArgs &args, TSNode call);
    Value makeOpaque(const QString &name, const CallArgs &args, TSNode call);
    void readNodeFields(LaunchAction &action, const CallArgs &args, const Evidence &evidence) const;
    QList<LaunchRemap> remaps(const Value &value, const Evidence &evidence) const;
    QList<LaunchParameter> parameters(const Value &value, const Evidence &evidence) const;
    LaunchCondition condition(const CallArgs &args) const;
    QString textOf(TSNode node) const;
    QString textOfCall(TSNode call) const;

    const SyntaxTree &m_tree;
    std::shared_ptr<Scope> m_module;
    Frame *m_frame = nullptr;
    GuardPath m_guards;
    int m_callDepth = 0;
    int m_exprDepth = 0;
    int m_steps = 0;
    bool m_exhausted = false;
    QList<Diagnostic> m_diagnostics;
    // Everything that can hold a Value; cleared at the end, since closures and self-appended
    // lists make reference cycles.
    std::vector<std::weak_ptr<ListData>> m_lists;
    std::vector<std::weak_ptr<DictData>> m_dicts;
    std::vector<std::weak_ptr<Scope>> m_scopes;
};

} // namespace rosarch::pylaunch
