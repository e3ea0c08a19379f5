#include "project/correctedmodel.h"
#include "accepted/acceptedmodel.h"
#include "compose/composearchitecture.h"
#include "compose/subsystemgrouping.h"
#include "project/classifiercorrections.h"

#include <QHash>
#include <QSet>

namespace rosarch {

namespace {

// Applies corrections to stages 1 and 2, one at a time, keeping the keys of what is there now
// (a rename or an addition changes them; later corrections name the element as it is then).
class Corrector
{
public:
    Corrector(Recovery *model, QList<Orphan> *orphans) : m_model(model), m_orphans(orphans)
    {
        refresh();
    }

    void apply(const Correction &c)
    {
        m_current = &c;
        switch (c.kind) {
        case Correction::Kind::Rename:
            rename(c);
            break;
        case Correction::Kind::SetName:
            if (Port *p = port(c.target))
                setPortName(p, c.newValue);
            break;
        case Correction::Kind::SetType:
            if (Port *p = port(c.target)) {
                p->type = c.newValue;
                p->marks.provenance = Provenance::Corrected;
                m_composeAgain = true;
            }
            break;
        case Correction::Kind::Remove:
            remove(c);
            break;
        case Correction::Kind::AddPort:
            addPort(c);
            break;
        case Correction::Kind::AddPart:
            addPart(c);
            break;
        case Correction::Kind::AddConnection:
            addConnection(c);
            break;
        case Correction::Kind::Group:
            group(c);
            break;
        case Correction::Kind::Review:
            if (knows(c.target))
                m_reviewed.insert(c.target);
            break;
        case Correction::Kind::Describe:
            if (StableKeys::family(c.target) != QLatin1String("class"))
                orphan(QStringLiteral("%1 is not a class").arg(c.target));
            else if (knows(c.target))
                if (AtomicNode *n = node(m_keys.idOf(c.target))) {
                    n->description = c.newValue;
                    n->marks.provenance = Provenance::Corrected;
                }
            break;
        }
    }

    bool composeAgain() const { return m_composeAgain; }
    const QHash<QString, QString> &renamedChannels() const { return m_renamed; }
    const QList<SubsystemGroup> &groups() const { return m_groups; }
    const QSet<QString> &reviewed() const { return m_reviewed; }
    const StableKeys &keys() const { return m_keys; }

    /// Marks what was reviewed among classes, ports and instances (before stage 3, which
    /// carries the marks to parts and their ports).
    void markReviewed()
    {
        for (AtomicNode &n : m_model->nodes.nodes) {
            n.marks.reviewed = m_reviewed.contains(m_keys.keyOf(n.id));
            for (Port &p : n.ports)
                p.marks.reviewed = m_reviewed.contains(m_keys.keyOf(n.id + u'/' + p.id));
        }
        for (QList<NodeInstance> *list : {&m_model->launch.nodes, &m_model->launch.classifierNodes})
            for (NodeInstance &n : *list)
                n.marks.reviewed =
                    m_reviewed.contains(m_keys.keyOf(n.id)) ||
                    std::any_of(m_reviewed.cbegin(), m_reviewed.cend(), [&](const QString &key) {
                        return key.startsWith(u"part:") && m_keys.instancesOf(key).contains(n.id);
                    });
    }

private:
    void refresh() { m_keys = StableKeys(*m_model); }

    void orphan(const QString &reason)
    {
        Orphan o;
        o.source = Orphan::Source::Correction;
        o.id = m_current->id;
        o.kind = Correction::kindName(m_current->kind);
        o.target = m_current->target;
        o.said = m_current->summary();
        o.reason = reason;
        m_orphans->append(o);
    }

    bool knows(const QString &key)
    {
        if (m_keys.contains(key))
            return true;
        orphan(QStringLiteral("nothing in this recovery has the key %1").arg(key));
        return false;
    }

    AtomicNode *node(const QString &arcId)
    {
        for (AtomicNode &n : m_model->nodes.nodes)
            if (n.id == arcId)
                return &n;
        return nullptr;
    }

    Port *port(const QString &key)
    {
        if (StableKeys::family(key) != QLatin1String("port")) {
            orphan(QStringLiteral("%1 is not a port").arg(key));
            return nullptr;
        }
        if (!knows(key))
            return nullptr;
        const QString id = m_keys.idOf(key);
        AtomicNode *n = node(id.section(u'/', 0, 0));
        if (!n)
            return nullptr;
        for (Port &p : n->ports)
            if (p.id == id.section(u'/', 1))
                return &p;
        return nullptr;
    }

