// Expression evaluation of the launch-file evaluator: names, literals, strings, containers,
// operators, attributes, subscripts and comprehensions. Calls go to the interpreter.
#include "launch/python/pythonlaunchexpressions.h"
#include "launch/python/pythonlaunchbuiltins.h"
#include "launch/python/pythonlaunchevaluator.h"
#include "launch/python/pythonlaunchoperators.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace rosarch::pylaunch {

namespace {
constexpr int kMaxExpressionDepth = 200;
constexpr qsizetype kMaxStringSize = 1 << 20;
constexpr qsizetype kMaxParts = 10000;
constexpr int kMaxComprehensionItems = 256;
} // namespace

PythonLaunchExpressions::PythonLaunchExpressions(PythonLaunchContext &ctx,
                                                 PythonLaunchEvaluator &interpreter,
                                                 PythonLaunchBuiltins &builtins)
    : m_ctx(ctx), m_interpreter(interpreter), m_builtins(builtins)
{
}

CallArgs PythonLaunchExpressions::evalArguments(TSNode call)
{
    CallArgs args;
    TSNode list = ts::field(call, "arguments");
    if (ts::is(list, "generator_expression")) {
        args.positional << eval(list);
        args.positionalNodes << list;
        return args;
    }
    for (TSNode c : ts::namedChildren(list)) {
        const std::string_view t = ts::type(c);
        if (t == "comment")
            continue;
        if (t == "keyword_argument") {
            TSNode value = ts::field(c, "value");
            args.keywords.append({m_ctx.tree.text(ts::field(c, "name")), eval(value)});
            args.keywordNodes << value;
        } else if (t == "list_splat") {
            const Value v = eval(ts_node_named_child(c, 0));
            bool known = false;
            const QList<Value> items = m_ctx.iterate(v, &known);
            for (const Value &item : known ? items : QList<Value>{v}) {
                args.positional << item;
                args.positionalNodes << c;
            }
        } else if (t == "dictionary_splat") {
            const Value v = eval(ts_node_named_child(c, 0));
            if (v.type == Value::Type::Dict)
                for (const auto &e : v.dict->entries)
                    if (e.first.type == Value::Type::String) {
                        args.keywords.append({e.first.text, e.second});
                        args.keywordNodes << c;
                    }
        } else {
            args.positional << eval(c);
            args.positionalNodes << c;
        }
    }
    return args;
}

Value PythonLaunchExpressions::eval(TSNode node)
{
    if (ts::isNull(node))
        return Value::unknown(QString());
    if (m_ctx.exprDepth >= kMaxExpressionDepth) {
        m_ctx.tooDeep = true;
        return m_ctx.unknownAt(node);
    }
    if (!m_ctx.step(node))
        return m_ctx.unknownAt(node);
    ++m_ctx.exprDepth;
    Value v = evalNode(node);
    --m_ctx.exprDepth;
    return v;
}

