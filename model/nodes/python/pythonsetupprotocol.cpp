#include "nodes/python/pythonsetupprotocol.h"

#include "nodes/python/pythonbinding.h"

#include <utility>

namespace rosarch {

PythonSetupProtocol::PythonSetupProtocol(const PythonDefinitionIndex &index, NodeTest isNode,
                                         HelperPorts helperPorts)
    : m_index(index), m_isNode(std::move(isNode)), m_helperPorts(std::move(helperPorts))
{
}

bool PythonSetupProtocol::isSetupHandoff(const PythonHandoff &handoff)
{
    // setup hands the node to every behaviour of the tree
    return handoff.target.section(QLatin1Char('.'), -1) == QLatin1String("setup") &&
           (handoff.keyword == QLatin1String("node") ||
            (handoff.keyword.isEmpty() && handoff.argument == 0));
}

QList<Port> PythonSetupProtocol::setupPorts(const PythonHandoff &handoff,
                                            const PythonScopeFacts &from, int depth) const
{
    // py_trees' setup(node=...) reaches every behaviour of the tree; the tree is built from
    // the workspace classes instantiated where the node sets it up, directly or in functions
    // called from there
    Reach reach;
    reachInstantiations(from, nullptr, nullptr, {handoff.evidence}, depth, &reach);
    QList<Port> out;
    for (const Instantiation &i : reach.found) {
        for (const MethodPort &mp : setupClassPorts(i.id, i.arguments, depth + 1)) {
            Port p = mp.port;
            p.via = m_index.classFacts(i.id).name;
            p.viaEvidence = i.chain + p.viaEvidence;
            out.append(p);
        }
    }
    return out;
}

void PythonSetupProtocol::reachInstantiations(const PythonScopeFacts &scope,
                                              const QList<PythonArgument> *bound,
                                              const QList<PythonParameter> *parameters,
                                              const QList<Evidence> &chain, int depth,
                                              Reach *reach) const
{
    reach->open.append(&scope);
    for (const PythonCall &call : scope.calls) {
        const int cls = m_index.findClass(call.target);
        const int fn = cls >= 0 ? -1 : m_index.findFunction(call.target);
        if ((cls < 0 && fn < 0) || (cls >= 0 && m_isNode(cls)))
            continue;
        if (reach->stopped)
            break;
        const bool deep = depth > kMaxDepth;
        reach->stopped = reach->found.size() >= kMaxInstantiations || reach->visits >= kMaxVisits;
        if (deep || reach->stopped) {
            if (!reach->reported)
                reportBound(call.evidence, QStringLiteral("classes that build the behaviour tree"));
            reach->reported = true;
            break;
        }
        const QList<PythonArgument> arguments =
            bound ? PythonBinding::bind(call.arguments, *bound, *parameters) : call.arguments;
        const QList<Evidence> here = chain + QList<Evidence>{call.evidence};
        if (cls >= 0)
            reach->found.append({cls, arguments, here});
        // what a workspace class or function builds in turn (a composite of its own, a
        // function returning a subtree)
        const PythonScopeFacts *next =
            cls >= 0 ? static_cast<const PythonScopeFacts *>(&m_index.classFacts(cls))
                     : &m_index.functionFacts(fn);
        if (reach->open.contains(next))
            continue;
        ++reach->visits;
        if (cls >= 0)
            reachInstantiations(*next, nullptr, nullptr, here, depth + 1, reach);
        else
            reachInstantiations(*next, &arguments, &m_index.functionFacts(fn).parameters, here,
                                depth + 1, reach);
    }
    reach->open.removeLast();
}

QList<PythonSetupProtocol::MethodPort>
PythonSetupProtocol::setupClassPorts(int id, const QList<PythonArgument> &arguments,
                                     int depth) const
{
    QList<MethodPort> out;
    const PythonClassFacts &c = m_index.classFacts(id);
    if (depth > kMaxDepth) {
        reportBound(c.evidence, QStringLiteral("base classes of a behaviour"));
        return out;
    }
    PythonHandle setup;
    setup.kind = PythonHandle::Kind::Setup;
    for (const PythonPortFact &f : c.ports) {
        if (!f.handle.sameAs(setup))
            continue;
        MethodPort mp;
        mp.port = f.port;
        mp.method = f.method;
        PythonBinding::applyArguments(&mp.port, f, QString(), arguments, &c.initParameters);
        out.append(mp);
    }
    for (const PythonHandoff &h : c.handoffs) {
        if (!h.handle.sameAs(setup))
            continue;
        for (const Port &p : m_helperPorts(h, c, depth + 1))
            out.append({p, h.method});
    }
    for (int base : m_index.projectBases(id)) {
        for (const MethodPort &mp :
             setupClassPorts(base, PythonBinding::forwardToBase(c, arguments), depth + 1)) {
            // an override that does not call the base's version replaces its ports
            if (!mp.method.isEmpty() && c.methods.contains(mp.method) &&
                !c.superCalledMethods.contains(mp.method))
                continue;
            out.append(mp);
        }
    }
    return out;
}

void PythonSetupProtocol::reportBound(const Evidence &at, const QString &what) const
{
    Diagnostic d;
    d.severity = Diagnostic::Severity::Info;
    d.code = QStringLiteral("helper-depth");
    d.message = QStringLiteral("Stopped following %1 here (bounds: %2 levels; %3 classes and "
                               "%4 calls per tree); ports created beyond it are not given to "
                               "the node.")
                    .arg(what)
                    .arg(kMaxDepth)
                    .arg(kMaxInstantiations)
                    .arg(kMaxVisits);
    d.evidence = at;
    if (!m_diagnostics.contains(d))
        m_diagnostics.append(d);
}

} // namespace rosarch