    QList<NodeInstance *> instances(const QString &key)
    {
        QList<NodeInstance *> out;
        const QString family = StableKeys::family(key);
        if ((family != QLatin1String("instance") && family != QLatin1String("part")) || !knows(key))
            return out;
        const QStringList ids = m_keys.instancesOf(key);
        for (QList<NodeInstance> *list : {&m_model->launch.nodes, &m_model->launch.classifierNodes})
            for (NodeInstance &n : *list)
                if (ids.contains(n.id))
                    out.append(&n);
        if (out.isEmpty())
            orphan(QStringLiteral("%1 is not a node instance").arg(key));
        return out;
    }

    void setPortName(Port *p, const QString &name)
    {
        p->name = name;
        p->nameOrigin = NameOrigin::Literal;
        p->parameter.clear();
        p->parameterPrefix.clear();
        p->parameterSuffix.clear();
        p->marks.provenance = Provenance::Corrected;
        m_composeAgain = true;
        refresh();
    }

    void rename(const Correction &c)
    {
        const QString family = StableKeys::family(c.target);
        if (family == QLatin1String("port")) {
            if (Port *p = port(c.target))
                setPortName(p, c.newValue);
        } else if (StableKeys::isChannelKey(c.target)) {
            if (knows(c.target)) {
                m_renamed.insert(c.target, c.newValue);
                m_composeAgain = true;
            }
        } else if (family == QLatin1String("instance") || family == QLatin1String("part")) {
            const QList<NodeInstance *> list = instances(c.target);
            for (NodeInstance *n : list) {
                n->nodeName = c.newValue;
                n->marks.provenance = Provenance::Corrected;
            }
            if (!list.isEmpty()) {
                m_composeAgain = true;
                refresh();
            }
        } else {
            orphan(QStringLiteral("%1 cannot be renamed").arg(c.target));
        }
    }

    void remove(const Correction &c)
    {
        const QString family = StableKeys::family(c.target);
        if (family == QLatin1String("class")) {
            if (!knows(c.target))
                return;
            const QString id = m_keys.idOf(c.target);
            m_model->nodes.nodes.removeIf([&](const AtomicNode &n) { return n.id == id; });
        } else if (family == QLatin1String("port")) {
            if (!knows(c.target))
                return;
            const QString id = m_keys.idOf(c.target);
            if (AtomicNode *n = node(id.section(u'/', 0, 0)))
                n->ports.removeIf([&](const Port &p) { return p.id == id.section(u'/', 1); });
        } else if (family == QLatin1String("instance") || family == QLatin1String("part")) {
            const QList<NodeInstance *> list = instances(c.target);
            if (list.isEmpty())
                return;
            if (!c.port.isEmpty()) { // one connection: the port of these instances
                if (!knows(c.port))
                    return;
                const QString portId = m_keys.idOf(c.port);
                for (NodeInstance *n : list)
                    if (n->classId == portId.section(u'/', 0, 0))
                        n->removedPorts.append(portId.section(u'/', 1));
                    else
                        n->removedPorts.append(portId); // an added port, by its own id
            } else {
                QSet<QString> ids;
                for (NodeInstance *n : list)
                    ids.insert(n->id);
                for (QList<NodeInstance> *nodes :
                     {&m_model->launch.nodes, &m_model->launch.classifierNodes})
                    nodes->removeIf([&](const NodeInstance &n) { return ids.contains(n.id); });
                for (QList<LaunchFileInstance> *lfs :
                     {&m_model->launch.instances, &m_model->launch.classifierInstances})
                    for (LaunchFileInstance &lf : *lfs)
                        lf.nodes.removeIf([&](const QString &id) { return ids.contains(id); });
            }
        } else {
            orphan(QStringLiteral("%1 cannot be removed").arg(c.target));
            return;
        }
        m_composeAgain = true;
        refresh();
    }

    static Port newPort(const Correction &c, const QString &id)
    {
        Port p;
        p.id = id;
        p.kind = c.portKind;
        p.name = c.newValue;
        p.type = c.type;
        p.marks.provenance = Provenance::Corrected;
        return p;
    }

