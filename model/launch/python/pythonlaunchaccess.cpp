// Names, attributes, subscripts, comprehensions and calls of the launch-file evaluator.
#include "pythonlaunchevaluator.h"

#include <functional>

namespace rosarch::pylaunch {

namespace {
constexpr int kMaxComprehensionItems = 256;
} // namespace

Value PythonLaunchEvaluator::lookup(TSNode identifier)
{
    const QString name = m_tree.text(identifier);
    if (const Value *v = m_frame->scope->lookup(name))
        return *v;
    if (name == QLatin1String("__file__")) {
        Substitution s;
        s.kind = Substitution::Kind::ThisLaunchFile;
        return Value::substitution(s);
    }
    Value m = Value::module(name); // a builtin, or a name the reader does not know
    m.evidence = m_tree.evidence(identifier);
    return m;
}

Value PythonLaunchEvaluator::evalSubscript(TSNode n)
{
    using T = Value::Type;
    const Value object = eval(ts::field(n, "value"));
    TSNode keyNode = ts::field(n, "subscript");
    if (ts::is(keyNode, "slice")) {
        if (object.type != T::List && object.type != T::String)
            return unknownAt(n);
        bool colonSeen = false;
        std::optional<double> lo, hi;
        for (TSNode c : ts::children(keyNode)) {
            if (ts::is(c, ":")) {
                if (colonSeen)
                    return unknownAt(n); // a step
                colonSeen = true;
                continue;
            }
            if (!ts_node_is_named(c))
                continue;
            const Value v = eval(c);
            if (v.type != T::Number)
                return unknownAt(n);
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
        return newList(object.items().mid(from, qMax<qsizetype>(0, to - from)), object.list->tuple);
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
        return Value::substitution(key.type == T::String ? Substitution::configuration(key.text)
                                                         : Substitution::unknown(m_tree.text(n)));
    if (object.type == T::Dict) {
        if (const Value *v = object.dict->find(key))
            return *v;
        return unknownAt(n);
    }
    if ((object.type == T::List || object.type == T::String) && key.type == T::Number) {
        const qsizetype size =
            object.type == T::String ? object.text.size() : object.items().size();
        qsizetype i = qsizetype(key.number);
        if (i < 0)
            i += size;
        if (i < 0 || i >= size)
            return unknownAt(n);
        return object.type == T::String ? Value::string(QString(object.text.at(i)))
                                        : object.items().at(i);
    }
    return unknownAt(n);
}

Value PythonLaunchEvaluator::evalAttribute(TSNode n)
{
    using T = Value::Type;
    const Value object = eval(ts::field(n, "object"));
    const QString attribute = m_tree.text(ts::field(n, "attribute"));
    if (object.type == T::Module) {
        Value m = Value::module(object.text + QLatin1Char('.') + attribute);
        m.evidence = m_tree.evidence(n);
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
    return unknownAt(n);
}

Value PythonLaunchEvaluator::evalComprehension(TSNode n)
{
    TSNode body = ts::field(n, "body");
    QList<TSNode> clauses;
    for (TSNode c : ts::namedChildren(n))
        if (ts::is(c, "for_in_clause") || ts::is(c, "if_clause"))
            clauses << c;
    const bool isDict = ts::is(n, "dictionary_comprehension");
    Value out = isDict ? newDict() : newList({});
    const std::shared_ptr<Scope> saved = m_frame->scope;
    m_frame->scope = newScope(saved);
    bool failed = false;
    int produced = 0;
    std::function<void(qsizetype)> generate = [&](qsizetype i) {
        if (failed || m_exhausted || produced > kMaxComprehensionItems)
            return;
        if (i == clauses.size()) {
            if (++produced > kMaxComprehensionItems)
                return;
            if (isDict)
                out.dict->set(eval(ts::field(body, "key")), eval(ts::field(body, "value")));
            else
                append(out, eval(body));
            return;
        }
        TSNode clause = clauses.at(i);
        if (ts::is(clause, "if_clause")) {
            const std::optional<bool> truth = eval(ts_node_named_child(clause, 0)).truth();
            if (!truth || *truth) // undecidable filters keep the item (best guess)
                generate(i + 1);
            return;
        }
        bool known = false;
        const QList<Value> items = iterate(eval(ts::fieldChildren(clause, "right").empty()
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
            assign(ts::field(clause, "left"), item);
            generate(i + 1);
        }
    };
    generate(0);
    m_frame->scope = saved;
    return failed ? unknownAt(n) : out;
}

PythonLaunchEvaluator::CallArgs PythonLaunchEvaluator::evalArguments(TSNode call)
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
            args.keywords.append({m_tree.text(ts::field(c, "name")), eval(value)});
            args.keywordNodes << value;
        } else if (t == "list_splat") {
            const Value v = eval(ts_node_named_child(c, 0));
            bool known = false;
            const QList<Value> items = iterate(v, &known);
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

Value PythonLaunchEvaluator::evalCall(TSNode n)
{
    TSNode function = ts::field(n, "function");
    Value callee;
    if (ts::is(function, "attribute")) {
        const Value object = eval(ts::field(function, "object"));
        const QString method = m_tree.text(ts::field(function, "attribute"));
        if (object.type != Value::Type::Module)
            return callMethod(object, method, evalArguments(n), n);
        callee = Value::module(object.text + QLatin1Char('.') + method);
    } else {
        callee = eval(function);
    }
    if (callee.type == Value::Type::Function)
        return callFunction(callee, evalArguments(n), n);
    if (callee.type != Value::Type::Module)
        return unknownAt(n);
    const CallArgs args = evalArguments(n);
    std::optional<Value> v = callBuiltin(callee.text, args, n);
    if (!v)
        v = callLaunchApi(callee.text.section(QLatin1Char('.'), -1), args, n);
    if (!v)
        return unknownAt(n);
    if (v->type == Value::Type::Unknown && !v->evidence.isValid())
        v->evidence = m_tree.evidence(n); // an Unresolved action made from it points at the call
    return *v;
}

const Value *PythonLaunchEvaluator::CallArgs::get(int index,
                                                  std::initializer_list<const char *> names) const
{
    for (const char *name : names)
        for (const auto &k : keywords)
            if (k.first == QLatin1String(name))
                return &k.second;
    if (index >= 0 && index < positional.size())
        return &positional.at(index);
    return nullptr;
}

TSNode PythonLaunchEvaluator::CallArgs::node(int index,
                                             std::initializer_list<const char *> names) const
{
    for (const char *name : names)
        for (qsizetype k = 0; k < keywords.size(); ++k)
            if (keywords.at(k).first == QLatin1String(name))
                return keywordNodes.value(k);
    if (index >= 0 && index < positionalNodes.size())
        return positionalNodes.at(index);
    return TSNode{};
}

} // namespace rosarch::pylaunch
