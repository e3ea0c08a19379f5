// Expression evaluation of the launch-file evaluator: literals, strings, containers and operators.
#include "pythonlaunchevaluator.h"

#include <cmath>

namespace rosarch::pylaunch {

namespace {
constexpr int kMaxExpressionDepth = 200;
constexpr int kMaxIteratedChars = 256;
constexpr qsizetype kMaxListSize = 10000;
constexpr qsizetype kMaxStringSize = 1 << 20;
constexpr qsizetype kMaxParts = 10000;

QString decodeEscapes(const QString &s)
{
    if (!s.contains(QLatin1Char('\\')))
        return s;
    QString out;
    out.reserve(s.size());
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s.at(i);
        if (c != QLatin1Char('\\') || i + 1 >= s.size()) {
            out += c;
            continue;
        }
        const QChar n = s.at(++i);
        switch (n.unicode()) {
        case 'n':
            out += QLatin1Char('\n');
            break;
        case 't':
            out += QLatin1Char('\t');
            break;
        case 'r':
            out += QLatin1Char('\r');
            break;
        case '\\':
            out += QLatin1Char('\\');
            break;
        case '\'':
            out += QLatin1Char('\'');
            break;
        case '"':
            out += QLatin1Char('"');
            break;
        case '\n':
            break; // line continuation
        default:
            out += QLatin1Char('\\');
            out += n;
        }
    }
    return out;
}

/// The text a value contributes to a string (f-string, str(), format): literals as Python prints
/// them.
Substitution asText(const Value &v)
{
    if (const auto literal = v.literalText())
        return Substitution::literal(*literal);
    return v.toSubstitution();
}

std::optional<bool> compare(std::string_view op, const Value &a, const Value &b)
{
    using T = Value::Type;
    if (op == "==" || op == "!=") {
        std::optional<bool> eq;
        if (a.isLiteral() && b.isLiteral())
            eq = a.sameLiteral(b);
        else if (a.type == T::Subst && b.type == T::Subst && a.subst == b.subst)
            eq = true;
        else if ((a.type == T::None) != (b.type == T::None) &&
                 (a.type == T::List || b.type == T::List || a.type == T::Dict ||
                  b.type == T::Dict || a.type == T::Action || b.type == T::Action))
            eq = false;
        if (!eq)
            return std::nullopt;
        return op == "==" ? *eq : !*eq;
    }
    if (op == "is" || op == "is not") {
        std::optional<bool> same;
        if (a.type == T::None || b.type == T::None) {
            const Value &other = a.type == T::None ? b : a;
            if (other.type == T::None)
                same = true;
            else if (other.type != T::Unknown && other.type != T::Module &&
                     other.type != T::Context)
                same = false;
        } else if (a.type == T::Bool && b.type == T::Bool) {
            same = a.boolean == b.boolean;
        }
        if (!same)
            return std::nullopt;
        return op == "is" ? *same : !*same;
    }
    if (op == "in" || op == "not in") {
        std::optional<bool> found;
        if (b.type == T::List && (a.isLiteral() || a.type == T::Subst)) {
            bool decided = true;
            found = false;
            for (const Value &item : b.items()) {
                if (a.sameLiteral(item)) {
                    found = true;
                    break;
                }
                if (!item.isLiteral())
                    decided = false;
            }
            if (!*found && !decided)
                found.reset();
        } else if (b.type == T::Dict && a.isLiteral()) {
            found = b.dict->find(a) != nullptr;
        } else if (b.type == T::String && a.type == T::String) {
            found = b.text.contains(a.text);
        }
        if (!found)
            return std::nullopt;
        return op == "in" ? *found : !*found;
    }
    if ((a.type == T::Number || a.type == T::Bool) && (b.type == T::Number || b.type == T::Bool)) {
        const double x = a.type == T::Bool ? a.boolean : a.number;
        const double y = b.type == T::Bool ? b.boolean : b.number;
        if (op == "<")
            return x < y;
        if (op == "<=")
            return x <= y;
        if (op == ">")
            return x > y;
        if (op == ">=")
            return x >= y;
    }
    if (a.type == T::String && b.type == T::String) {
        const int c = a.text.compare(b.text);
        if (op == "<")
            return c < 0;
        if (op == "<=")
            return c <= 0;
        if (op == ">")
            return c > 0;
        if (op == ">=")
            return c >= 0;
    }
    return std::nullopt;
}
} // namespace