    void addPort(const Correction &c)
    {
        if (StableKeys::family(c.target) != QLatin1String("class") || !knows(c.target)) {
            if (StableKeys::family(c.target) != QLatin1String("class"))
                orphan(QStringLiteral("%1 is not a class").arg(c.target));
            return;
        }
        AtomicNode *n = node(m_keys.idOf(c.target));
        const QString prefix = portIdPrefix(c.portKind);
        int highest = 0;
        for (const Port &p : n->ports)
            if (p.id.startsWith(prefix) && !p.id.mid(prefix.size()).isEmpty() &&
                p.id.mid(prefix.size()).at(0).isDigit())
                highest = std::max(highest, p.id.mid(prefix.size()).toInt());
        n->ports.append(newPort(c, prefix + QString::number(highest + 1)));
        m_composeAgain = true;
        refresh();
    }

    void addConnection(const Correction &c)
    {
        const QList<NodeInstance *> list = instances(c.target);
        // The name is the system's, as the person saw it; the instance's copies in the launch
        // files' own classifiers take it relative to the instance, so that it is the same
        // channel there (ClassifierCorrections).
        const auto isCopy = [this](const NodeInstance *n) {
            const QList<NodeInstance> &copies = m_model->launch.classifierNodes;
            return !copies.isEmpty() && n >= copies.constData() &&
                   n < copies.constData() + copies.size();
        };
        const auto system = std::find_if(list.cbegin(), list.cend(),
                                         [&](const NodeInstance *n) { return !isCopy(n); });
        for (NodeInstance *n : list) {
            Port p = newPort(c, QStringLiteral("%1_%2").arg(c.id, portIdPrefix(c.portKind)));
            if (isCopy(n) && system != list.cend())
                p.name = ClassifierCorrections::relativeTo(p.name, (*system)->nameSpace);
            n->addedPorts.append(p);
        }
        if (!list.isEmpty())
            m_composeAgain = true;
    }

    void addPart(const Correction &c)
    {
        if (StableKeys::family(c.target) != QLatin1String("launch")) {
            orphan(QStringLiteral("%1 is not a launch file").arg(c.target));
            return;
        }
        if (!knows(c.target) || !knows(c.classKey))
            return;
        const AtomicNode *cls = node(m_keys.idOf(c.classKey));
        for (auto [lfs, nodes] :
             {std::pair{&m_model->launch.instances, &m_model->launch.nodes},
              std::pair{&m_model->launch.classifierInstances, &m_model->launch.classifierNodes}}) {
            for (LaunchFileInstance &lf : *lfs) {
                if (StableKeys::launchKey(lf) != c.target)
                    continue;
                NodeInstance n;
                // ids stay unique in their list: the correction's id, per launch-file instance
                n.id = QStringLiteral("%1_%2").arg(c.id, lf.id);
                n.launchFileId = lf.id;
                n.package = cls->packageName;
                n.execName = cls->execution();
                n.className = cls->className;
                n.classId = cls->id;
                n.nodeKind = cls->compileType == AtomicNode::CompileType::Python
                                 ? QStringLiteral("python")
                                 : QStringLiteral("cpp");
                n.nodeName = c.newValue;
                n.nameSpace = c.nameSpace;
                if (n.nameSpace.isEmpty()) // where the file's own nodes are
                    for (const NodeInstance &sibling : std::as_const(*nodes))
                        if (sibling.launchFileId == lf.id) {
                            n.nameSpace = sibling.nameSpace;
                            break;
                        }
                // no source line says it: after every declared part, without evidence
                n.marks.provenance = Provenance::Corrected;
                lf.nodes.append(n.id);
                nodes->append(n);
            }
        }
        m_composeAgain = true;
        refresh();
    }

    void group(const Correction &c)
    {
        const QString family = StableKeys::family(c.target);
        if (family != QLatin1String("include") || !knows(c.target))
            return family == QLatin1String("include")
                       ? void()
                       : orphan(
                             QStringLiteral("%1 is not a root launch-file instance").arg(c.target));
        SubsystemGroup g;
        g.name = c.newValue;
        g.rootId = m_keys.idOf(c.target);
        for (const QString &member : c.members) {
            if (!m_keys.contains(member)) {
                orphan(QStringLiteral("member %1 is not in this recovery").arg(member));
                return;
            }
            g.memberInstanceIds += m_keys.instancesOf(member);
        }
        m_groups.append(g);
    }

