#include "nodes/cpp/cpphelperports.h"

#include "syntax/cppsyntax.h"

#include <QRegularExpression>
#include <QThread>

// Ports created through helpers: classes and free functions that receive the node (`this`,
// shared_from_this(), a procedural node) and create ports on it.
namespace rosarch {

using namespace cppsyntax;

namespace {

// "std::shared_ptr<ns::Helper<T>>", "ns::Helper::UniquePtr", "Helper *" -> "ns::Helper<T>".
QString classFromType(const QString &type)
{
    QString t = type.simplified();
    for (const char *prefix : {"const ", "mutable ", "static "})
        if (t.startsWith(QLatin1String(prefix)))
            t = t.mid(int(strlen(prefix)));
    t.remove(u' ');
    while (t.endsWith(u'*') || t.endsWith(u'&'))
        t.chop(1);
    for (const char *wrapper : {"std::shared_ptr<", "std::unique_ptr<", "std::weak_ptr<",
                                "std::optional<", "shared_ptr<", "unique_ptr<"}) {
        if (t.startsWith(QLatin1String(wrapper)) && t.endsWith(u'>')) {
            t = t.mid(int(strlen(wrapper)));
            t.chop(1);
        }
    }
    QStringList parts = splitScope(t);
    while (parts.size() > 1 &&
           (parts.last() == QLatin1String("SharedPtr") ||
            parts.last() == QLatin1String("UniquePtr") || parts.last() == QLatin1String("Ptr")))
        parts.removeLast();
    return parts.join(QStringLiteral("::"));
}

bool looksLikeQos(const QString &text)
{
    return text.contains(QLatin1String("qos"), Qt::CaseInsensitive) ||
           text.contains(QLatin1String("QoS"));
}

} // namespace

CppHelperPorts::CppHelperPorts(
    const CppClassIndex &index, const CppNameResolver &names,
    const QHash<QString, QList<CppClassIndex::FunctionRef>> &freeFunctions,
    const std::vector<const CppProceduralNode *> &ownedNodes)
    : m_index(index), m_names(names), m_freeFunctionsByName(freeFunctions), m_ownedNodes(ownedNodes)
{
}

QList<Evidence> CppHelperPorts::takeBoundsHit() const
{
    const QMutexLocker lock(&m_boundsMutex);
    return m_boundsHit.take(QThread::currentThreadId());
}

void CppHelperPorts::boundHit(const Evidence &where) const
{
    const QMutexLocker lock(&m_boundsMutex);
    m_boundsHit[QThread::currentThreadId()].append(where);
}

bool CppHelperPorts::isOwner(int cls) const
{
    return cls >= 0 && cls < int(m_ownedNodes.size()) && m_ownedNodes[size_t(cls)];
}

void CppHelperPorts::addHelperPorts(const CppInstantiation &inst, const CppLinkContext &ctx,
                                    int depth, QList<Port> *ports) const
{
    if (depth > kMaxHelperDepth) {
        boundHit(inst.evidence);
        return;
    }
    bool handsNode = false;
    for (const CppValue &arg : inst.arguments)
        handsNode = handsNode || m_names.isNodeHandle(arg, ctx);
    if (!handsNode)
        return;
    QStringList templateArguments;
    const int helper = helperClass(inst, ctx, &templateArguments);
    if (helper < 0 || helper == ctx.cls)
        return;
    QList<Port> found = helperPorts(helper, inst.arguments, templateArguments, ctx, depth + 1);
    const QString guardParameter =
        inst.guard.isEmpty() ? QString() : m_names.guardParameter(inst.guardValue, ctx);
    // the value the tested parameter has when nothing sets it (a name's default, `"laser"`)
    const QString guardDefault =
        guardParameter.isEmpty() ? QString() : m_names.resolve(inst.guardValue, ctx).name;
    for (Port &p : found) { // the chain of call sites, outermost first
        p.viaEvidence.prepend(inst.evidence);
        // `if (type == "scan") sources_.push_back(make_shared<Scan>(...))`: a port of the
        // helper exists where the helper is built, decided per item when the test is.
        // A port's own test is kept beside it; the construction's decides where the port's
        // does not, and always where it tests an item of a list (`{sources}.type`).
        if (!guardParameter.isEmpty() &&
            (p.guardParameter.isEmpty() || guardParameter.contains(u'{'))) {
            p.guard = p.guard.isEmpty() ? inst.guard
                                        : QStringLiteral("%1 && %2").arg(inst.guard, p.guard);
            p.guardParameter = guardParameter;
            p.guardDefault = guardDefault != guardParameter && !guardDefault.contains(u'{')
                                 ? guardDefault
                                 : QString();
        }
    }
    *ports += found;
}

// `setup_publishers(node)`: the ports a free function creates on the node it is handed.
void CppHelperPorts::addFreeCallPorts(const CppFreeCall &call, const CppLinkContext &ctx, int depth,
                                      QList<Port> *ports) const
{
    const qsizetype before = ports->size();
    addFreeCallPortsAt(call, ctx, depth, ports);
    for (qsizetype i = before; i < ports->size(); ++i)
        (*ports)[i].viaEvidence.prepend(call.evidence);
}

void CppHelperPorts::addFreeCallPortsAt(const CppFreeCall &call, const CppLinkContext &ctx,
                                        int depth, QList<Port> *ports) const
{
    if (depth > kMaxHelperDepth) {
        boundHit(call.evidence);
        return;
    }
    bool handsNode = false;
    for (const CppValue &arg : call.arguments)
        handsNode = handsNode || m_names.isNodeHandle(arg, ctx);
    if (!handsNode)
        return;
    const int n = int(call.arguments.size());
    const QStringList written = splitScope(call.function);
    const QString scope = written.mid(0, written.size() - 1).join(QStringLiteral("::"));
    QList<CppClassIndex::FunctionRef> candidates;
    for (const auto &ref : m_freeFunctionsByName.value(written.value(written.size() - 1))) {
        const CppFunction *fn = ref.function;
        const QString ns = fn->namespaces.join(QStringLiteral("::"));
        if (fn == ctx.fn || n < fn->requiredParameters ||
            (!fn->variadic && n > fn->parameterNames.size()) ||
            (!scope.isEmpty() && ns != scope && !ns.endsWith(QStringLiteral("::") + scope)))
            continue;
        candidates.append(ref);
    }
    // Inside a helper, a method called with the node (`configure(node)`) hands it on to what
    // that method instantiates; its own port calls are already counted with the helper.
    if (ctx.subst && ctx.cls >= 0) {
        for (int c : m_index.lineage(ctx.cls)) {
            for (const auto &ref : m_index.at(c).functions) {
                const CppFunction *fn = ref.function;
                if (fn == ctx.fn || fn->isConstructor ||
                    fn->name != written.value(written.size() - 1) || n < fn->requiredParameters ||
                    (!fn->variadic && n > fn->parameterNames.size()))
                    continue;
                const CppSubstitution subst{call.arguments, ctx, ctx.subst->templateArguments, fn};
                const CppLinkContext inner{ctx.cls, fn, ref.file, &subst};
                addCallPorts(*fn, inner, depth + 1, ports);
            }
        }
    }
    // A same-named function in the caller's package wins over the rest of the workspace.
    const QString package = ctx.file ? ctx.file->package : QString();
    if (std::any_of(candidates.begin(), candidates.end(),
                    [&](const auto &ref) { return ref.file->package == package; }))
        candidates.removeIf([&](const auto &ref) { return ref.file->package != package; });
    for (const auto &ref : std::as_const(candidates)) {
        const CppFunction *fn = ref.function;
        const CppSubstitution subst{call.arguments, ctx, {}, fn};
        const CppLinkContext inner{-1, fn, ref.file, &subst};
        for (const CppPortCall &port : fn->ports) {
            if (port.typeIsTemplateParameter)
                continue;
            Port p = m_names.port(port, inner);
            p.via = fn->name;
            ports->append(p);
        }
        addCallPorts(*fn, inner, depth + 1, ports);
    }
}

void CppHelperPorts::addCallPorts(const CppFunction &fn, const CppLinkContext &ctx, int depth,
                                  QList<Port> *ports) const
{
    for (const CppInstantiation &inst : fn.instantiations)
        addHelperPorts(inst, ctx, depth, ports);
    for (const CppFreeCall &call : fn.freeCalls)
        addFreeCallPorts(call, ctx, depth, ports);
    for (const CppMethodCall &call : fn.methodCalls)
        addMethodCallPorts(call, ctx, depth, ports);
}

bool CppHelperPorts::handsNode(const QList<CppValue> &arguments, const CppLinkContext &ctx) const
{
    return std::any_of(arguments.begin(), arguments.end(),
                       [&](const CppValue &arg) { return m_names.isNodeHandle(arg, ctx); });
}

void CppHelperPorts::addMemberHelperPorts(int cls, int self, QList<Port> *ports) const
{
    const CppClassIndex::ClassInfo &info = m_index.at(cls);
    const CppLinkContext ctx{cls, nullptr, info.file, nullptr, self};
    for (const CppInstantiation &inst : info.cls->memberInstantiations)
        addHelperPorts(inst, ctx, 0, ports);
}

void CppHelperPorts::addMethodCallPorts(const CppMethodCall &call, const CppLinkContext &ctx,
                                        int depth, QList<Port> *ports) const
{
    if (depth > kMaxHelperDepth)
        boundHit(call.evidence);
    if (depth > kMaxHelperDepth || ctx.cls < 0)
        return;
    CppInstantiation asMember;
    asMember.member = call.member;
    QStringList classArguments;
    const int helper = helperClass(asMember, ctx, &classArguments);
    if (helper < 0 || helper == ctx.cls)
        return;
    // The object must have been built with the node somewhere in the class.
    const CppInstantiation *built = nullptr;
    CppLinkContext builtAt;
    for (int c : m_index.lineage(ctx.cls)) {
        for (const auto &ref : m_index.at(c).functions) {
            const CppLinkContext at{c, ref.function, ref.file, ctx.subst, ctx.self};
            for (const CppInstantiation &inst : ref.function->instantiations) {
                QStringList unused;
                if (!built && (inst.member.isEmpty() || inst.member == call.member) &&
                    helperClass(inst, at, &unused) == helper && handsNode(inst.arguments, at)) {
                    built = &inst;
                    builtAt = at;
                }
            }
        }
    }
    if (!built)
        return;
    const CppSubstitution constructed{built->arguments, builtAt, {}, nullptr};
    const int n = int(call.arguments.size());
    const QStringList &classParameters = m_index.at(helper).cls->templateParameters;
    for (const auto &ref : m_index.at(helper).functions) {
        const CppFunction *fn = ref.function;
        if (fn->name != call.method || fn->isConstructor || fn->ports.isEmpty() ||
            n < fn->requiredParameters || (!fn->variadic && n > fn->parameterNames.size()))
            continue;
        CppSubstitution subst{call.arguments, ctx, {}, fn};
        subst.constructed = &constructed;
        for (qsizetype i = 0; i < classParameters.size() && i < classArguments.size(); ++i)
            subst.templateArguments.insert(classParameters.at(i),
                                           m_names.expandAliases(classArguments.at(i), ctx));
        for (qsizetype i = 0;
             i < fn->templateParameters.size() && i < call.templateArguments.size(); ++i)
            subst.templateArguments.insert(
                fn->templateParameters.at(i),
                m_names.expandAliases(call.templateArguments.at(i), ctx));
        const CppLinkContext inner{helper, fn, ref.file, &subst};
        for (const CppPortCall &port : fn->ports) {
            if (port.typeIsTemplateParameter &&
                !subst.templateArguments.contains(splitScope(port.typeWritten).value(0)))
                continue;
            Port p = m_names.port(port, inner);
            p.via = m_index.at(helper).cls->name;
            p.viaEvidence = {call.evidence};
            // `if (publishers_.count(name) == 0)` makes the port on first use: no guard.
            if (std::any_of(fn->parameterNames.begin(), fn->parameterNames.end(),
                            [&](const QString &key) {
                                return !key.isEmpty() &&
                                       QRegularExpression(QStringLiteral("\\b%1\\b").arg(key))
                                           .match(p.guard)
                                           .hasMatch();
                            })) {
                p.guard.clear();
                p.guardParameter.clear();
                p.guardDefault.clear();
            }
            // Created once per name: a second call with the same name is the same port.
            const bool seen = std::any_of(ports->begin(), ports->end(), [&](const Port &q) {
                return q.kind == p.kind && q.name == p.name && q.type == p.type && q.via == p.via;
            });
            if (!seen)
                ports->append(p);
        }
        return; // the first overload that creates ports (the others forward to it)
    }
}

int CppHelperPorts::helperClass(const CppInstantiation &inst, const CppLinkContext &ctx,
                                QStringList *templateArguments) const
{
    QString type = inst.className;
    if (type.isEmpty() && !inst.member.isEmpty() && ctx.cls >= 0) {
        for (int c : m_index.lineage(ctx.cls)) {
            type = m_index.at(c).cls->memberTypes.value(inst.member);
            if (!type.isEmpty())
                break;
        }
    }
    if (type.isEmpty())
        return -1;
    // `using ActionServer = SimpleActionServer<Action>; make_unique<ActionServer>(...)`
    const QString written = classFromType(m_names.expandAliases(classFromType(type), ctx));
    int h = m_index.lookup(withoutTemplateArguments(written), m_names.scopeOf(ctx), ctx.file);
    // A helper library that moved namespaces (autoware_utils:: for autoware::universe_utils::)
    // is taken by its class name when the workspace has exactly one class of that name.
    if (h < 0 && written.contains(QLatin1String("::")))
        h = m_index.uniqueBySimpleName(lastSegment(withoutTemplateArguments(written)));
    if (h < 0 || m_index.at(h).node || isOwner(h))
        return -1;
    *templateArguments = templateArgumentsOf(written);
    return h;
}

QList<Port> CppHelperPorts::helperPorts(int helper, const QList<CppValue> &arguments,
                                        const QStringList &templateArguments,
                                        const CppLinkContext &outer, int depth) const
{
    QList<Port> ports;
    CppSubstitution subst{arguments, outer, {}};
    // A helper template (SimpleActionServer<ActionT>) gets its interface type from the
    // instantiation.
    const QStringList &parameters = m_index.at(helper).cls->templateParameters;
    for (qsizetype i = 0; i < parameters.size() && i < templateArguments.size(); ++i)
        subst.templateArguments.insert(parameters.at(i),
                                       m_names.expandAliases(templateArguments.at(i), outer));
    const QString via = m_index.at(helper).cls->name;
    QList<const CppFunction *> constructors;
    for (const auto &ref : m_index.at(helper).functions)
        if (ref.function->isConstructor)
            constructors.append(ref.function);
    for (int c : m_index.lineage(helper)) {
        for (const auto &ref : m_index.at(c).functions) {
            if (c == helper && ref.function->isConstructor &&
                !constructorApplies(*ref.function, arguments, constructors))
                continue;
            const CppLinkContext ctx{helper, ref.function, ref.file, &subst};
            for (const CppPortCall &call : ref.function->ports) {
                if (call.typeIsTemplateParameter &&
                    !subst.templateArguments.contains(splitScope(call.typeWritten).value(0)))
                    continue;
                Port p = m_names.port(call, ctx);
                p.via = via;
                ports.append(p);
            }
            addCallPorts(*ref.function, ctx, depth, &ports);
        }
    }
    return ports;
}

// Of overloaded constructors, only those the instantiation can call create ports: the
// argument count must fit, and a QoS argument should meet a QoS parameter.
bool CppHelperPorts::constructorApplies(const CppFunction &fn, const QList<CppValue> &arguments,
                                        const QList<const CppFunction *> &constructors) const
{
    const int n = int(arguments.size());
    auto fits = [n](const CppFunction *c) {
        return n >= c->requiredParameters && (c->variadic || n <= c->parameterNames.size());
    };
    auto score = [&](const CppFunction *c) {
        int s = 0;
        for (int i = 0; i < n && i < c->parameterTypes.size(); ++i)
            s +=
                looksLikeQos(arguments.at(i).text) == looksLikeQos(c->parameterTypes.at(i)) ? 1 : 0;
        return s;
    };
    int best = -1;
    for (const CppFunction *c : constructors)
        if (fits(c))
            best = std::max(best, score(c));
    if (best < 0)
        return true; // nothing fits: the parse is incomplete, keep everything
    return fits(&fn) && score(&fn) == best;
}

// A member `message_filters::Subscriber<T>` subscribes where it is constructed with a node
// and a name (`sub_(this, "input/x", qos)` in a constructor's initializer list) or told to
// (`sub_.subscribe(this, "~/input/x", qos)`); its messages go to a synchronizer. An
// `image_transport::SubscriberFilter` does the same for images, with the transport before the
// QoS (`sub_.subscribe(this, "~/input/image", "raw", qos)`).
void CppHelperPorts::addMessageFilterPorts(int cls, const CppClassIndex::FunctionRef &ref,
                                           QList<Port> *ports) const
{
    const auto subscriberType = [&](const QString &member, bool *image) -> QString {
        for (int c : m_index.lineage(cls)) {
            const QString type = m_index.at(c).cls->memberTypes.value(member);
            if (type.isEmpty())
                continue;
            QString plain = withoutTemplateArguments(type).remove(u' ');
            if (plain.startsWith(QLatin1String("::")))
                plain = plain.mid(2);
            *image = plain == QLatin1String("image_transport::SubscriberFilter");
            if (*image)
                return QStringLiteral("sensor_msgs::msg::Image");
            return plain == QLatin1String("message_filters::Subscriber")
                       ? templateArgumentsOf(type.simplified()).value(0)
                       : QString();
        }
        return {};
    };
    const CppLinkContext ctx{cls, ref.function, ref.file, nullptr};
    const auto add = [&](const QString &member, const QList<CppValue> &arguments,
                         const Evidence &evidence, const QString &guard = {},
                         const CppValue &guardValue = {}) {
        if (arguments.size() < 2 || arguments.front().kind != CppValue::Kind::SelfNode)
            return;
        bool image = false;
        const QString type = subscriberType(member, &image);
        if (type.isEmpty())
            return;
        CppPortCall call;
        call.kind = PortKind::Subscriber;
        call.name = arguments.at(1);
        call.typeWritten = type;
        if (const int qos = image ? 3 : 2; arguments.size() > qos)
            call.qos = arguments.at(qos).text;
        call.guard = guard;
        call.guardValue = guardValue;
        call.evidence = evidence;
        ports->append(m_names.port(call, ctx));
    };
    for (const CppInstantiation &inst : ref.function->instantiations)
        if (!inst.member.isEmpty())
            add(inst.member, inst.arguments, inst.evidence);
    for (const CppMethodCall &call : ref.function->methodCalls)
        if (call.method == QLatin1String("subscribe"))
            add(call.member, call.arguments, call.evidence, call.guard, call.guardValue);
}

} // namespace rosarch