Value PythonLaunchEvaluator::unknownAt(TSNode node) const
{
    return Value::unknown(m_tree.text(node), m_tree.evidence(node));
}

Value PythonLaunchEvaluator::newList(QList<Value> items, bool tuple)
{
    Value v = Value::makeList(std::move(items), tuple);
    v.list->createdUnder = m_guards;
    m_lists.push_back(v.list);
    return v;
}

Value PythonLaunchEvaluator::newDict()
{
    Value v = Value::makeDict();
    v.dict->createdUnder = m_guards;
    m_dicts.push_back(v.dict);
    return v;
}

std::shared_ptr<Scope> PythonLaunchEvaluator::newScope(std::shared_ptr<Scope> parent)
{
    auto scope = std::make_shared<Scope>();
    scope->parent = std::move(parent);
    m_scopes.push_back(scope);
    return scope;
}

void PythonLaunchEvaluator::append(const Value &list, const Value &item)
{
    if (list.type != Value::Type::List || list.list->items.size() >= kMaxListSize)
        return;
    list.list->items << item;
    list.list->guards << relativeGuards(list.list->createdUnder, m_guards);
}

QList<Value> PythonLaunchEvaluator::iterate(const Value &value, bool *known) const
{
    *known = true;
    switch (value.type) {
    case Value::Type::List:
        return value.items();
    case Value::Type::Dict: {
        QList<Value> keys;
        for (const auto &e : value.dict->entries)
            keys << e.first;
        return keys;
    }
    case Value::Type::String: {
        QList<Value> chars;
        for (QChar c : value.text.left(kMaxIteratedChars))
            chars << Value::string(QString(c));
        return chars;
    }
    default:
        *known = false;
        return {};
    }
}

Value PythonLaunchEvaluator::eval(TSNode node)
{
    if (ts::isNull(node))
        return Value::unknown(QString());
    if (m_exprDepth >= kMaxExpressionDepth || !step())
        return unknownAt(node);
    ++m_exprDepth;
    Value v = evalNode(node);
    --m_exprDepth;
    return v;
}

Value PythonLaunchEvaluator::evalNode(TSNode n)
{
    const std::string_view t = ts::type(n);
    if (t == "identifier")
        return lookup(n);
    if (t == "string")
        return evalString(n);
    if (t == "concatenated_string") {
        QList<Substitution> parts;
        for (TSNode s : ts::namedChildren(n))
            if (ts::is(s, "string"))
                parts << eval(s).toSubstitution();
        return Value::substitution(concatenate(parts));
    }
    if (t == "integer" || t == "float")
        return evalNumber(n);
    if (t == "true" || t == "false")
        return Value::boolean_(t == "true");
    if (t == "none")
        return Value::none();
    if (t == "list" || t == "set" || t == "tuple" || t == "expression_list") {
        QList<Value> items;
        for (TSNode c : ts::namedChildren(n)) {
            if (ts::is(c, "comment"))
                continue;
            if (ts::is(c, "list_splat")) {
                const Value splat = eval(ts_node_named_child(c, 0));
                bool known = false;
                const QList<Value> inner = iterate(splat, &known);
                if (known)
                    items += inner;
                else
                    items << splat;
                continue;
            }
            items << eval(c);
        }
        return newList(items, t == "tuple" || t == "expression_list");
    }
    if (t == "parenthesized_expression") {
        for (TSNode c : ts::namedChildren(n))
            if (!ts::is(c, "comment"))
                return eval(c);
        return unknownAt(n);
    }
    if (t == "dictionary") {
        Value d = newDict();
        d.text = m_tree.text(n);
        for (TSNode c : ts::namedChildren(n)) {
            if (ts::is(c, "pair")) {
                d.dict->set(eval(ts::field(c, "key")), eval(ts::field(c, "value")));
            } else if (ts::is(c, "dictionary_splat")) {
                const Value other = eval(ts_node_named_child(c, 0));
                if (other.type == Value::Type::Dict)
                    for (const auto &e : other.dict->entries)
                        d.dict->set(e.first, e.second);
            }
        }
        return d;
    }
    if (t == "list_comprehension" || t == "generator_expression" || t == "set_comprehension" ||
        t == "dictionary_comprehension")
        return evalComprehension(n);
    if (t == "binary_operator")
        return evalBinary(n);
    if (t == "unary_operator") {
        const Value v = eval(ts::field(n, "argument"));
        const std::string_view op = m_tree.view(ts::field(n, "operator"));
        if (v.type == Value::Type::Number && op == "-")
            return Value::number_(-v.number, v.text.startsWith(QLatin1Char('-'))
                                                 ? v.text.mid(1)
                                                 : QLatin1Char('-') + v.text);
        if (v.type == Value::Type::Number && op == "+")
            return v;
        return unknownAt(n);
    }
    if (t == "boolean_operator")
        return evalBoolean(n);
    if (t == "not_operator") {
        const std::optional<bool> truth = eval(ts::field(n, "argument")).truth();
        return truth ? Value::boolean_(!*truth) : unknownAt(n);
    }
    if (t == "comparison_operator")
        return evalComparison(n);
    if (t == "conditional_expression") {
        const std::vector<TSNode> c = ts::namedChildren(n);
        if (c.size() < 3)
            return unknownAt(n);
        const std::optional<bool> truth = eval(c[1]).truth();
        // Undecidable: the first alternative is the best guess.
        return (!truth || *truth) ? eval(c[0]) : eval(c[2]);
    }
    if (t == "call")
        return evalCall(n);
    if (t == "attribute")
        return evalAttribute(n);
    if (t == "subscript")
        return evalSubscript(n);
    if (t == "lambda") {
        Value f;
        f.type = Value::Type::Function;
        f.node = n;
        f.closure = m_frame->scope;
        f.text = QStringLiteral("lambda");
        return f;
    }
    if (t == "named_expression") {
        const Value v = eval(ts::field(n, "value"));
        assign(ts::field(n, "name"), v);
        return v;
    }
    if (t == "await")
        return eval(ts_node_named_child(n, 0));
    return unknownAt(n);
}

