#include "launch/python/pythonlauncheval.h"

#include "core/valuebudget.h"
#include "launch/python/pythonlaunchevaluator.h"
#include "syntax/syntaxtree.h"

#include <QStringList>

#include <optional>

namespace rosarch {

namespace {

using pylaunch::Value;

/// What writing a value may cost: lists and dicts nest, and may share or hold themselves.
struct TextBudget
{
    int depth = 48;
    int items = 20000;
    qsizetype chars = kMaxValueChars;
};

/// `v` as Python's repr() writes it; nothing for a value that is not plain data, or past the
/// budget.
std::optional<QString> repr(const Value &v, TextBudget &budget, int depth = 0)
{
    using T = Value::Type;
    if (depth > budget.depth || --budget.items < 0)
        return std::nullopt;
    const auto spend = [&](QString text) -> std::optional<QString> {
        budget.chars -= text.size();
        return budget.chars < 0 ? std::nullopt : std::optional<QString>(std::move(text));
    };
    const auto join = [&](const QList<Value> &items) -> std::optional<QString> {
        QStringList parts;
        for (const Value &item : items) {
            const std::optional<QString> part = repr(item, budget, depth + 1);
            if (!part)
                return std::nullopt;
            parts << *part;
        }
        return parts.join(QStringLiteral(", "));
    };
    switch (v.type) {
    case T::String:
        return spend(QLatin1Char('\'') + v.text + QLatin1Char('\''));
    case T::Number:
    case T::Bool:
    case T::None:
        return spend(*v.literalText());
    case T::List: {
        const std::optional<QString> inner = join(v.items());
        if (!inner)
            return std::nullopt;
        if (!v.list->tuple)
            return QLatin1Char('[') + *inner + QLatin1Char(']');
        const bool single = v.items().size() == 1;
        return QLatin1Char('(') + *inner + (single ? QStringLiteral(",)") : QStringLiteral(")"));
    }
    case T::Dict: {
        QStringList entries;
        for (const auto &[key, value] : std::as_const(v.dict->entries)) {
            const std::optional<QString> k = repr(key, budget, depth + 1);
            const std::optional<QString> item = k ? repr(value, budget, depth + 1) : std::nullopt;
            if (!item)
                return std::nullopt;
            entries << *k + QStringLiteral(": ") + *item;
        }
        return QLatin1Char('{') + entries.join(QStringLiteral(", ")) + QLatin1Char('}');
    }
    default:
        return std::nullopt;
    }
}

/// `v` as str() prints it, booleans as launch reads them.
std::optional<QString> text(const Value &v)
{
    if (v.type == Value::Type::String || v.type == Value::Type::Number)
        return v.text;
    if (v.type == Value::Type::Bool)
        return v.boolean ? QStringLiteral("true") : QStringLiteral("false");
    TextBudget budget;
    return repr(v, budget);
}

} // namespace

PythonLaunchEval::Outcome PythonLaunchEval::evaluate(const QString &expression, QString *value)
{
    // Python's eval() strips the blanks around the expression; a line break within is an error.
    const SyntaxTree tree =
        SyntaxTree::parse(SyntaxTree::Grammar::Python, expression.trimmed().toUtf8(), QString());
    const TSNode root = tree.root();
    if (ts::isNull(root) || ts_node_has_error(root) || ts_node_named_child_count(root) != 1)
        return Outcome::Unknown;
    const TSNode statement = ts_node_named_child(root, 0);
    if (!ts::is(statement, "expression_statement") || ts_node_named_child_count(statement) != 1)
        return Outcome::Unknown;
    pylaunch::PythonLaunchEvaluator evaluator(tree);
    // Launch substitutions give booleans as "true" and "false", which the expression then holds.
    const Value v = evaluator.evaluate(ts_node_named_child(statement, 0),
                                       {{QStringLiteral("true"), Value::boolean_(true)},
                                        {QStringLiteral("false"), Value::boolean_(false)}});
    const pylaunch::PythonLaunchContext &context = evaluator.context();
    if (context.tooDeep)
        return Outcome::TooDeep;
    if (context.approximate || context.exhausted)
        return Outcome::Unknown;
    const std::optional<QString> out = text(v);
    if (!out)
        return Outcome::Unknown;
    *value = *out;
    return Outcome::Value;
}

} // namespace rosarch