    Recovery *m_model;
    QList<Orphan> *m_orphans;
    StableKeys m_keys;
    const Correction *m_current = nullptr;
    bool m_composeAgain = false;
    QHash<QString, QString> m_renamed;
    QList<SubsystemGroup> m_groups;
    QSet<QString> m_reviewed;
};

void markChannels(QList<Composite> *composites, const QSet<QString> &reviewed)
{
    for (Composite &c : *composites)
        for (Channel &ch : c.channels) {
            const QString family = ch.kind == Channel::Kind::Topic     ? QStringLiteral("topic")
                                   : ch.kind == Channel::Kind::Service ? QStringLiteral("service")
                                                                       : QStringLiteral("action");
            ch.marks.reviewed = reviewed.contains(family + u':' + ch.name);
        }
}

} // namespace

bool CorrectedModel::keyed(const SuggestionDecision &decision, const StableKeys &keys,
                           SuggestionDecision *out)
{
    SuggestionDecision d = decision;
    d.targetId = keys.keyOf(decision.targetId);
    if (d.targetId.isEmpty())
        return false;
    d.memberIds.clear();
    for (const QString &m : decision.memberIds) {
        const QString key = keys.keyOf(m);
        if (key.isEmpty())
            return false;
        d.memberIds.append(key);
    }
    *out = d;
    return true;
}

bool CorrectedModel::bound(const SuggestionDecision &decision, const StableKeys &keys,
                           SuggestionDecision *out, QString *reason)
{
    SuggestionDecision d = decision;
    d.targetId = keys.idOf(decision.targetId);
    if (d.targetId.isEmpty()) {
        *reason = QStringLiteral("nothing in this recovery has the key %1").arg(decision.targetId);
        return false;
    }
    d.memberIds.clear();
    for (const QString &m : decision.memberIds) {
        const QString id = keys.idOf(m); // the instance itself, not its CCD's copy
        if (id.isEmpty()) {
            *reason = QStringLiteral("member %1 is not in this recovery").arg(m);
            return false;
        }
        d.memberIds.append(id);
    }
    d.memberIds.sort();
    *out = d;
    return true;
}

CorrectedRecovery CorrectedModel::apply(const Recovery &recovered, const Project &project)
{
    CorrectedRecovery out;
    const StableKeys keys(recovered);
    for (const SuggestionDecision &d : project.decisions) {
        SuggestionDecision b;
        QString reason;
        if (bound(d, keys, &b, &reason)) {
            out.decisions.insert(b.key(), b);
            continue;
        }
        Orphan o;
        o.source = Orphan::Source::Decision;
        o.id = d.key();
        o.kind = Suggestion::kindName(d.kind);
        o.target = d.targetId;
        o.said = d.proposal;
        o.reason = reason;
        out.orphans.append(o);
    }
    if (project.corrections.isEmpty() && out.decisions.isEmpty()) {
        out.recovery = recovered;
        return out;
    }

    // Accepted suggestions, as AcceptedModel applies them, marked `suggested`.
    const AcceptedDecisions accepted = AcceptedModel::select(out.decisions, recovered);
    Recovery model = recovered;
    bool composeAgain = false;
    for (AtomicNode &n : model.nodes.nodes) {
        if (const auto it = accepted.descriptions.constFind(n.id);
            it != accepted.descriptions.cend()) {
            n.description = *it;
            n.marks.provenance = Provenance::Suggested;
        }
        for (Port &p : n.ports)
            if (const auto it = accepted.names.constFind(n.id + u'/' + p.id);
                it != accepted.names.cend() && !p.isResolved()) {
                p.name = *it;
                p.nameOrigin = NameOrigin::Literal;
                p.marks.provenance = Provenance::Suggested;
                composeAgain = true;
            }
    }

    Corrector corrector(&model, &out.orphans);
    for (const Correction &c : project.corrections)
        corrector.apply(c);
    corrector.markReviewed();
    if (composeAgain || corrector.composeAgain() || !corrector.reviewed().isEmpty()) {
        model.architecture =
            composeArchitecture(model.nodes, model.launch, {}, corrector.renamedChannels());
        ClassifierCorrections::rename(&model.architecture, model.nodes, model.launch,
                                      corrector.renamedChannels(), corrector.keys());
    }
    QList<SubsystemGroup> groups = accepted.groupings;
    // a grouping a person made is bound to this model's ids (a removed member is gone)
    for (const SubsystemGroup &g : corrector.groups())
        groups.append(g);
    model.architecture = SubsystemGrouping::apply(model.architecture, groups);
    markChannels(&model.architecture.composites, corrector.reviewed());
    markChannels(&model.architecture.classifiers, corrector.reviewed());
    out.recovery = std::move(model);
    return out;
}

} // namespace rosarch
