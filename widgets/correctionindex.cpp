#include "widgets/correctionindex.h"
#include "document/document.h"

#include <QCoreApplication>

namespace rosarch {

CorrectionIndex::CorrectionIndex(const Document &document)
    : m_corrections(document.session()->corrections())
{
    if (m_corrections.isEmpty())
        return;
    const Recovery &corrected = document.accepted();
    m_corrected = StableKeys(corrected);
    m_recovered = document.session()->recoveredKeys(); // made once per model
    for (int i = 0; i < m_corrections.size(); ++i)
        m_byTarget[m_corrections[i].target].append(i);
    // A port a correction added has no key of its own as recovered: find it by what it says.
    for (const AtomicNode &n : corrected.nodes.nodes) {
        const AtomicNode *was = document.atomicNodes().node(n.id);
        for (const Port &p : n.ports) {
            const bool added = !was || std::none_of(was->ports.cbegin(), was->ports.cend(),
                                                    [&](const Port &q) { return q.id == p.id; });
            if (added)
                m_portNames.insert(n.id + u'/' + p.id, portKindName(p.kind) + u'|' + p.name);
        }
    }
}

QList<Correction> CorrectionIndex::of(const QString &id) const
{
    QList<Correction> out;
    if (m_corrections.isEmpty() || id.isEmpty())
        return out;
    QList<int> found;
    const auto addTarget = [&](const QString &key) {
        if (!key.isEmpty())
            for (int i : m_byTarget.value(key))
                if (!found.contains(i))
                    found.append(i);
    };
    addTarget(m_recovered.keyOf(id));
    addTarget(m_corrected.keyOf(id));
    const QString family = StableKeys::family(id);
    for (int i = 0; i < m_corrections.size(); ++i) {
        const Correction &c = m_corrections[i];
        bool touches = false;
        // a part a correction added: its ids are "<correction>_<launch-file instance>"
        if (c.kind == Correction::Kind::AddPart)
            touches = id.startsWith(c.id + u'_');
        else if (c.kind == Correction::Kind::AddPort)
            touches = m_portNames.value(id) == portKindName(c.portKind) + u'|' + c.newValue &&
                      m_corrected.keyOf(id.section(u'/', 0, 0)) == c.target;
        else if (c.kind == Correction::Kind::Rename && !family.isEmpty()) // a renamed channel
            touches = StableKeys::family(c.target) == family && family + u':' + c.newValue == id;
        if (touches && !found.contains(i))
            found.append(i);
    }
    std::sort(found.begin(), found.end());
    for (int i : found)
        out.append(m_corrections[i]);
    return out;
}

QString CorrectionIndex::removedBy(const QString &id) const
{
    for (const Correction &c : of(id))
        if (c.kind == Correction::Kind::Remove && c.port.isEmpty())
            return c.id;
    return {};
}

QString CorrectionIndex::summary(const QString &id) const
{
    QStringList lines;
    for (const Correction &c : of(id)) {
        QString line =
            QCoreApplication::translate("rosarch::CorrectionIndex", "%1 by %2 (%3): %4")
                .arg(c.kind == Correction::Kind::Review
                         ? QCoreApplication::translate("rosarch::CorrectionIndex", "Reviewed")
                         : QCoreApplication::translate("rosarch::CorrectionIndex", "Corrected"),
                     c.id, Correction::kindName(c.kind), c.summary());
        if (!c.reason.isEmpty())
            line += QStringLiteral(" (%1)").arg(c.reason);
        lines.append(line);
    }
    return lines.join(u'\n');
}

QString CorrectionIndex::keyOf(const QString &id) const
{
    const QString key = m_corrected.keyOf(id);
    return key.isEmpty() ? m_recovered.keyOf(id) : key;
}

QString CorrectionIndex::idOf(const QString &key) const
{
    const QString id = m_corrected.idOf(key);
    return id.isEmpty() ? m_recovered.idOf(key) : id;
}

} // namespace rosarch
