#include "compose/systemports.h"

#include <algorithm>
#include <cstdlib>

namespace rosarch {

namespace {

QString keyOf(const QString &family, const QString &name)
{
    return family + QLatin1Char(' ') + name;
}

/// Whether two different names differ by one letter (replaced, added or left out) that is no
/// digit and no separator, within one segment of at least four letters.
bool oneLetterApart(QStringView a, QStringView b)
{
    if (a.size() > b.size())
        std::swap(a, b);
    qsizetype head = 0;
    while (head < a.size() && a[head] == b[head])
        ++head;
    qsizetype tail = 0;
    while (tail < a.size() - head && a[a.size() - 1 - tail] == b[b.size() - 1 - tail])
        ++tail;
    // what is left between the common head and tail: one letter of b, or one of each
    if (b.size() - head - tail != 1 || a.size() - head - tail > 1)
        return false;
    for (const QStringView side : {a, b})
        for (qsizetype i = head; i < side.size() - tail; ++i)
            if (side[i].isDigit() || side[i] == u'/')
                return false;
    const qsizetype start = b.lastIndexOf(u'/', head) + 1;
    qsizetype end = b.indexOf(u'/', head);
    if (end < 0)
        end = b.size();
    return end - start >= 4;
}

/// Whether two names with the same last segment are one in a namespace nested in the other's
/// (`/battery_state` or `/robot1/battery_state`, and `/robot1/monitoring/battery_state`), or
/// one with its namespace doubled (`/robot1/cmd_vel`, `/robot1/robot1/cmd_vel`).
bool nestedOrDoubled(const QString &a, const QString &b)
{
    const QString na = a.section(u'/', 0, -2) + QLatin1Char('/');
    const QString nb = b.section(u'/', 0, -2) + QLatin1Char('/');
    const QString &inner = na.size() < nb.size() ? na : nb;
    const QString &outer = na.size() < nb.size() ? nb : na;
    if (inner == outer)
        return false;
    if (outer.startsWith(inner))
        return true;
    const QString extra = outer.left(outer.size() - inner.size()); // "/robot1/"
    return outer.endsWith(inner) && inner.startsWith(extra);
}

/// A port whose namespace decides its name: written relative and not remapped. (Names a
/// launch file wired on purpose, by a remap to an absolute name, slip nowhere.)
bool placedByNamespace(const PartPort &port)
{
    return !port.remapped && !port.nameAsWritten.isEmpty() &&
           !port.nameAsWritten.startsWith(u'/') && !port.nameAsWritten.startsWith(u'~');
}

} // namespace

void SystemPorts::clear()
{
    m_families.clear();
    m_order.clear();
    m_byLastSegment.clear();
    m_byLength.clear();
}

void SystemPorts::add(const RosNodePart &part)
{
    for (const PartPort &port : part.ports) {
        if (!port.active || !port.resolved || port.guessed)
            continue;
        const QString key = keyOf(portFamilyName(port.kind), port.name);
        if (!m_families.contains(key)) {
            m_order.append(key);
            const QString family = portFamilyName(port.kind);
            m_byLastSegment[keyOf(family, port.name.section(u'/', -1))].append(key);
            m_byLength[keyOf(family, QString::number(port.name.size()))].append(key);
        }
        PortFamily &f = m_families[key];
        (isProvidingPort(port.kind) ? f.providers : f.users).append({&part, &port});
    }
}

const PortUse *SystemPorts::misspelling(const QString &family, const QString &name,
                                        bool wantProviders, const RosNodePart *except,
                                        QString *found) const
{
    // A name this long is no misspelling a person would make; and past the run's budget,
    // it stops looking.
    if (name.size() > 256 || hintsCut())
        return nullptr;
    const qsizetype prefix = family.size() + 1;
    // one letter apart: the lengths differ by at most one
    for (const qsizetype length : {name.size() - 1, name.size(), name.size() + 1}) {
        for (const QString &key : m_byLength.value(keyOf(family, QString::number(length)))) {
            const QStringView candidate = QStringView(key).mid(prefix);
            m_hintWork += candidate.size();
            if (candidate == name)
                continue;
            const auto it = m_families.constFind(key);
            const QList<PortUse> &side = wantProviders ? it->providers : it->users;
            const auto other = std::find_if(side.cbegin(), side.cend(),
                                            [&](const PortUse &u) { return u.part != except; });
            if (other == side.cend() || !oneLetterApart(name, candidate))
                continue;
            *found = candidate.toString();
            return &*other;
        }
    }
    return nullptr;
}

const PortUse *SystemPorts::namespaceSlip(const QString &family, const QString &name,
                                          const PortUse &use, bool wantProviders,
                                          QString *found) const
{
    if (!isCanonicalInterfaceType(use.port->type) || !name.startsWith(u'/'))
        return nullptr;
    const QString prefix = family + QLatin1Char(' ');
    for (const QString &key : m_byLastSegment.value(keyOf(family, name.section(u'/', -1)))) {
        const QString candidate = key.mid(prefix.size());
        if (candidate == name || !candidate.startsWith(u'/') || !nestedOrDoubled(name, candidate))
            continue;
        const PortFamily &f = *m_families.constFind(key);
        const QList<PortUse> &side = wantProviders ? f.providers : f.users;
        if (!(wantProviders ? f.users : f.providers).isEmpty())
            continue; // wired already: a name of its own
        for (const PortUse &u : side)
            if (u.part != use.part && u.port->type == use.port->type &&
                (placedByNamespace(*use.port) || placedByNamespace(*u.port))) {
                *found = candidate;
                return &u;
            }
    }
    return nullptr;
}

} // namespace rosarch