Value PythonLaunchExpressions::evalNode(TSNode n)
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
                const QList<Value> inner = m_ctx.iterate(splat, &known);
                if (known)
                    items += inner;
                else
                    items << splat;
                continue;
            }
            items << eval(c);
        }
        // A set iterates in hash order, which for strings changes from run to run.
        m_ctx.approximate = m_ctx.approximate || (t == "set" && items.size() > 1);
        return m_ctx.newList(items, t == "tuple" || t == "expression_list");
    }
    if (t == "parenthesized_expression") {
        for (TSNode c : ts::namedChildren(n))
            if (!ts::is(c, "comment"))
                return eval(c);
        return m_ctx.unknownAt(n);
    }
    if (t == "dictionary") {
        Value d = m_ctx.newDict();
        d.text = m_ctx.tree.text(n);
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
        const std::string_view op = m_ctx.tree.view(ts::field(n, "operator"));
        // An integer as Python prints it (-0 is 0); any other number as written, negated.
        const auto integer = [](const QString &text) {
            return std::all_of(text.cbegin(), text.cend(), [](QChar c) { return c.isDigit(); });
        };
        if (v.type == Value::Type::Number && op == "-" && integer(v.text))
            return Value::number_(-v.number);
        if (v.type == Value::Type::Number && op == "-")
            return Value::number_(-v.number, v.text.startsWith(QLatin1Char('-'))
                                                 ? v.text.mid(1)
                                                 : QLatin1Char('-') + v.text);
        if (v.type == Value::Type::Number && op == "+")
            return v;
        return m_ctx.unknownAt(n);
    }
    if (t == "boolean_operator")
        return evalBoolean(n);
    if (t == "not_operator") {
        const std::optional<bool> truth = eval(ts::field(n, "argument")).truth();
        return truth ? Value::boolean_(!*truth) : m_ctx.unknownAt(n);
    }
    if (t == "comparison_operator")
        return evalComparison(n);
    if (t == "conditional_expression") {
        const std::vector<TSNode> c = ts::namedChildren(n);
        if (c.size() < 3)
            return m_ctx.unknownAt(n);
        const std::optional<bool> truth = eval(c[1]).truth();
        // Undecidable: the first alternative is the best guess.
        m_ctx.approximate = m_ctx.approximate || !truth;
        return (!truth || *truth) ? eval(c[0]) : eval(c[2]);
    }
    if (t == "call")
        return m_interpreter.evalCall(n);
    if (t == "attribute")
        return evalAttribute(n);
    if (t == "subscript")
        return evalSubscript(n);
    if (t == "lambda") {
        Value f;
        f.type = Value::Type::Function;
        f.node = n;
        f.closure = m_ctx.frame->scope;
        f.text = QStringLiteral("lambda");
        return f;
    }
    if (t == "named_expression") {
        const Value v = eval(ts::field(n, "value"));
        m_interpreter.assign(ts::field(n, "name"), v);
        return v;
    }
    if (t == "await")
        return eval(ts_node_named_child(n, 0));
    return m_ctx.unknownAt(n);
}

