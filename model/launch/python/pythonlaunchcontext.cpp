#include "launch/python/pythonlaunchcontext.h"

namespace rosarch::pylaunch {

namespace {
constexpr int kMaxSteps = 200000;
constexpr int kMaxIteratedChars = 256;
} // namespace

PythonLaunchContext::PythonLaunchContext(const SyntaxTree &tree) : tree(tree)
{
    module = newScope(nullptr);
}

PythonLaunchContext::~PythonLaunchContext()
{
    for (const auto &l : m_lists)
        if (auto list = l.lock())
            list->items.clear();
    for (const auto &d : m_dicts)
        if (auto dict = d.lock())
            dict->entries.clear();
    for (const auto &s : m_scopes)
        if (auto scope = s.lock()) {
            scope->vars.clear();
            scope->parent.reset();
        }
}

Value PythonLaunchContext::unknownAt(TSNode node) const
{
    return Value::unknown(tree.text(node), tree.evidence(node));
}

Value PythonLaunchContext::newList(QList<Value> items, bool tuple)
{
    Value v = Value::makeList(std::move(items), tuple);
    v.list->createdUnder = guards;
    m_lists.push_back(v.list);
    return v;
}

Value PythonLaunchContext::newDict()
{
    Value v = Value::makeDict();
    v.dict->createdUnder = guards;
    m_dicts.push_back(v.dict);
    return v;
}

std::shared_ptr<Scope> PythonLaunchContext::newScope(std::shared_ptr<Scope> parent)
{
    auto scope = std::make_shared<Scope>();
    scope->parent = std::move(parent);
    m_scopes.push_back(scope);
    return scope;
}

void PythonLaunchContext::append(const Value &list, const Value &item)
{
    if (list.type != Value::Type::List)
        return;
    if (list.list->items.size() >= kMaxListSize) {
        approximate = true;
        return;
    }
    list.list->items << item;
    list.list->guards << relativeGuards(list.list->createdUnder, guards);
}

QList<Value> PythonLaunchContext::iterate(const Value &value, bool *known)
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
        approximate = approximate || value.text.size() > kMaxIteratedChars;
        for (QChar c : value.text.left(kMaxIteratedChars))
            chars << Value::string(QString(c));
        return chars;
    }
    default:
        *known = false;
        return {};
    }
}

bool PythonLaunchContext::step(TSNode at)
{
    if (++m_steps > kMaxSteps && !exhausted) {
        exhausted = true;
        stoppedAt = at;
    }
    return !exhausted;
}

bool PythonLaunchContext::stopped() const
{
    return exhausted || frame->returned || frame->breaking || frame->continuing;
}

QString PythonLaunchContext::textOf(TSNode node) const
{
    return tree.text(node);
}

const Value *CallArgs::get(int index, std::initializer_list<const char *> names) const
{
    for (const char *name : names)
        for (const auto &k : keywords)
            if (k.first == QLatin1String(name))
                return &k.second;
    if (index >= 0 && index < positional.size())
        return &positional.at(index);
    return nullptr;
}

TSNode CallArgs::node(int index, std::initializer_list<const char *> names) const
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
