#pragma once

#include "core/diagnostic.h"
#include "launch/python/pythonlaunchvalue.h"
#include "syntax/syntaxtree.h"

#include <QList>
#include <QPair>
#include <QSet>
#include <QString>

#include <initializer_list>
#include <memory>
#include <vector>

namespace rosarch::pylaunch {

/// Lists grow no longer than this (appending, concatenating, repeating).
constexpr qsizetype kMaxListSize = 10000;

/// A call's arguments, evaluated, with the nodes they were written at.
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

/// One activation of a function (or the module): its scope, and how its block is left.
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

/// What the parts of the Python launch evaluator share: the file, the frame being run and the
/// undecided branches around it, the budgets, the diagnostics, and every list, dict and scope
/// made (cleared at the end, since closures and self-appended lists make reference cycles).
class PythonLaunchContext
{
public:
    explicit PythonLaunchContext(const SyntaxTree &tree);
    ~PythonLaunchContext();
    PythonLaunchContext(const PythonLaunchContext &) = delete;
    PythonLaunchContext &operator=(const PythonLaunchContext &) = delete;

    /// Counts one evaluation step; false once the budget is spent (then `exhausted`).
    /// Spends one step of the file's budget on `at`; false once it is spent (the first node
    /// it was refused for is kept in `stoppedAt`).
    bool step(TSNode at);
    /// True when the current block must not go on: budget spent, returned, break, continue.
    bool stopped() const;

    Value newList(QList<Value> items, bool tuple = false);
    Value newDict();
    std::shared_ptr<Scope> newScope(std::shared_ptr<Scope> parent);
    /// Appends under the current guards, up to kMaxListSize items.
    void append(const Value &list, const Value &item);
    /// The items a `for` over `value` sees; `known` false when that cannot be decided.
    QList<Value> iterate(const Value &value, bool *known);
    /// An unknown value standing for the code at `node`.
    Value unknownAt(TSNode node) const;
    QString textOf(TSNode node) const;

    const SyntaxTree &tree;
    std::shared_ptr<Scope> module;
    Frame *frame = nullptr;
    GuardPath guards; ///< the undecided branches the current code runs under
    int callDepth = 0;
    int exprDepth = 0;
    bool exhausted = false;
    bool tooDeep = false; ///< an expression nested past the depth bound was not evaluated
    /// A value stands for a guess (an undecided condition's first alternative, an unordered
    /// set's order) or was cut short by a bound (a range, a repetition, a list's length).
    bool approximate = false;
    TSNode stoppedAt{}; ///< where the step budget ran out (null while it lasts)
    QList<Diagnostic> diagnostics;

private:
    int m_steps = 0;
    std::vector<std::weak_ptr<ListData>> m_lists;
    std::vector<std::weak_ptr<DictData>> m_dicts;
    std::vector<std::weak_ptr<Scope>> m_scopes;
};

} // namespace rosarch::pylaunch
