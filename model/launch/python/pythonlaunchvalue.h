#pragma once

#include "core/launchaction.h"

#include <QHash>
#include <QList>
#include <QPair>
#include <QString>

#include <tree_sitter/api.h>

#include <memory>
#include <optional>

// Values of the symbolic Python evaluator behind PythonLaunchReader.
namespace rosarch::pylaunch {

/// A Python `if` (or a loop over an unknown list) that the reader cannot decide; actions
/// added under it are wrapped into an unscoped Group with an unknown condition.
struct Guard
{
    QString text; ///< the condition as written
    bool unless = false;
    Evidence evidence;
};
using GuardPtr = std::shared_ptr<const Guard>;
using GuardPath = QList<GuardPtr>;

struct Scope;
struct ListData;
struct DictData;

/// One Python value, as far as the reader can tell.
struct Value
{
    enum class Type
    {
        Unknown, ///< `text` = the expression as written
        None,
        Bool,
        Number, ///< `text` = as written or computed
        String,
        List, ///< list, tuple, LaunchDescription (see ListData)
        Dict,
        Subst,     ///< a launch substitution (string-like)
        Action,    ///< one or more LaunchActions made by one call
        Condition, ///< IfCondition / UnlessCondition / LaunchConfigurationEquals
        Source,    ///< a launch description source; `subst` = its path
        Function,  ///< a def or lambda of this file
        Module,    ///< an imported or unbound dotted name; `text` = the dotted name
        Context, ///< the LaunchContext of an OpaqueFunction; `text` = "" or "launch_configurations"
        Skip, ///< a harmless action that is recorded as nothing (LogInfo, SetEnvironmentVariable)
    };

    Type type = Type::Unknown;
    QString text;
    bool boolean = false;
    double number = 0;
    Substitution subst;
    LaunchCondition condition;
    Evidence evidence; ///< where an Unknown value or an action comes from
    std::shared_ptr<ListData> list;
    std::shared_ptr<DictData> dict;
    std::shared_ptr<const QList<LaunchAction>>
        actions;                    ///< Action; also an event handler's actions (Unknown)
    TSNode node{};                  ///< Function: function_definition or lambda
    std::shared_ptr<Scope> closure; ///< Function: where it was defined

    static Value unknown(const QString &text, const Evidence &evidence = {});
    static Value none();
    static Value boolean_(bool b);
    static Value number_(double n, const QString &text = {});
    static Value string(const QString &s);
    static Value substitution(const Substitution &s);
    static Value module(const QString &dotted);
    static Value makeList(QList<Value> items, bool tuple = false, bool launchDescription = false);
    static Value makeDict();
    static Value action(QList<LaunchAction> actions);
    static Value skip()
    {
        Value v;
        v.type = Type::Skip;
        return v;
    }

    bool is(Type t) const { return type == t; }
    bool isStringLike() const { return type == Type::String || type == Type::Subst; }
    bool isLiteral() const
    {
        return type == Type::String || type == Type::Number || type == Type::Bool ||
               type == Type::None;
    }
    /// Python truthiness when it can be decided.
    std::optional<bool> truth() const;
    /// The literal text of a String/Number/Bool/None (Python `str()`), else nothing.
    std::optional<QString> literalText() const;
    /// A string-like launch value: lists concatenate (launch semantics), Python bools read "true".
    Substitution toSubstitution() const;
    /// A parameter value: lists as "[a, b]", bools as "true"/"false".
    Substitution toParameterValue() const;
    /// The items of a list, tuple or LaunchDescription, without those under an `else` guard.
    QList<Value> items() const;
    /// Structural equality for literals (dictionary keys, `==`, `in`).
    bool sameLiteral(const Value &other) const;
};

/// A mutable list shared by every Python name bound to it (append through an alias works).
struct ListData
{
    QList<Value> items;
    QList<GuardPath> guards; ///< per item, the undecided ifs it was added under
    GuardPath createdUnder;  ///< the guards active when the list was created
    bool tuple = false;
    bool launchDescription = false;
};

struct DictData
{
    QList<QPair<Value, Value>> entries;
    GuardPath createdUnder;
    const Value *find(const Value &key) const;
    void set(const Value &key, const Value &value);
};

/// A Python scope: function locals (parent = enclosing scope) or the module.
struct Scope
{
    QHash<QString, Value> vars;
    std::shared_ptr<Scope> parent;
    const Value *lookup(const QString &name) const;
};

/// The guards in `current` that are not already in `createdUnder` (common prefix removed).
GuardPath relativeGuards(const GuardPath &createdUnder, const GuardPath &current);
/// True when an item added under `path` belongs to the best guess (no `else` guard).
bool inBestGuess(const GuardPath &path);
/// Concatenation that folds adjacent literals and flattens nested Concat.
Substitution concatenate(const QList<Substitution> &parts);
/// The actions a value stands for in an action position; unknown values become Unresolved.
QList<LaunchAction> toActions(const Value &value);
/// True when a value is or contains actions (a LaunchDescription counts even when empty).
bool holdsActions(const Value &value);
/// Removes line breaks and repeated blanks, for expressions shown on one line.
QString oneLine(const QString &text);

} // namespace rosarch::pylaunch