Value PythonLaunchEvaluator::evalString(TSNode n)
{
    bool raw = false, formatted = false;
    QList<Substitution> parts;
    for (TSNode c : ts::namedChildren(n)) {
        const std::string_view t = ts::type(c);
        if (t == "string_start") {
            const std::string_view prefix = m_tree.view(c);
            raw = prefix.find_first_of("rR") != std::string_view::npos;
            formatted = prefix.find_first_of("fF") != std::string_view::npos;
        } else if (t == "string_content") {
            QString text = m_tree.text(c);
            if (!raw)
                text = decodeEscapes(text);
            if (formatted)
                text.replace(QStringLiteral("{{"), QStringLiteral("{"))
                    .replace(QStringLiteral("}}"), QStringLiteral("}"));
            parts << Substitution::literal(text);
        } else if (t == "interpolation") {
            parts << asText(eval(ts::field(c, "expression")));
        }
    }
    return Value::substitution(concatenate(parts));
}

Value PythonLaunchEvaluator::evalNumber(TSNode n)
{
    QString text = m_tree.text(n);
    text.remove(QLatin1Char('_'));
    bool ok = false;
    double value = 0;
    if (ts::is(n, "integer")) {
        if (text.startsWith(QLatin1String("0o"), Qt::CaseInsensitive))
            value = double(text.mid(2).toLongLong(&ok, 8));
        else if (text.startsWith(QLatin1String("0b"), Qt::CaseInsensitive))
            value = double(text.mid(2).toLongLong(&ok, 2));
        else
            value = double(text.toLongLong(&ok, 0));
    } else {
        value = text.toDouble(&ok);
    }
    return ok ? Value::number_(value, text) : unknownAt(n);
}

