// Builtins and methods of plain Python values for the launch-file evaluator: str, list, dict,
// os.path, os.environ, range, format strings.
#include "launch/python/pythonlaunchbuiltins.h"

#include <algorithm>
#include <cmath>

namespace rosarch::pylaunch {

namespace {
constexpr int kMaxRange = 256;

bool oneOf(const QString &dotted, std::initializer_list<const char *> names)
{
    for (const char *n : names)
        if (dotted == QLatin1String(n))
            return true;
    return false;
}

Substitution textOfValue(const Value &v)
{
    if (const auto literal = v.literalText())
        return Substitution::literal(*literal);
    return v.toSubstitution();
}

Value environmentVariable(const Value *name, const Value *fallback, const QString &text)
{
    if (!name || name->type != Value::Type::String)
        return Value::unknown(text);
    Substitution env;
    env.kind = Substitution::Kind::EnvironmentVariable;
    env.text = name->text;
    if (fallback && fallback->type != Value::Type::None)
        env.parts << fallback->toSubstitution();
    return Value::substitution(env);
}

/// os.path.join: literal parts as Python joins them, otherwise a PathJoin substitution.
Value joinPaths(const QList<Value> &parts)
{
    bool literal = true;
    for (const Value &p : parts)
        literal = literal && p.type == Value::Type::String;
    if (literal) {
        QString out;
        for (const Value &p : parts) {
            if (p.text.startsWith(QLatin1Char('/')) || out.isEmpty())
                out = p.text;
            else
                out += (out.endsWith(QLatin1Char('/')) ? QString() : QStringLiteral("/")) + p.text;
        }
        return Value::string(out);
    }
    Substitution join;
    join.kind = Substitution::Kind::PathJoin;
    for (const Value &p : parts) {
        const Substitution s = p.toSubstitution();
        if (s.kind == Substitution::Kind::PathJoin && join.parts.isEmpty())
            join.parts = s.parts;
        else
            join.parts << s;
    }
    return Value::substitution(join);
}

Value dirname(const Value &v, const QString &text)
{
    if (v.type == Value::Type::String)
        return Value::string(v.text.contains(QLatin1Char('/'))
                                 ? v.text.section(QLatin1Char('/'), 0, -2)
                                 : QString());
    if (v.type == Value::Type::Subst) {
        if (v.subst.kind == Substitution::Kind::ThisLaunchFile) {
            Substitution dir;
            dir.kind = Substitution::Kind::ThisLaunchFileDir;
            return Value::substitution(dir);
        }
        if (v.subst.kind == Substitution::Kind::PathJoin && v.subst.parts.size() > 1 &&
            v.subst.parts.last().isLiteral() &&
            !v.subst.parts.last().text.contains(QLatin1Char('/'))) {
            Substitution s = v.subst;
            s.parts.removeLast();
            return Value::substitution(s.parts.size() == 1 ? s.parts.first() : s);
        }
    }
    return Value::unknown(text);
}
} // namespace

PythonLaunchBuiltins::PythonLaunchBuiltins(PythonLaunchContext &ctx) : m_ctx(ctx) {}

std::optional<Value> PythonLaunchBuiltins::callBuiltin(const QString &dotted, const CallArgs &args,
                                                       TSNode call)
{
    using T = Value::Type;
    const Value *a0 = args.get(0);
    const QString text = m_ctx.tree.text(call);
    const Evidence evidence = m_ctx.tree.evidence(call);
    if (oneOf(dotted, {"os.path.join", "path.join", "posixpath.join"}))
        return joinPaths(args.positional);
    if (oneOf(dotted, {"os.path.dirname", "path.dirname"}))
        return a0 ? dirname(*a0, text) : Value::unknown(text, evidence);
    if (oneOf(dotted, {"os.path.basename", "path.basename"})) {
        if (a0 && a0->type == T::String)
            return Value::string(a0->text.section(QLatin1Char('/'), -1));
        return Value::unknown(text, evidence);
    }
    if (oneOf(dotted,
              {"os.path.abspath", "os.path.realpath", "os.path.normpath", "os.path.expanduser",
               "os.fspath", "path.abspath", "path.realpath", "path.normpath"}))
        return a0 ? *a0 : Value::unknown(text, evidence);
    if (oneOf(dotted, {"os.environ.get", "os.getenv"}))
        return environmentVariable(a0, args.get(1, {"default"}), text);
    if (oneOf(dotted, {"Path", "pathlib.Path", "PurePath", "pathlib.PurePath", "PosixPath"})) {
        if (args.positional.isEmpty())
            return Value::string(QStringLiteral("."));
        return args.positional.size() == 1 ? args.positional.first() : joinPaths(args.positional);
    }
    if (dotted == QLatin1String("str")) {
        if (!a0)
            return Value::string(QString());
        if (a0->type == T::Subst || a0->isLiteral())
            return Value::substitution(textOfValue(*a0));
        return Value::unknown(text, evidence);
    }
    if (oneOf(dotted, {"int", "float"})) {
        if (a0 && (a0->type == T::Number || a0->type == T::Bool || a0->type == T::String)) {
            bool ok = true;
            double d = a0->type == T::String ? a0->text.trimmed().toDouble(&ok)
                                             : (a0->type == T::Bool ? a0->boolean : a0->number);
            if (ok)
                return dotted == QLatin1String("int") ? Value::number_(std::trunc(d))
                                                      : Value::number_(d);
        }
        return Value::unknown(text, evidence);
    }
    if (dotted == QLatin1String("bool")) {
        const std::optional<bool> truth = a0 ? a0->truth() : std::optional<bool>(false);
        return truth ? Value::boolean_(*truth) : Value::unknown(text, evidence);
    }
    if (dotted == QLatin1String("len")) {
        if (a0 && a0->type == T::List)
            return Value::number_(double(a0->items().size()));
        if (a0 && a0->type == T::Dict)
            return Value::number_(double(a0->dict->entries.size()));
        if (a0 && a0->type == T::String)
            return Value::number_(double(a0->text.size()));
        return Value::unknown(text, evidence);
    }
    if (oneOf(dotted, {"list", "tuple", "sorted", "set", "reversed"})) {
        if (!a0)
            return m_ctx.newList({}, dotted == QLatin1String("tuple"));
        bool known = false;
        QList<Value> items = m_ctx.iterate(*a0, &known);
        if (!known)
            return Value::unknown(text, evidence);
        if (dotted == QLatin1String("reversed"))
            std::reverse(items.begin(), items.end());
        // A set iterates in hash order, which for strings changes from run to run.
        m_ctx.approximate =
            m_ctx.approximate || (dotted == QLatin1String("set") && items.size() > 1);
        if (dotted == QLatin1String("sorted")) {
            const auto all = [&](T type) {
                return std::all_of(items.cbegin(), items.cend(),
                                   [type](const Value &v) { return v.type == type; });
            };
            if (all(T::String))
                std::stable_sort(items.begin(), items.end(),
                                 [](const Value &x, const Value &y) { return x.text < y.text; });
            else if (all(T::Number))
                std::stable_sort(items.begin(), items.end(), [](const Value &x, const Value &y) {
                    return x.number < y.number;
                });
            else
                m_ctx.approximate = true; // left in their order
        }
        return m_ctx.newList(items, dotted == QLatin1String("tuple"));
    }
    if (dotted == QLatin1String("dict")) {
        Value d = m_ctx.newDict();
        if (a0 && a0->type == T::Dict) {
            d.dict->entries = a0->dict->entries;
        } else if (a0) {
            bool known = false;
            for (const Value &pair : m_ctx.iterate(*a0, &known)) {
                const QList<Value> kv = pair.items();
                if (kv.size() == 2)
                    d.dict->set(kv.at(0), kv.at(1));
            }
        }
        for (const auto &k : args.keywords)
            d.dict->set(Value::string(k.first), k.second);
        return d;
    }
    if (dotted == QLatin1String("range")) {
        double from = 0, to = 0, by = 1;
        QList<double> n;
        for (const Value &v : args.positional) {
            if (v.type != T::Number)
                return Value::unknown(text, evidence);
            n << v.number;
        }
        if (n.size() == 1)
            to = n.at(0);
        else if (n.size() >= 2)
            from = n.at(0), to = n.at(1), by = n.value(2, 1);
        if (by == 0)
            return Value::unknown(text, evidence);
        QList<Value> items;
        double i = from;
        for (; (by > 0 ? i < to : i > to) && items.size() < kMaxRange; i += by)
            items << Value::number_(i);
        m_ctx.approximate = m_ctx.approximate || (by > 0 ? i < to : i > to);
        return m_ctx.newList(items);
    }
    if (dotted == QLatin1String("enumerate") || dotted == QLatin1String("zip")) {
        QList<QList<Value>> columns;
        if (dotted == QLatin1String("enumerate") && a0) {
            bool known = false;
            const QList<Value> items = m_ctx.iterate(*a0, &known);
            if (!known)
                return Value::unknown(text, evidence);
            QList<Value> index;
            for (qsizetype i = 0; i < items.size(); ++i)
                index << Value::number_(double(i));
            columns << index << items;
        } else {
            for (const Value &v : args.positional) {
                bool known = false;
                columns << m_ctx.iterate(v, &known);
                if (!known)
                    return Value::unknown(text, evidence);
            }
        }
        qsizetype rows = columns.isEmpty() ? 0 : columns.first().size();
        for (const auto &c : columns)
            rows = qMin(rows, c.size());
        QList<Value> out;
        for (qsizetype r = 0; r < rows; ++r) {
            QList<Value> row;
            for (const auto &c : columns)
                row << c.at(r);
            out << m_ctx.newList(row, true);
        }
        return m_ctx.newList(out);
    }
    if (oneOf(dotted, {"print", "logging.info", "logging.warning", "logging.debug"}))
        return Value::none();
    return std::nullopt;
}

Value PythonLaunchBuiltins::callMethod(const Value &object, const QString &method,
                                       const CallArgs &args, TSNode call)
{
    using T = Value::Type;
    const Value *a0 = args.get(0);
    const Value *a1 = args.get(1);
    auto is = [&](std::initializer_list<const char *> names) { return oneOf(method, names); };

    if (object.type == T::List) {
        ListData &list = *object.list;
        if (is({"append", "add_action", "add_entity"}) && a0) {
            m_ctx.append(object, *a0);
            return Value::none();
        }
        if (is({"extend", "add_actions", "add_entities"}) && a0) {
            if (a0->type == T::List) {
                // keep the guards the items were added under
                const GuardPath here = relativeGuards(list.createdUnder, m_ctx.guards);
                for (qsizetype i = 0; i < a0->list->items.size(); ++i) {
                    list.items << a0->list->items.at(i);
                    list.guards << here + a0->list->guards.value(i);
                }
            } else {
                m_ctx.append(object, *a0);
            }
            return Value::none();
        }
        if (is({"insert"}) && a0 && a1 && a0->type == T::Number) {
            const qsizetype at = qBound<qsizetype>(
                0,
                a0->number < 0 ? list.items.size() + qsizetype(a0->number) : qsizetype(a0->number),
                list.items.size());
            list.items.insert(at, *a1);
            list.guards.insert(at, relativeGuards(list.createdUnder, m_ctx.guards));
            return Value::none();
        }
        if (is({"copy"}))
            return m_ctx.newList(object.items(), list.tuple);
        if (is({"pop"}) && !list.items.isEmpty()) {
            qsizetype at = list.items.size() - 1;
            if (a0 && a0->type == T::Number)
                at = a0->number < 0 ? list.items.size() + qsizetype(a0->number)
                                    : qsizetype(a0->number);
            if (at >= 0 && at < list.items.size()) {
                const Value v = list.items.takeAt(at);
                list.guards.removeAt(at);
                return v;
            }
        }
        return m_ctx.unknownAt(call);
    }
    if (object.type == T::Dict) {
        DictData &dict = *object.dict;
        if (is({"items", "keys", "values"})) {
            QList<Value> out;
            for (const auto &e : dict.entries) {
                if (method == QLatin1String("items"))
                    out << m_ctx.newList({e.first, e.second}, true);
                else
                    out << (method == QLatin1String("keys") ? e.first : e.second);
            }
            return m_ctx.newList(out);
        }
        if (is({"get", "pop", "setdefault"}) && a0) {
            if (const Value *v = dict.find(*a0))
                return *v;
            const Value fallback = a1 ? *a1 : Value::none();
            if (method == QLatin1String("setdefault"))
                dict.set(*a0, fallback);
            return fallback;
        }
        if (is({"update"})) {
            if (a0 && a0->type == T::Dict)
                for (const auto &e : a0->dict->entries)
                    dict.set(e.first, e.second);
            for (const auto &k : args.keywords)
                dict.set(Value::string(k.first), k.second);
            return Value::none();
        }
        if (is({"copy"})) {
            Value d = m_ctx.newDict();
            d.dict->entries = dict.entries;
            return d;
        }
        return m_ctx.unknownAt(call);
    }
    if (object.type == T::String) {
        const QString &s = object.text;
        if (is({"format"}))
            return formatString(s, args.positional, args.keywords, false, call);
        if (is({"join"}) && a0) {
            bool known = false;
            const QList<Value> items = m_ctx.iterate(*a0, &known);
            if (!known)
                return m_ctx.unknownAt(call);
            QList<Substitution> parts;
            for (qsizetype i = 0; i < items.size(); ++i) {
                if (i > 0)
                    parts << Substitution::literal(s);
                parts << textOfValue(items.at(i));
            }
            return Value::substitution(concatenate(parts));
        }
        if (is({"strip", "lstrip", "rstrip"})) {
            if (a0 && a0->type == T::String) {
                QString out = s;
                const QString chars = a0->text;
                if (method != QLatin1String("rstrip"))
                    while (!out.isEmpty() && chars.contains(out.front()))
                        out.remove(0, 1);
                if (method != QLatin1String("lstrip"))
                    while (!out.isEmpty() && chars.contains(out.back()))
                        out.chop(1);
                return Value::string(out);
            }
            QString out = s;
            if (method != QLatin1String("rstrip"))
                while (!out.isEmpty() && out.front().isSpace())
                    out.remove(0, 1);
            if (method != QLatin1String("lstrip"))
                while (!out.isEmpty() && out.back().isSpace())
                    out.chop(1);
            return Value::string(out);
        }
        if (is({"lower"}))
            return Value::string(s.toLower());
        if (is({"upper"}))
            return Value::string(s.toUpper());
        const Value *count = args.get(2, {"count"});
        if (is({"replace"}) && a0 && a1 && a0->type == T::String && a1->type == T::String &&
            (!count || count->type == T::Number)) {
            if (!count || count->number < 0)
                return Value::string(QString(s).replace(a0->text, a1->text));
            QString out = s; // the first `count` occurrences
            qsizetype from = 0;
            for (int i = 0; i < count->number && !a0->text.isEmpty(); ++i) {
                from = out.indexOf(a0->text, from);
                if (from < 0)
                    break;
                out.replace(from, a0->text.size(), a1->text);
                from += a1->text.size();
            }
            return Value::string(out);
        }
        if (is({"startswith", "endswith"}) && a0 && a0->type == T::String)
            return Value::boolean_(method == QLatin1String("startswith") ? s.startsWith(a0->text)
                                                                         : s.endsWith(a0->text));
        if (is({"split"}) && !(a0 && a0->type == T::String && a0->text.isEmpty())) {
            const QStringList pieces =
                a0 && a0->type == T::String
                    ? s.split(a0->text)
                    : s.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
            QList<Value> items;
            for (const QString &p : pieces)
                items << Value::string(p);
            return m_ctx.newList(items);
        }
        if (is({"encode", "decode"}))
            return object;
        return m_ctx.unknownAt(call);
    }
    if (object.type == T::Subst || object.type == T::Source) {
        // LaunchConfiguration('x').perform(context), FindPackageShare('p').find('p'), '...'.strip()
        if (is({"perform", "find", "strip", "resolve", "absolute", "as_posix", "expanduser"}))
            return object;
        return m_ctx.unknownAt(call);
    }
    if (object.type == T::Context) {
        if (is({"perform_substitution"}) && a0)
            return *a0;
        if (object.text == QLatin1String("launch_configurations") && is({"get"}) && a0) {
            if (a0->type != T::String)
                return m_ctx.unknownAt(call);
            Substitution config = Substitution::configuration(a0->text);
            if (a1 && a1->type != T::None)
                config.parts << a1->toSubstitution();
            return Value::substitution(config);
        }
        return m_ctx.unknownAt(call);
    }
    return m_ctx.unknownAt(call);
}

Value PythonLaunchBuiltins::formatString(const QString &format, const QList<Value> &positional,
                                         const QList<QPair<QString, Value>> &keywords, bool percent,
                                         TSNode node)
{
    QList<Substitution> parts;
    QString literal;
    qsizetype next = 0;
    auto flush = [&] {
        parts << Substitution::literal(literal);
        literal.clear();
    };
    for (qsizetype i = 0; i < format.size(); ++i) {
        const QChar c = format.at(i);
        if (percent && c == QLatin1Char('%')) {
            qsizetype j = i + 1;
            while (j < format.size() && QStringLiteral("#0- +.123456789").contains(format.at(j)))
                ++j;
            if (j >= format.size())
                return m_ctx.unknownAt(node);
            const QChar type = format.at(j);
            if (type == QLatin1Char('%')) {
                literal += QLatin1Char('%');
            } else {
                if (next >= positional.size() || !QStringLiteral("sdifrg").contains(type))
                    return m_ctx.unknownAt(node);
                const Value &v = positional.at(next++);
                flush();
                if (type == QLatin1Char('d') || type == QLatin1Char('i'))
                    parts << (v.type == Value::Type::Number
                                  ? Substitution::literal(QString::number(qint64(v.number)))
                                  : textOfValue(v));
                else if (type == QLatin1Char('r') && v.type == Value::Type::String)
                    parts << Substitution::literal(QLatin1Char('\'') + v.text + QLatin1Char('\''));
                else
                    parts << textOfValue(v);
            }
            i = j;
            continue;
        }
        if (!percent && (c == QLatin1Char('{') || c == QLatin1Char('}'))) {
            if (i + 1 < format.size() && format.at(i + 1) == c) {
                literal += c;
                ++i;
                continue;
            }
            if (c == QLatin1Char('}'))
                return m_ctx.unknownAt(node);
            const qsizetype close = format.indexOf(QLatin1Char('}'), i);
            if (close < 0)
                return m_ctx.unknownAt(node);
            QString field = format.mid(i + 1, close - i - 1)
                                .section(QLatin1Char(':'), 0, 0)
                                .section(QLatin1Char('!'), 0, 0);
            const Value *v = nullptr;
            bool isIndex = false;
            const int index = field.toInt(&isIndex);
            if (field.isEmpty())
                v = next < positional.size() ? &positional.at(next++) : nullptr;
            else if (isIndex)
                v = index < positional.size() ? &positional.at(index) : nullptr;
            else
                for (const auto &k : keywords)
                    if (k.first == field)
                        v = &k.second;
            if (!v)
                return m_ctx.unknownAt(node);
            flush();
            parts << textOfValue(*v);
            i = close;
            continue;
        }
        literal += c;
    }
    flush();
    return Value::substitution(concatenate(parts));
}

} // namespace rosarch::pylaunch
