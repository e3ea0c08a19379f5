#pragma once

#include "nodes/cpp/cppfacts.h"
#include "syntax/cppmacro.h"
#include "syntax/cppsyntax.h"
#include "syntax/syntaxtree.h"

#include <QHash>
#include <QList>
#include <QPair>
#include <QSet>
#include <QString>

#include <vector>

namespace rosarch {

/// A local variable of the function being read, as far as it has been seen.
struct CppLocal
{
    QString type;
    TSNode value{};    ///< latest value (initializer or assignment)
    QString parameter; ///< bound through get_parameter("p", local)
    /// `value` is a for loop's initial value, no value of the variable in the body. Kept with
    /// the value: finding it walks up the tree, and a local is read far more often than set.
    bool loopInitial = false;
    /// Declared without a value and then handed to `outCall(...)` as argument `outIndex`: the
    /// function may fill it through a reference parameter.
    QString outCall;
    int outIndex = -1;
    /// A range-for variable: `value` is the container it walks, each element in turn.
    bool element = false;
    /// `topic = joinWithParentNamespace(topic)`: `value` joined to the parent namespace.
    bool parentJoined = false;
    /// `settings.topic = "scan";` on a struct local: the fields set, in order.
    QList<QPair<QString, TSNode>> fields;

    void setValue(TSNode v);
    /// With `loopInitial` known (CppFunctionExtractor finds it from the path it walked).
    void setValue(TSNode v, bool isLoopInitial)
    {
        value = v;
        loopInitial = isLoopInitial;
    }
};

/// navigation2's `Layer::joinWithParentNamespace(topic)`.
inline constexpr char kJoinWithParentNamespace[] = "joinWithParentNamespace";

/// `inner` joined to the parent of the node's namespace (RosNames::withParentNamespace).
CppValue joinedWithParentNamespace(CppValue inner);

/// What an expression refers to, seen from inside its function: a literal, a local holding
/// one, a declared parameter, a member, a function parameter, the node itself.
class CppValueEvaluator
{
public:
    /// Reads `locals` and `function` as they are when asked (the extractor fills them).
    /// `macros` (may be null): a call of a function-like one that stands for a string is that
    /// string.
    CppValueEvaluator(const SyntaxTree &tree, const QHash<QString, CppLocal> &locals,
                      const CppFunction &function, const CppMacros *macros = nullptr);

    CppValue evaluate(TSNode expression, int depth = 0) const;
    /// What the identifier `name` holds at this point of the function.
    CppValue evaluateIdentifier(const QString &name, int depth) const;
    /// The first of the leading arguments that is a literal parameter name (`parameter`), or -1.
    int literalParameterIndex(const std::vector<TSNode> &args, QString *parameter,
                              int depth = 0) const;
    /// How deep one evaluation may go, through identifiers and calls (they nest a few levels).
    static constexpr int kMaxDepth = 24;

private:
    /// What `name` holds as last bound, without a join the code applies to it afterwards.
    CppValue evaluateBoundIdentifier(const QString &name, int depth) const;
    CppValue evaluateField(TSNode fieldExpression, int depth) const;
    /// `Settings{.topic = "scan"}` (or `{.topic = "scan"}`): an Aggregate; None when the
    /// list designates no field.
    CppValue evaluateAggregate(TSNode list, int depth) const;
    /// The class the elements a range-for variable walks are known to be: a cast of it the
    /// function makes (`dynamic_pointer_cast<CostmapLayer>(layer)`), else its declared type.
    QString elementClass(const QString &variable) const;
    CppValue evaluateStringCall(const cppsyntax::CallShape &shape, const std::vector<TSNode> &args,
                                int depth) const;

    const SyntaxTree &m_tree;
    const QHash<QString, CppLocal> &m_locals;
    const CppFunction &m_function;
    const CppMacros *m_macros = nullptr;
    /// The fields of struct locals being evaluated, against a cycle through them.
    mutable QSet<QString> m_fieldsOnTheWay;
};

} // namespace rosarch
