#include "launch/python/pythonlaunchvalue.h"

#include <QStringList>

namespace rosarch::pylaunch {

Value Value::unknown(const QString &text, const Evidence &evidence)
{
    Value v;
    v.type = Type::Unknown;
    v.text = text;
    v.evidence = evidence;
    return v;
}

Value Value::none()
{
    Value v;
    v.type = Type::None;
    return v;
}

Value Value::boolean_(bool b)
{
    Value v;
    v.type = Type::Bool;
    v.boolean = b;
    return v;
}

Value Value::number_(double n, const QString &text)
{
    Value v;
    v.type = Type::Number;
    v.number = n;
    if (!text.isEmpty())
        v.text = text;
    else if (n == double(qint64(n)) && qAbs(n) < 1e15)
        v.text = QString::number(qint64(n));
    else
        v.text = QString::number(n, 'g', 15);
    return v;
}

Value Value::string(const QString &s)
{
    Value v;
    v.type = Type::String;
    v.text = s;
    return v;
}

Value Value::substitution(const Substitution &s)
{
    if (s.kind == Substitution::Kind::Text)
        return string(s.text);
    Value v;
    v.type = Type::Subst;
    v.subst = s;
    return v;
}

Value Value::module(const QString &dotted)
{
    Value v;
    v.type = Type::Module;
    v.text = dotted;
    return v;
}

Value Value::makeList(QList<Value> items, bool tuple, bool launchDescription)
{
    Value v;
    v.type = Type::List;
    v.list = std::make_shared<ListData>();
    v.list->guards.resize(items.size());
    v.list->items = std::move(items);
    v.list->tuple = tuple;
    v.list->launchDescription = launchDescription;
    return v;
}

Value Value::makeDict()
{
    Value v;
    v.type = Type::Dict;
    v.dict = std::make_shared<DictData>();
    return v;
}

Value Value::action(QList<LaunchAction> actions)
{
    Value v;
    v.type = Type::Action;
    if (!actions.isEmpty())
        v.evidence = actions.first().evidence;
    v.actions = std::make_shared<const QList<LaunchAction>>(std::move(actions));
    return v;
}

std::optional<bool> Value::truth() const
{
    switch (type) {
    case Type::None:
        return false;
    case Type::Bool:
        return boolean;
    case Type::Number:
        return number != 0;
    case Type::String:
        return !text.isEmpty();
    case Type::List: {
        bool guarded = false;
        for (qsizetype i = 0; i < list->items.size(); ++i) {
            if (list->guards.value(i).isEmpty())
                return true;
            guarded = true;
        }
        if (guarded)
            return std::nullopt;
        return false;
    }
    case Type::Dict:
        return !dict->entries.isEmpty();
    case Type::Action:
    case Type::Condition:
    case Type::Source:
    case Type::Function:
    case Type::Skip:
        return true;
    case Type::Unknown:
    case Type::Subst:
    case Type::Module:
    case Type::Context:
        return std::nullopt;
    }
    return std::nullopt;
}

std::optional<QString> Value::literalText() const
{
    switch (type) {
    case Type::String:
    case Type::Number:
        return text;
    case Type::Bool:
        return boolean ? QStringLiteral("True") : QStringLiteral("False");
    case Type::None:
        return QStringLiteral("None");
    default:
        return std::nullopt;
    }
}

QList<Value> Value::items() const
{
    QList<Value> out;
    if (type != Type::List)
        return out;
    for (qsizetype i = 0; i < list->items.size(); ++i)
        if (inBestGuess(list->guards.value(i)))
            out << list->items.at(i);
    return out;
}

namespace {
// Lists can nest and share their storage ([a, a] repeated), so every walk over a value has a
// node budget and a depth limit; beyond them a value is unknown or contributes nothing.
constexpr int kWalkBudget = 20000;
constexpr int kWalkDepth = 48;

struct Walk
{
    int budget = kWalkBudget;
    bool enter(int depth) { return --budget >= 0 && depth <= kWalkDepth; }
};

Substitution substitutionOf(const Value &v, Walk &walk, int depth, bool parameter)
{
    using T = Value::Type;
    if (!walk.enter(depth))
        return Substitution::unknown(QStringLiteral("..."));
    switch (v.type) {
    case T::String:
    case T::Number:
        return Substitution::literal(v.text);
    case T::Bool:
        return Substitution::literal(v.boolean ? QStringLiteral("true") : QStringLiteral("false"));
    case T::None:
        return Substitution::literal(QString());
    case T::Subst:
    case T::Source:
        return v.subst;
    case T::List: {
        QList<Substitution> parts;
        if (parameter)
            parts << Substitution::literal(QStringLiteral("["));
        bool first = true;
        for (const Value &item : v.items()) {
            if (parameter && !first)
                parts << Substitution::literal(QStringLiteral(", "));
            first = false;
            parts << substitutionOf(item, walk, depth + 1, parameter);
        }
        if (parameter)
            parts << Substitution::literal(QStringLiteral("]"));
        return concatenate(parts);
    }
    case T::Condition:
        return v.condition.expression;
    case T::Action:
        if (v.actions && !v.actions->isEmpty() && !v.actions->first().expression.isEmpty())
            return Substitution::unknown(oneLine(v.actions->first().expression));
        return Substitution::unknown(QStringLiteral("<action>"));
    case T::Dict:
        return Substitution::unknown(v.text.isEmpty() ? QStringLiteral("<dict>") : oneLine(v.text));
    case T::Context:
        return Substitution::unknown(QStringLiteral("context"));
    case T::Unknown:
    case T::Module:
    case T::Function:
    case T::Skip:
        break;
    }
    return Substitution::unknown(oneLine(v.text));
}
} // namespace

Substitution Value::toSubstitution() const
{
    Walk walk;
    return substitutionOf(*this, walk, 0, false);
}

Substitution Value::toParameterValue() const
{
    Walk walk;
    return substitutionOf(*this, walk, 0, true);
}

bool Value::sameLiteral(const Value &other) const
{
    if (isLiteral() && other.isLiteral()) {
        if (type == Type::String || other.type == Type::String)
            return type == other.type && text == other.text;
        if (type == Type::None || other.type == Type::None)
            return type == other.type;
        const double a = type == Type::Bool ? double(boolean) : number;
        const double b = other.type == Type::Bool ? double(other.boolean) : other.number;
        return a == b;
    }
    if (type == Type::Subst && other.type == Type::Subst)
        return subst == other.subst;
    return false;
}

const Value *DictData::find(const Value &key) const
{
    for (const auto &e : entries)
        if (e.first.sameLiteral(key))
            return &e.second;
    return nullptr;
}

void DictData::set(const Value &key, const Value &value)
{
    for (auto &e : entries) {
        if (e.first.sameLiteral(key)) {
            e.second = value;
            return;
        }
    }
    entries.append({key, value});
}

const Value *Scope::lookup(const QString &name) const
{
    for (const Scope *s = this; s; s = s->parent.get()) {
        auto it = s->vars.constFind(name);
        if (it != s->vars.constEnd())
            return &it.value();
    }
    return nullptr;
}

GuardPath relativeGuards(const GuardPath &createdUnder, const GuardPath &current)
{
    qsizetype common = 0;
    while (common < createdUnder.size() && common < current.size() &&
           createdUnder.at(common) == current.at(common))
        ++common;
    return current.mid(common);
}

bool inBestGuess(const GuardPath &path)
{
    for (const GuardPtr &g : path)
        if (g->unless)
            return false;
    return true;
}

Substitution concatenate(const QList<Substitution> &parts)
{
    QList<Substitution> out;
    auto add = [&](const Substitution &s) {
        if (s.kind == Substitution::Kind::Text) {
            if (s.text.isEmpty())
                return;
            if (!out.isEmpty() && out.last().kind == Substitution::Kind::Text) {
                out.last().text += s.text;
                return;
            }
        }
        out << s;
    };
    for (const Substitution &p : parts) {
        if (p.kind == Substitution::Kind::Concat) {
            for (const Substitution &q : p.parts)
                add(q);
        } else {
            add(p);
        }
    }
    if (out.isEmpty())
        return Substitution::literal(QString());
    return Substitution::concat(out);
}

namespace {
LaunchAction guardGroup(const Guard &g)
{
    LaunchAction group;
    group.kind = LaunchAction::Kind::Group;
    group.scoped = false;
    group.evidence = g.evidence;
    group.condition.expression = Substitution::unknown(g.text);
    group.condition.unless = g.unless;
    group.condition.text = g.text;
    return group;
}

void insertGuarded(QList<LaunchAction> &out, const GuardPath &path,
                   const QList<LaunchAction> &actions)
{
    if (actions.isEmpty())
        return;
    if (path.isEmpty()) {
        out += actions;
        return;
    }
    LaunchAction group = guardGroup(*path.first());
    if (!out.isEmpty()) {
        LaunchAction &last = out.last();
        // Consecutive additions under the same `if` share one group.
        if (last.kind == group.kind && !last.scoped && last.expression.isEmpty() &&
            last.condition == group.condition && last.evidence == group.evidence) {
            insertGuarded(last.children, path.mid(1), actions);
            return;
        }
    }
    insertGuarded(group.children, path.mid(1), actions);
    out.append(group);
}
} // namespace

namespace {
QList<LaunchAction> actionsOf(const Value &value, Walk &walk, int depth)
{
    using T = Value::Type;
    if (!walk.enter(depth))
        return {};
    switch (value.type) {
    case T::Action:
        return value.actions ? *value.actions : QList<LaunchAction>();
    case T::List: {
        QList<LaunchAction> out;
        for (qsizetype i = 0; i < value.list->items.size(); ++i)
            insertGuarded(out, value.list->guards.value(i),
                          actionsOf(value.list->items.at(i), walk, depth + 1));
        return out;
    }
    case T::Unknown:
    case T::Module: {
        LaunchAction a;
        a.kind = LaunchAction::Kind::Unresolved;
        a.expression = oneLine(value.text);
        a.evidence = value.evidence;
        return {a};
    }
    default:
        return {};
    }
}

bool actionsIn(const Value &v, Walk &walk, int depth)
{
    if (v.type == Value::Type::Action)
        return true;
    if (v.type != Value::Type::List || !walk.enter(depth))
        return false;
    if (v.list->launchDescription)
        return true;
    for (const Value &item : v.list->items)
        if (actionsIn(item, walk, depth + 1))
            return true;
    return false;
}
} // namespace

QList<LaunchAction> toActions(const Value &value)
{
    Walk walk;
    return actionsOf(value, walk, 0);
}

bool holdsActions(const Value &value)
{
    Walk walk;
    return actionsIn(value, walk, 0);
}

QString oneLine(const QString &text)
{
    QString s = text.simplified();
    s.replace(QStringLiteral("( "), QStringLiteral("("));
    s.replace(QStringLiteral("[ "), QStringLiteral("["));
    s.replace(QStringLiteral("{ "), QStringLiteral("{"));
    s.replace(QStringLiteral(", )"), QStringLiteral(")"));
    s.replace(QStringLiteral(", ]"), QStringLiteral("]"));
    s.replace(QStringLiteral(", }"), QStringLiteral("}"));
    s.replace(QStringLiteral(" )"), QStringLiteral(")"));
    s.replace(QStringLiteral(" ]"), QStringLiteral("]"));
    s.replace(QStringLiteral(" }"), QStringLiteral("}"));
    s = s.trimmed();
    constexpr qsizetype kMaxLength = 240; // a whole RegisterEventHandler(...) is not a label
    if (s.size() > kMaxLength)
        s = s.left(kMaxLength - 3) + QStringLiteral("...");
    return s;
}

} // namespace rosarch::pylaunch