Value PythonLaunchEvaluator::evalBinary(TSNode n)
{
    using T = Value::Type;
    const Value a = eval(ts::field(n, "left"));
    const Value b = eval(ts::field(n, "right"));
    const std::string_view op = m_tree.view(ts::field(n, "operator"));
    const bool numbers =
        (a.type == T::Number || a.type == T::Bool) && (b.type == T::Number || b.type == T::Bool);
    const double x = a.type == T::Bool ? a.boolean : a.number;
    const double y = b.type == T::Bool ? b.boolean : b.number;
    if (op == "+") {
        if (numbers)
            return Value::number_(x + y);
        if (a.type == T::List && b.type == T::List) {
            if (a.list->items.size() + b.list->items.size() > kMaxListSize)
                return unknownAt(n);
            Value out = newList({}, a.list->tuple);
            for (const Value *src : {&a, &b})
                for (qsizetype i = 0; i < src->list->items.size(); ++i) {
                    out.list->items << src->list->items.at(i);
                    out.list->guards << src->list->guards.value(i);
                }
            return out;
        }
        auto stringish = [](const Value &v) {
            return v.isStringLike() || v.type == T::Unknown || v.type == T::Module;
        };
        if ((a.isStringLike() || b.isStringLike()) && stringish(a) && stringish(b)) {
            const Substitution x = a.toSubstitution(), y = b.toSubstitution();
            if (x.text.size() + y.text.size() > kMaxStringSize ||
                x.parts.size() + y.parts.size() > kMaxParts)
                return unknownAt(n);
            return Value::substitution(concatenate({x, y}));
        }
        return unknownAt(n);
    }
    if (op == "%" && a.type == T::String) {
        bool known = false;
        QList<Value> args = b.type == T::List ? iterate(b, &known) : QList<Value>{b};
        return formatString(a.text, args, {}, true, n);
    }
    if (op == "/" && (a.isStringLike() || a.type == T::Source) &&
        (b.isStringLike() || b.type == T::Unknown)) {
        // pathlib / launch substitutions: '/' joins paths
        if (a.type == T::String && b.type == T::String)
            return Value::string(
                b.text.startsWith(QLatin1Char('/')) ? b.text : a.text + QLatin1Char('/') + b.text);
        Substitution join;
        join.kind = Substitution::Kind::PathJoin;
        const Substitution left = a.toSubstitution();
        if (left.kind == Substitution::Kind::PathJoin)
            join.parts = left.parts;
        else
            join.parts << left;
        join.parts << b.toSubstitution();
        return Value::substitution(join);
    }
    if (op == "*" && (a.type == T::List || a.type == T::String) && b.type == T::Number) {
        const int times = qBound(0, int(y), 64);
        if ((a.type == T::String ? a.text.size() : a.list->items.size()) * times >
            (a.type == T::String ? kMaxStringSize : kMaxListSize))
            return unknownAt(n);
        if (a.type == T::String)
            return Value::string(a.text.repeated(times));
        QList<Value> items;
        for (int i = 0; i < times; ++i)
            items += a.items();
        return newList(items, a.list->tuple);
    }
    if (numbers) {
        if (op == "-")
            return Value::number_(x - y);
        if (op == "*")
            return Value::number_(x * y);
        if (op == "/" && y != 0)
            return Value::number_(x / y, QString::number(x / y, 'g', 15));
        if (op == "//" && y != 0)
            return Value::number_(std::floor(x / y));
        if (op == "%" && y != 0)
            return Value::number_(x - y * std::floor(x / y));
    }
    return unknownAt(n);
}

Value PythonLaunchEvaluator::evalBoolean(TSNode n)
{
    const Value a = eval(ts::field(n, "left"));
    const bool isAnd = m_tree.view(ts::field(n, "operator")) == "and";
    const std::optional<bool> ta = a.truth();
    if (ta.has_value())
        return (*ta == isAnd) ? eval(ts::field(n, "right")) : a;
    const Value b = eval(ts::field(n, "right"));
    const std::optional<bool> tb = b.truth();
    // `x or True` is true and `x and False` is false, whatever x is.
    if (tb.has_value() && *tb != isAnd)
        return b;
    return unknownAt(n);
}

Value PythonLaunchEvaluator::evalComparison(TSNode n)
{
    QList<Value> operands;
    for (TSNode c : ts::namedChildren(n))
        if (!ts::is(c, "comment"))
            operands << eval(c);
    const std::vector<TSNode> ops = ts::fieldChildren(n, "operators");
    if (operands.size() != qsizetype(ops.size()) + 1)
        return unknownAt(n);
    for (size_t i = 0; i < ops.size(); ++i) {
        const std::optional<bool> r =
            compare(ts::type(ops[i]), operands.at(qsizetype(i)), operands.at(qsizetype(i) + 1));
        if (!r)
            return unknownAt(n);
        if (!*r)
            return Value::boolean_(false);
    }
    return Value::boolean_(true);
}

} // namespace rosarch::pylaunch
