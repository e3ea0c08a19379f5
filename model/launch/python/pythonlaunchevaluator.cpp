#include "launch/python/pythonlaunchevaluator.h"

#include "syntax/pythonsyntax.h"

#include <cstring>

namespace rosarch::pylaunch {

namespace {
constexpr int kMaxCallDepth = 12;
constexpr int kMaxIterations = 64;

Evidence spanEvidence(const SyntaxTree &tree, TSNode from, TSNode to)
{
    Evidence e = tree.evidence(from);
    const Evidence end = tree.evidence(to);
    if (end.isValid()) {
        e.endLine = end.endLine;
        e.endColumn = end.endColumn;
    }
    return e;
}

GuardPtr negated(const GuardPtr &g)
{
    auto n = std::make_shared<Guard>(*g);
    n->unless = !g->unless;
    return n;
}

} // namespace

PythonLaunchEvaluator::PythonLaunchEvaluator(const SyntaxTree &tree)
    : m_ctx(tree), m_builtins(m_ctx), m_api(m_ctx, *this), m_expressions(m_ctx, *this, m_builtins)
{
}

QList<LaunchAction> PythonLaunchEvaluator::run()
{
    Frame module;
    module.scope = m_ctx.module;
    m_ctx.frame = &module;
    m_ctx.module->vars.insert(QStringLiteral("__name__"),
                              Value::string(QStringLiteral("__rosarch__")));
    for (TSNode statement : ts::namedChildren(m_ctx.tree.root())) {
        if (m_ctx.stopped())
            break;
        // Module-level calls (main(), launch_testing runners) are not part of the description.
        if (ts::is(statement, "expression_statement") &&
            ts::is(ts_node_named_child(statement, 0), "call"))
            continue;
        execStatement(statement);
    }
    module.returned = false;

    QList<LaunchAction> actions;
    const Value *function = m_ctx.module->lookup(QStringLiteral("generate_launch_description"));
    if (!function || function->type != Value::Type::Function) {
        Diagnostic d;
        d.code = QStringLiteral("no-launch-description");
        d.message =
            QStringLiteral("%1 defines no generate_launch_description().").arg(m_ctx.tree.file());
        d.evidence.file = m_ctx.tree.file();
        m_ctx.diagnostics << d;
        return actions;
    }
    const Value result = callFunction(*function, CallArgs{}, TSNode{});
    if (result.type == Value::Type::List || result.type == Value::Type::Action ||
        result.type == Value::Type::Unknown) {
        actions = toActions(result);
    } else if (!m_ctx.exhausted) {
        Diagnostic d;
        d.code = QStringLiteral("launch-description-unknown");
        d.message =
            QStringLiteral("generate_launch_description() in %1 returns no launch description "
                           "that can be read statically.")
                .arg(m_ctx.tree.file());
        d.evidence = m_ctx.tree.evidence(ts::field(function->node, "name"));
        m_ctx.diagnostics << d;
    }
    if (m_ctx.exhausted) {
        Diagnostic d;
        d.code = QStringLiteral("launch-evaluation-limit");
        d.evidence = ts::isNull(m_ctx.stoppedAt) ? Evidence{m_ctx.tree.file(), 1, 1, 1, 1}
                                                 : m_ctx.tree.evidence(m_ctx.stoppedAt);
        d.evidence.endLine = d.evidence.line; // the place, not the whole statement
        d.message = QStringLiteral("%1 needs more evaluation steps than allowed; evaluation "
                                   "stopped at line %2, so what follows (nodes, includes, "
                                   "arguments) is not in the launch description.")
                        .arg(m_ctx.tree.file())
                        .arg(d.evidence.line);
        m_ctx.diagnostics << d;
    }
    return actions;
}

Value PythonLaunchEvaluator::evaluate(TSNode expression, const QHash<QString, Value> &names)
{
    Frame module;
    module.scope = m_ctx.module;
    module.scope->vars.insert(names);
    m_ctx.frame = &module;
    const Value v = m_expressions.eval(expression);
    m_ctx.frame = nullptr;
    return v;
}

void PythonLaunchEvaluator::execBlock(TSNode block)
{
    for (TSNode statement : ts::namedChildren(block)) {
        if (m_ctx.stopped())
            return;
        execStatement(statement);
    }
}

void PythonLaunchEvaluator::execStatement(TSNode n)
{
    if (!m_ctx.step(n))
        return;
    const std::string_view t = ts::type(n);
    if (t == "expression_statement") {
        TSNode e = ts_node_named_child(n, 0);
        if (ts::is(e, "assignment")) {
            // a = b = value: the innermost right-hand side is evaluated once
            QList<TSNode> targets;
            TSNode right = e;
            while (ts::is(right, "assignment")) {
                targets << ts::field(right, "left");
                right = ts::field(right, "right");
            }
            if (ts::isNull(right))
                return; // a bare annotation
            const Value v = m_expressions.eval(right);
            for (TSNode target : targets)
                assign(target, v);
        } else if (ts::is(e, "augmented_assignment")) {
            TSNode left = ts::field(e, "left");
            const Value current = m_expressions.eval(left);
            const Value right = m_expressions.eval(ts::field(e, "right"));
            const std::string_view op = m_ctx.tree.view(ts::field(e, "operator"));
            if (op == "+=" && current.type == Value::Type::List && !current.list->tuple) {
                bool known = false;
                const QList<Value> items = m_ctx.iterate(right, &known);
                if (known)
                    for (const Value &item : items)
                        m_ctx.append(current, item);
                else
                    m_ctx.append(current, right);
            } else if (op == "+=" && current.isStringLike() && right.isStringLike()) {
                assign(left, Value::substitution(
                                 concatenate({current.toSubstitution(), right.toSubstitution()})));
            } else if (op == "+=" && current.type == Value::Type::Number &&
                       right.type == Value::Type::Number) {
                assign(left, Value::number_(current.number + right.number));
            } else {
                assign(left, m_ctx.unknownAt(e));
            }
        } else {
            m_expressions.eval(e);
        }
    } else if (t == "return_statement") {
        TSNode e = ts_node_named_child(n, 0);
        m_ctx.frame->returnValue = ts::isNull(e) ? Value::none() : m_expressions.eval(e);
        m_ctx.frame->returned = true;
    } else if (t == "if_statement") {
        execIf(n);
    } else if (t == "for_statement") {
        execFor(n);
    } else if (t == "try_statement") {
        execBlock(ts::field(n, "body"));
        for (TSNode c : ts::namedChildren(n))
            if (ts::is(c, "finally_clause"))
                for (TSNode b : ts::namedChildren(c))
                    if (ts::is(b, "block"))
                        execBlock(b);
    } else if (t == "with_statement") {
        py::walk(n, [&](TSNode c) {
            if (ts::is(c, "block"))
                return false;
            if (ts::is(c, "as_pattern"))
                for (TSNode target : ts::namedChildren(c))
                    if (ts::is(target, "as_pattern_target"))
                        assign(ts_node_named_child(target, 0), m_ctx.unknownAt(c));
            return true;
        });
        execBlock(ts::field(n, "body"));
    } else if (t == "function_definition" || t == "decorated_definition") {
        TSNode def = py::undecorated(n);
        Value f;
        f.type = Value::Type::Function;
        f.node = def;
        f.closure = m_ctx.frame->scope;
        f.text = m_ctx.tree.text(ts::field(def, "name"));
        if (ts::is(def, "function_definition"))
            bind(f.text, f);
        else if (ts::is(def, "class_definition"))
            bind(f.text, Value::module(f.text));
    } else if (t == "class_definition") {
        const QString name = m_ctx.tree.text(ts::field(n, "name"));
        bind(name, Value::module(name));
    } else if (t == "import_statement" || t == "import_from_statement") {
        execImport(n);
    } else if (t == "global_statement" || t == "nonlocal_statement") {
        for (TSNode id : ts::namedChildren(n))
            if (ts::is(id, "identifier"))
                m_ctx.frame->globals.insert(m_ctx.tree.text(id));
    } else if (t == "break_statement") {
        m_ctx.frame->breaking = true;
    } else if (t == "continue_statement") {
        m_ctx.frame->continuing = true;
    }
    // while loops, match, raise, assert, del, pass: nothing a launch description needs
}

void PythonLaunchEvaluator::execImport(TSNode n)
{
    if (ts::is(n, "import_statement")) {
        for (TSNode name : ts::fieldChildren(n, "name")) {
            if (ts::is(name, "dotted_name")) {
                const QString first = m_ctx.tree.text(name).section(QLatin1Char('.'), 0, 0);
                bind(first, Value::module(first));
            } else if (ts::is(name, "aliased_import")) {
                bind(m_ctx.tree.text(ts::field(name, "alias")),
                     Value::module(m_ctx.tree.text(ts::field(name, "name"))));
            }
        }
        return;
    }
    const QString from = m_ctx.tree.text(ts::field(n, "module_name"));
    const QString prefix = from.isEmpty() ? QString() : from + QLatin1Char('.');
    for (TSNode name : ts::fieldChildren(n, "name")) {
        if (ts::is(name, "dotted_name")) {
            const QString text = m_ctx.tree.text(name);
            bind(text, Value::module(prefix + text));
        } else if (ts::is(name, "aliased_import")) {
            bind(m_ctx.tree.text(ts::field(name, "alias")),
                 Value::module(prefix + m_ctx.tree.text(ts::field(name, "name"))));
        }
    }
}

void PythonLaunchEvaluator::bind(const QString &name, const Value &value)
{
    if (m_ctx.frame->globals.contains(name))
        m_ctx.module->vars.insert(name, value);
    else
        m_ctx.frame->scope->vars.insert(name, value);
}

void PythonLaunchEvaluator::assign(TSNode target, const Value &value)
{
    const std::string_view t = ts::type(target);
    if (t == "identifier") {
        bind(m_ctx.tree.text(target), value);
    } else if (t == "pattern_list" || t == "tuple_pattern" || t == "list_pattern" || t == "tuple" ||
               t == "list" || t == "expression_list") {
        bool known = false;
        const QList<Value> items = m_ctx.iterate(value, &known);
        const std::vector<TSNode> targets = ts::namedChildren(target);
        qsizetype i = 0;
        for (TSNode sub : targets) {
            if (ts::is(sub, "list_splat_pattern") || ts::is(sub, "list_splat")) {
                const qsizetype rest = items.size() - qsizetype(targets.size()) + 1;
                assign(ts_node_named_child(sub, 0),
                       known ? m_ctx.newList(items.mid(i, qMax<qsizetype>(0, rest)))
                             : m_ctx.unknownAt(sub));
                i += qMax<qsizetype>(0, rest);
                continue;
            }
            assign(sub, known && i < items.size() ? items.at(i) : m_ctx.unknownAt(sub));
            ++i;
        }
    } else if (t == "parenthesized_expression") {
        assign(ts_node_named_child(target, 0), value);
    } else if (t == "subscript") {
        const Value object = m_expressions.eval(ts::field(target, "value"));
        const Value key = m_expressions.eval(ts::field(target, "subscript"));
        if (object.type == Value::Type::Dict) {
            // A write in an `else` branch does not overwrite the best guess.
            const GuardPath rel = relativeGuards(object.dict->createdUnder, m_ctx.guards);
            if (inBestGuess(rel) || !object.dict->find(key))
                object.dict->set(key, value);
        } else if (object.type == Value::Type::List && key.type == Value::Type::Number) {
            qsizetype i = qsizetype(key.number);
            if (i < 0)
                i += object.list->items.size();
            if (i >= 0 && i < object.list->items.size())
                object.list->items[i] = value;
        }
    }
    // attributes (self.x = ...) are not tracked
}

void PythonLaunchEvaluator::execIf(TSNode n)
{
    QList<TSNode> clauses{n};
    for (TSNode alternative : ts::fieldChildren(n, "alternative"))
        clauses << alternative;
    execIfChain(clauses, 0);
}

void PythonLaunchEvaluator::execIfChain(const QList<TSNode> &clauses, qsizetype from)
{
    if (from >= clauses.size() || m_ctx.stopped())
        return;
    TSNode clause = clauses.at(from);
    if (ts::is(clause, "else_clause")) {
        execBlock(ts::field(clause, "body"));
        return;
    }
    TSNode condition = ts::field(clause, "condition");
    TSNode body = ts::field(clause, "consequence");
    const std::optional<bool> truth = m_expressions.eval(condition).truth();
    if (truth.has_value()) {
        if (*truth)
            execBlock(body);
        else
            execIfChain(clauses, from + 1);
        return;
    }

    // Undecidable: run both branches, each under a guard. Names keep the first branch's values
    // (the best guess); list additions keep both, wrapped into conditional groups.
    auto guard = std::make_shared<Guard>();
    guard->text = oneLine(m_ctx.textOf(condition));
    guard->evidence = spanEvidence(m_ctx.tree, clause, body);
    Frame &frame = *m_ctx.frame;
    const QHash<QString, Value> before = frame.scope->vars;

    m_ctx.guards.append(guard);
    execBlock(body);
    m_ctx.guards.removeLast();
    const bool thenReturned = frame.returned;
    const Value thenValue = frame.returnValue;
    const bool thenBreaking = frame.breaking, thenContinuing = frame.continuing;
    frame.returned = frame.breaking = frame.continuing = false;
    const QHash<QString, Value> thenVars = frame.scope->vars;
    frame.scope->vars = before;

    GuardPtr elseGuard;
    if (from + 1 < clauses.size()) {
        auto g = std::make_shared<Guard>(*guard);
        g->unless = true;
        g->evidence = spanEvidence(m_ctx.tree, clauses.at(from + 1), clauses.last());
        elseGuard = g;
        m_ctx.guards.append(elseGuard);
        execIfChain(clauses, from + 1);
        m_ctx.guards.removeLast();
    } else {
        elseGuard = negated(guard);
    }
    const bool elseReturned = frame.returned;
    const Value elseValue = frame.returnValue;
    frame.returned = false;

    const bool elseBreaking = frame.breaking, elseContinuing = frame.continuing;
    if (thenReturned && elseReturned) {
        frame.returned = true;
        frame.returnValue = combineReturns(guard, thenValue, elseValue);
    } else if (thenReturned) {
        frame.pendingReturns.append({guard, thenValue}); // the rest of the function is the else
    } else if (elseReturned) {
        frame.pendingReturns.append({elseGuard, elseValue});
        frame.scope->vars = thenVars;
    } else {
        for (auto it = thenVars.constBegin(); it != thenVars.constEnd(); ++it)
            frame.scope->vars.insert(it.key(), it.value());
    }
    const bool useElse = thenReturned && !elseReturned;
    frame.breaking = useElse ? elseBreaking : thenBreaking;
    frame.continuing = useElse ? elseContinuing : thenContinuing;
}

Value PythonLaunchEvaluator::combineReturns(const GuardPtr &guard, const Value &taken,
                                            const Value &other)
{
    if (!holdsActions(taken) && !holdsActions(other))
        return taken;
    Value out = m_ctx.newList({});
    out.list->launchDescription = true;
    // An action both alternatives return (`if c: return [node]` ... `return [node, more]`)
    // runs whichever is taken: it goes once, unguarded, and only the rest is under the guard.
    const auto actionsOf = [](const Value &v) {
        QList<const QList<LaunchAction> *> out;
        if (v.type == Value::Type::List && v.list)
            for (const Value &item : v.list->items)
                if (item.type == Value::Type::Action && item.actions)
                    out << item.actions.get();
        return out;
    };
    const QList<const QList<LaunchAction> *> inTaken = actionsOf(taken);
    const QList<const QList<LaunchAction> *> inOther = actionsOf(other);
    QList<const QList<LaunchAction> *> common;
    for (const QList<LaunchAction> *a : inTaken)
        if (inOther.contains(a) && !common.contains(a))
            common << a;
    const auto without = [&](const Value &v) {
        if (common.isEmpty() || v.type != Value::Type::List || !v.list)
            return v;
        Value rest = m_ctx.newList({});
        rest.list->launchDescription = v.list->launchDescription;
        for (qsizetype i = 0; i < v.list->items.size(); ++i) {
            const Value &item = v.list->items.at(i);
            if (item.type == Value::Type::Action && common.contains(item.actions.get()))
                continue;
            rest.list->items << item;
            rest.list->guards << v.list->guards.value(i);
        }
        return rest;
    };
    if (!common.isEmpty())
        for (qsizetype i = 0; i < taken.list->items.size(); ++i) {
            const Value &item = taken.list->items.at(i);
            if (item.type == Value::Type::Action && common.contains(item.actions.get())) {
                out.list->items << item;
                out.list->guards << taken.list->guards.value(i);
            }
        }
    out.list->items << without(taken);
    out.list->guards << GuardPath{guard};
    if (other.type != Value::Type::None) {
        out.list->items << without(other);
        out.list->guards << GuardPath{negated(guard)};
    }
    return out;
}

void PythonLaunchEvaluator::execFor(TSNode n)
{
    TSNode left = ts::field(n, "left");
    TSNode body = ts::field(n, "body");
    bool known = false;
    const QList<Value> items = m_ctx.iterate(m_expressions.eval(ts::field(n, "right")), &known);
    Frame &frame = *m_ctx.frame;
    if (!known) {
        // Loop over something unknown: its body once, under an undecided guard.
        auto guard = std::make_shared<Guard>();
        guard->text = oneLine(QStringLiteral("for %1 in %2")
                                  .arg(m_ctx.textOf(left), m_ctx.textOf(ts::field(n, "right"))));
        guard->evidence = m_ctx.tree.evidence(n);
        assign(left, m_ctx.unknownAt(left));
        m_ctx.guards.append(guard);
        execBlock(body);
        m_ctx.guards.removeLast();
        frame.breaking = frame.continuing = false;
        return;
    }
    bool broke = false;
    int count = 0;
    for (const Value &item : items) {
        if (m_ctx.stopped())
            break;
        if (++count > kMaxIterations) {
            Diagnostic d;
            d.code = QStringLiteral("launch-loop-limit");
            d.message =
                QStringLiteral("A loop in %1 runs more than %2 times; only the first %2 are read.")
                    .arg(m_ctx.tree.file())
                    .arg(kMaxIterations);
            d.evidence = m_ctx.tree.evidence(n);
            if (!m_ctx.diagnostics.contains(d))
                m_ctx.diagnostics << d;
            break;
        }
        assign(left, item);
        execBlock(body);
        frame.continuing = false;
        if (frame.breaking) {
            frame.breaking = false;
            broke = true;
            break;
        }
    }
    if (!broke && !frame.returned)
        for (TSNode alternative : ts::fieldChildren(n, "alternative"))
            execBlock(ts::field(alternative, "body"));
}

Value PythonLaunchEvaluator::callFunction(const Value &function, const CallArgs &args, TSNode call)
{
    if (m_ctx.callDepth >= kMaxCallDepth || m_ctx.exhausted)
        return ts::isNull(call) ? Value::unknown(function.text) : m_ctx.unknownAt(call);
    const bool lambda = ts::is(function.node, "lambda");
    Frame frame;
    frame.scope = m_ctx.newScope(function.closure);
    Frame *caller = m_ctx.frame;
    m_ctx.frame = &frame;
    ++m_ctx.callDepth;

    // Bind parameters: positional, keyword, *args, **kwargs, defaults.
    qsizetype nextPositional = 0;
    QList<bool> usedKeyword(args.keywords.size(), false);
    QString starName, starStarName;
    for (TSNode p : ts::namedChildren(ts::field(function.node, "parameters"))) {
        const std::string_view t = ts::type(p);
        TSNode nameNode{}, defaultNode{}; // unset until a parameter form sets them
        if (t == "identifier") {
            nameNode = p;
        } else if (t == "default_parameter" || t == "typed_default_parameter") {
            nameNode = ts::field(p, "name");
            defaultNode = ts::field(p, "value");
        } else if (t == "typed_parameter" || t == "list_splat_pattern" ||
                   t == "dictionary_splat_pattern") {
            TSNode inner = t == "typed_parameter" ? ts_node_named_child(p, 0) : p;
            if (ts::is(inner, "identifier")) {
                nameNode = inner;
            } else if (ts::is(inner, "list_splat_pattern")) {
                starName = m_ctx.tree.text(ts_node_named_child(inner, 0));
                continue;
            } else if (ts::is(inner, "dictionary_splat_pattern")) {
                starStarName = m_ctx.tree.text(ts_node_named_child(inner, 0));
                continue;
            }
        }
        if (!ts::is(nameNode, "identifier"))
            continue;
        const QString name = m_ctx.tree.text(nameNode);
        Value v;
        bool found = false;
        if (nextPositional < args.positional.size()) {
            v = args.positional.at(nextPositional++);
            found = true;
        }
        for (qsizetype k = 0; !found && k < args.keywords.size(); ++k) {
            if (args.keywords.at(k).first == name) {
                v = args.keywords.at(k).second;
                usedKeyword[k] = found = true;
            }
        }
        if (!found)
            v = ts::isNull(defaultNode) ? m_ctx.unknownAt(nameNode)
                                        : m_expressions.eval(defaultNode);
        frame.scope->vars.insert(name, v);
    }
    if (!starName.isEmpty())
        frame.scope->vars.insert(starName,
                                 m_ctx.newList(args.positional.mid(nextPositional), true));
    if (!starStarName.isEmpty()) {
        Value kwargs = m_ctx.newDict();
        for (qsizetype k = 0; k < args.keywords.size(); ++k)
            if (!usedKeyword.at(k))
                kwargs.dict->set(Value::string(args.keywords.at(k).first),
                                 args.keywords.at(k).second);
        frame.scope->vars.insert(starStarName, kwargs);
    }

    Value result;
    if (lambda) {
        result = m_expressions.eval(ts::field(function.node, "body"));
    } else {
        execBlock(ts::field(function.node, "body"));
        result = frame.returned ? frame.returnValue : Value::none();
        for (qsizetype i = frame.pendingReturns.size() - 1; i >= 0; --i)
            result = combineReturns(frame.pendingReturns.at(i).first,
                                    frame.pendingReturns.at(i).second, result);
    }
    --m_ctx.callDepth;
    m_ctx.frame = caller;
    return result;
}

Value PythonLaunchEvaluator::evalCall(TSNode n)
{
    TSNode function = ts::field(n, "function");
    Value callee;
    if (ts::is(function, "attribute")) {
        const Value object = m_expressions.eval(ts::field(function, "object"));
        const QString method = m_ctx.tree.text(ts::field(function, "attribute"));
        if (object.type != Value::Type::Module)
            return m_builtins.callMethod(object, method, m_expressions.evalArguments(n), n);
        callee = Value::module(object.text + QLatin1Char('.') + method);
    } else {
        callee = m_expressions.eval(function);
    }
    if (callee.type == Value::Type::Function)
        return callFunction(callee, m_expressions.evalArguments(n), n);
    if (callee.type != Value::Type::Module)
        return m_ctx.unknownAt(n);
    const CallArgs args = m_expressions.evalArguments(n);
    std::optional<Value> v = m_builtins.callBuiltin(callee.text, args, n);
    if (!v)
        v = m_api.callLaunchApi(callee.text.section(QLatin1Char('.'), -1), args, n);
    if (!v)
        return m_ctx.unknownAt(n);
    if (v->type == Value::Type::Unknown && !v->evidence.isValid())
        v->evidence =
            m_ctx.tree.evidence(n); // an Unresolved action made from it points at the call
    return *v;
}

} // namespace rosarch::pylaunch