Value PythonLaunchExpressions::evalString(TSNode n)
{
    bool raw = false, formatted = false;
    QList<Substitution> parts;
    for (TSNode c : ts::namedChildren(n)) {
        const std::string_view t = ts::type(c);
        if (t == "string_start") {
            const std::string_view prefix = m_ctx.tree.view(c);
            raw = prefix.find_first_of("rR") != std::string_view::npos;
            formatted = prefix.find_first_of("fF") != std::string_view::npos;
        } else if (t == "string_content") {
            QString text = m_ctx.tree.text(c);
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

Value PythonLaunchExpressions::evalNumber(TSNode n)
{
    QString text = m_ctx.tree.text(n);
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
    return ok ? Value::number_(value, text) : m_ctx.unknownAt(n);
}

Value PythonLaunchExpressions::evalBinary(TSNode n)
{
    using T = Value::Type;
    const Value a = eval(ts::field(n, "left"));
    const Value b = eval(ts::field(n, "right"));
    const std::string_view op = m_ctx.tree.view(ts::field(n, "operator"));
    const bool numbers =
        (a.type == T::Number || a.type == T::Bool) && (b.type == T::Number || b.type == T::Bool);
    const double x = a.type == T::Bool ? a.boolean : a.number;
    const double y = b.type == T::Bool ? b.boolean : b.number;
    if (op == "+") {
        if (numbers)
            return Value::number_(x + y);
        if (a.type == T::List && b.type == T::List) {
            if (a.list->items.size() + b.list->items.size() > kMaxListSize)
                return m_ctx.unknownAt(n);
            Value out = m_ctx.newList({}, a.list->tuple);
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
                return m_ctx.unknownAt(n);
            return Value::substitution(concatenate({x, y}));
        }
        return m_ctx.unknownAt(n);
    }
    if (op == "%" && a.type == T::String) {
        bool known = false;
        QList<Value> args = b.type == T::List ? m_ctx.iterate(b, &known) : QList<Value>{b};
        return m_builtins.formatString(a.text, args, {}, true, n);
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
        m_ctx.approximate = m_ctx.approximate || y > times;
        if ((a.type == T::String ? a.text.size() : a.list->items.size()) * times >
            (a.type == T::String ? kMaxStringSize : kMaxListSize))
            return m_ctx.unknownAt(n);
        if (a.type == T::String)
            return Value::string(a.text.repeated(times));
        QList<Value> items;
        for (int i = 0; i < times; ++i)
            items += a.items();
        return m_ctx.newList(items, a.list->tuple);
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
    return m_ctx.unknownAt(n);
}

Value PythonLaunchExpressions::evalBoolean(TSNode n)
{
    const Value a = eval(ts::field(n, "left"));
    const bool isAnd = m_ctx.tree.view(ts::field(n, "operator")) == "and";
    const std::optional<bool> ta = a.truth();
    if (ta.has_value())
        return (*ta == isAnd) ? eval(ts::field(n, "right")) : a;
    const Value b = eval(ts::field(n, "right"));
    const std::optional<bool> tb = b.truth();
    // `x or True` is true and `x and False` is false, whatever x is; its value is a guess.
    if (tb.has_value() && *tb != isAnd) {
        m_ctx.approximate = true;
        return b;
    }
    return m_ctx.unknownAt(n);
}

Value PythonLaunchExpressions::evalComparison(TSNode n)
{
    QList<Value> operands;
    for (TSNode c : ts::namedChildren(n))
        if (!ts::is(c, "comment"))
            operands << eval(c);
    const std::vector<TSNode> ops = ts::fieldChildren(n, "operators");
    if (operands.size() != qsizetype(ops.size()) + 1)
        return m_ctx.unknownAt(n);
    for (size_t i = 0; i < ops.size(); ++i) {
        const std::optional<bool> r =
            compare(ts::type(ops[i]), operands.at(qsizetype(i)), operands.at(qsizetype(i) + 1));
        if (!r)
            return m_ctx.unknownAt(n);
        if (!*r)
            return Value::boolean_(false);
    }
    return Value::boolean_(true);
}

Value PythonLaunchExpressions::lookup(TSNode identifier)
{
    const QString name = m_ctx.tree.text(identifier);
    if (const Value *v = m_ctx.frame->scope->lookup(name))
        return *v;
    if (name == QLatin1String("__file__")) {
        Substitution s;
        s.kind = Substitution::Kind::ThisLaunchFile;
        return Value::substitution(s);
    }
    Value m = Value::module(name); // a builtin, or a name the reader does not know
    m.evidence = m_ctx.tree.evidence(identifier);
    return m;
}

Value PythonLaunchExpressions::evalSubscript(TSNode n)
{
    using T = Value::Type;
    const Value object = eval(ts::field(n, "value"));
    TSNode keyNode = ts::field(n, "subscript");
    if (ts::is(keyNode, "slice")) {
        if (object.type != T::List && object.type != T::String)
            return m_ctx.unknownAt(n);
        bool colonSeen = false;
        std::optional<double> lo, hi;
        for (TSNode c : ts::children(keyNode)) {
            if (ts::is(c, ":")) {
                if (colonSeen)
                    return m_ctx.unknownAt(n); // a step
                colonSeen = true;
                continue;
            }
            if (!ts_node_is_named(c))
                continue;
            const Value v = eval(c);
            if (v.type != T::Number)
                return m_ctx.unknownAt(n);
            (colonSeen ? hi : lo) = v.number;
        }
        const qsizetype size =
            object.type == T::String ? object.text.size() : object.items().size();
        auto clamp = [&](std::optional<double> b, qsizetype dflt) {
            if (!b)
                return dflt;
            qsizetype i = qsizetype(*b);
            if (i < 0)
                i += size;
            return qBound<qsizetype>(0, i, size);
        };
        const qsizetype from = clamp(lo, 0), to = clamp(hi, size);
        if (object.type == T::String)
            return Value::string(object.text.mid(from, qMax<qsizetype>(0, to - from)));
        return m_ctx.newList(object.items().mid(from, qMax<qsizetype>(0, to - from)),
                             object.list->tuple);
    }
    const Value key = eval(keyNode);
    if (object.type == T::Module && object.text == QLatin1String("os.environ") &&
        key.type == T::String) {
        Substitution env;
        env.kind = Substitution::Kind::EnvironmentVariable;
        env.text = key.text;
        return Value::substitution(env);
    }
    if (object.type == T::Context && object.text == QLatin1String("launch_configurations"))
        return Value::substitution(key.type == T::String
                                       ? Substitution::configuration(key.text)
                                       : Substitution::unknown(m_ctx.tree.text(n)));
    if (object.type == T::Dict) {
        if (const Value *v = object.dict->find(key))
            return *v;
        return m_ctx.unknownAt(n);
    }
    if ((object.type == T::List || object.type == T::String) && key.type == T::Number) {
        const qsizetype size =
            object.type == T::String ? object.text.size() : object.items().size();
        qsizetype i = qsizetype(key.number);
        if (i < 0)
            i += size;
        if (i < 0 || i >= size)
            return m_ctx.unknownAt(n);
        return object.type == T::String ? Value::string(QString(object.text.at(i)))
                                        : object.items().at(i);
    }
    return m_ctx.unknownAt(n);
}

Value PythonLaunchExpressions::evalAttribute(TSNode n)
{
    using T = Value::Type;
    const Value object = eval(ts::field(n, "object"));
    const QString attribute = m_ctx.tree.text(ts::field(n, "attribute"));
    if (object.type == T::Module) {
        Value m = Value::module(object.text + QLatin1Char('.') + attribute);
        m.evidence = m_ctx.tree.evidence(n);
        return m;
    }
    if (object.type == T::Context && object.text.isEmpty() &&
        attribute == QLatin1String("launch_configurations")) {
        Value c = object;
        c.text = attribute;
        return c;
    }
    if (attribute == QLatin1String("parent")) {
        if (object.type == T::Subst && object.subst.kind == Substitution::Kind::ThisLaunchFile) {
            Substitution dir;
            dir.kind = Substitution::Kind::ThisLaunchFileDir;
            return Value::substitution(dir);
        }
        if (object.type == T::String && object.text.contains(QLatin1Char('/')))
            return Value::string(object.text.section(QLatin1Char('/'), 0, -2));
    }
    if (object.type == T::List && object.list->launchDescription &&
        attribute == QLatin1String("entities"))
        return object;
    return m_ctx.unknownAt(n);
}

Value PythonLaunchExpressions::evalComprehension(TSNode n)
{
    TSNode body = ts::field(n, "body");
    QList<TSNode> clauses;
    for (TSNode c : ts::namedChildren(n))
        if (ts::is(c, "for_in_clause") || ts::is(c, "if_clause"))
            clauses << c;
    const bool isDict = ts::is(n, "dictionary_comprehension");
    Value out = isDict ? m_ctx.newDict() : m_ctx.newList({});
    const std::shared_ptr<Scope> saved = m_ctx.frame->scope;
    m_ctx.frame->scope = m_ctx.newScope(saved);
    bool failed = false;
    int produced = 0;
    std::function<void(qsizetype)> generate = [&](qsizetype i) {
        if (failed || m_ctx.exhausted || produced > kMaxComprehensionItems)
            return;
        if (i == clauses.size()) {
            if (++produced > kMaxComprehensionItems) {
                m_ctx.approximate = true;
                return;
            }
            if (isDict)
                out.dict->set(eval(ts::field(body, "key")), eval(ts::field(body, "value")));
            else
                m_ctx.append(out, eval(body));
            return;
        }
        TSNode clause = clauses.at(i);
        if (ts::is(clause, "if_clause")) {
            const std::optional<bool> truth = eval(ts_node_named_child(clause, 0)).truth();
            m_ctx.approximate = m_ctx.approximate || !truth;
            if (!truth || *truth) // undecidable filters keep the item (best guess)
                generate(i + 1);
            return;
        }
        bool known = false;
        const QList<Value> items =
            m_ctx.iterate(eval(ts::fieldChildren(clause, "right").empty()
                                   ? TSNode{}
                                   : ts::fieldChildren(clause, "right").front()),
                          &known);
        if (!known) {
            failed = true;
            return;
        }
        for (const Value &item : items) {
            if (produced > kMaxComprehensionItems)
                break;
            m_interpreter.assign(ts::field(clause, "left"), item);
            generate(i + 1);
        }
    };
    generate(0);
    m_ctx.frame->scope = saved;
    return failed ? m_ctx.unknownAt(n) : out;
}

} // namespace rosarch::pylaunch
