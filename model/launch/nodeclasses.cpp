#include "launch/nodeclasses.h"

#include <QSet>

namespace rosarch {

NodeClasses::NodeClasses(const AtomicNodeList &nodes)
{
    for (const AtomicNode &n : nodes.nodes) {
        QSet<QString> seen;
        for (const QString &e : n.executables)
            if (!seen.contains(e)) {
                seen.insert(e);
                m_byExecutable[n.packageName + QChar(0) + e].append(&n);
                m_byExecutableName[e].append(&n);
            }
        for (const QString &p : n.plugins)
            if (!m_byPlugin.contains(p))
                m_byPlugin.insert(p, &n);
        if (!n.isPlugin() && !n.procedural && !m_byQualifiedName.contains(n.qualifiedName))
            m_byQualifiedName.insert(n.qualifiedName, &n);
    }
}

QList<const AtomicNode *> NodeClasses::started(const QString &package, const QString &executable,
                                               bool plugin) const
{
    QString wanted = executable;
    if (plugin && wanted.startsWith(QLatin1String("::")))
        wanted.remove(0, 2);
    if (plugin) {
        const AtomicNode *n = m_byPlugin.value(wanted);
        return n ? QList<const AtomicNode *>{n} : QList<const AtomicNode *>{};
    }
    return m_byExecutable.value(package + QChar(0) + executable);
}

QList<NodeClasses::Start> NodeClasses::starts(const QList<const AtomicNode *> &classes,
                                              const QString &executable)
{
    QList<Start> out;
    for (const AtomicNode *cls : classes) {
        const qsizetype before = out.size();
        for (const NodeConstruction &k : cls->constructions)
            if (k.executable == executable)
                out.append({cls, &k});
        if (out.size() == before)
            out.append({cls, nullptr});
    }
    return out;
}

QList<const AtomicNode *> NodeClasses::elsewhere(const QString &executable, QString *builtBy) const
{
    // A package may install an executable under another package's name
    // (`install(TARGETS x DESTINATION lib/other)`): the one package of the workspace that
    // builds it, when there is exactly one.
    const QList<const AtomicNode *> out = m_byExecutableName.value(executable);
    QSet<QString> packages;
    for (const AtomicNode *n : out)
        packages.insert(n->packageName);
    if (packages.size() != 1)
        return {};
    *builtBy = *packages.cbegin();
    return out;
}

const AtomicNode *NodeClasses::node(const QString &qualifiedName) const
{
    return m_byQualifiedName.value(qualifiedName);
}

bool NodeClasses::declares(const RosPackage *package, const QString &name)
{
    if (!package)
        return false;
    for (const Executable &e : package->executables)
        if (e.name == name)
            return true;
    return false;
}

} // namespace rosarch
