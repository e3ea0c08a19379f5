#include "diff/architecturesnapshot.h"
#include "artifacts/architecturejson.h"
#include "artifacts/atomicnodesjson.h"
#include "artifacts/jsonsupport.h"
#include "plantuml/ccdwriter.h"

#include <QDir>
#include <QFile>
#include <QHash>

namespace rosarch {

using JsonSupport::Json;
using JsonSupport::string;

namespace {

QString familyOf(const QString &portKind)
{
    if (portKind == QLatin1String("publisher") || portKind == QLatin1String("subscriber"))
        return QStringLiteral("topic");
    if (portKind.startsWith(QLatin1String("service")))
        return QStringLiteral("service");
    return QStringLiteral("action");
}

QString verb(const QString &connectionKind)
{
    static const QHash<QString, QString> verbs = {
        {QStringLiteral("publish"), QStringLiteral("publishes")},
        {QStringLiteral("subscribe"), QStringLiteral("subscribes to")},
        {QStringLiteral("client"), QStringLiteral("calls")},
        {QStringLiteral("server"), QStringLiteral("serves")}};
    return verbs.value(connectionKind, connectionKind);
}

/// A connection's verb from the kind of the part's port (delegations included).
QString verbOfPort(const QString &portKind)
{
    if (portKind == QLatin1String("publisher"))
        return verb(QStringLiteral("publish"));
    if (portKind == QLatin1String("subscriber"))
        return verb(QStringLiteral("subscribe"));
    if (portKind.endsWith(QLatin1String("client")))
        return verb(QStringLiteral("client"));
    return verb(QStringLiteral("server"));
}

bool readComposites(const Json &root, ArchitectureSnapshot *out, QString *error)
{
    const auto list = root.find("list_composed_ros_node_classifiers");
    if (list == root.end() || !list->is_array()) {
        *error = QStringLiteral("architecture.json has no list_composed_ros_node_classifiers");
        return false;
    }
    for (const Json &c : *list) {
        // The CCD of a launch file is its first instance: the one that names a ccd file.
        const QString file = string(c, "launch_file");
        if (!c.contains("ccd") || file.isEmpty() || out->composites.contains(file))
            continue;
        ArchitectureSnapshot::Composite comp;
        comp.file = file;
        QHash<QString, QString> partKeys;  // part id -> key
        QHash<QString, QString> portKinds; // "part/port" -> port kind
        QHash<QString, int> seen;
        for (const Json &p : c.value("parts", Json::array())) {
            const bool node = string(p, "kind") == QLatin1String("node");
            const QString ns = string(p, "namespace");
            QString key =
                node ? (ns == QLatin1String("/") ? QString() : ns) + QLatin1Char('/') +
                           string(p, "name")
                     : QLatin1Char(':') + string(p, "type") +
                           (ns == QLatin1String("/") ? QString() : QStringLiteral(" in ") + ns);
            if (const int n = seen[key]++; n > 0)
                key += QStringLiteral(" #%1").arg(n + 1);
            partKeys.insert(string(p, "id"), key);
            comp.parts.append({key, string(p, "type")});
            for (const Json &port : p.value("ports", Json::array()))
                portKinds.insert(string(p, "id") + QLatin1Char('/') + string(port, "id"),
                                 string(port, "kind"));
        }
        QHash<QString, QString> targets; // channel or boundary id -> "topic /name"
        for (const Json &ch : c.value("channels", Json::array())) {
            const ArchitectureSnapshot::Name n{string(ch, "kind"), string(ch, "name"),
                                               string(ch, "type")};
            targets.insert(string(ch, "id"), n.kind + QLatin1Char(' ') + n.name);
            comp.names.append(n);
        }
        for (const Json &b : c.value("boundary_ports", Json::array())) {
            const ArchitectureSnapshot::Name n{familyOf(string(b, "kind")), string(b, "name"),
                                               string(b, "type")};
            targets.insert(string(b, "id"), n.kind + QLatin1Char(' ') + n.name);
            const bool known = std::any_of(comp.names.begin(), comp.names.end(), [&](auto &o) {
                return o.kind == n.kind && o.name == n.name;
            });
            if (!known)
                comp.names.append(n);
        }
        for (const Json &k : c.value("connections", Json::array())) {
            const QString part = string(k, "part");
            const QString kind = portKinds.value(part + QLatin1Char('/') + string(k, "port"));
            const QString text = QStringLiteral("%1 %2 %3")
                                     .arg(partKeys.value(part, part), verbOfPort(kind),
                                          targets.value(string(k, "target"), string(k, "target")));
            if (!comp.connections.contains(text))
                comp.connections.append(text);
        }
        comp.connections.sort();
        out->composites.insert(file, comp);
    }
    return true;
}

} // namespace

bool ArchitectureSnapshot::read(const QByteArray &atomicNodes, const QByteArray &architecture,
                                ArchitectureSnapshot *out, QString *error)
{
    *out = {};
    AtomicNodeList nodes;
    if (!AtomicNodesJson::read(atomicNodes, &nodes, error))
        return false;
    QHash<QString, int> seen;
    for (const AtomicNode &n : nodes.nodes) {
        NodeClass c;
        c.name = n.className;
        c.key = n.packageName + QLatin1Char('/') +
                (n.qualifiedName.isEmpty() ? n.className : n.qualifiedName);
        if (const int k = seen[c.key]++; k > 0)
            c.key += QStringLiteral(" #%1").arg(k + 1);
        for (const rosarch::Port &p : n.ports)
            c.ports.append({portKindName(p.kind), p.name, p.type});
        out->classes.insert(c.key, c);
    }
    if (architecture.trimmed().isEmpty())
        return true;
    const Json root = Json::parse(architecture.toStdString(), nullptr, false);
    if (root.is_discarded() || !root.is_object()) {
        *error = QStringLiteral("architecture.json is not valid JSON");
        return false;
    }
    return readComposites(root, out, error);
}

bool ArchitectureSnapshot::load(const QString &folder, ArchitectureSnapshot *out, QString *error)
{
    const QDir dir(folder);
    QFile nodes(dir.filePath(QStringLiteral("atomic_nodes.json")));
    if (!nodes.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1 has no readable atomic_nodes.json (is it a folder `rosarch "
                                "recover` wrote?)")
                     .arg(folder);
        return false;
    }
    QFile arch(dir.filePath(QStringLiteral("architecture.json")));
    const QByteArray architecture = arch.open(QIODevice::ReadOnly) ? arch.readAll() : QByteArray();
    QString why;
    if (!read(nodes.readAll(), architecture, out, &why)) {
        *error = QStringLiteral("%1: %2").arg(folder, why);
        return false;
    }
    return true;
}

ArchitectureSnapshot ArchitectureSnapshot::of(const Recovery &recovery)
{
    ArchitectureSnapshot s;
    QString error;
    read(
        AtomicNodesJson::write(recovery.nodes),
        ArchitectureJson::write(recovery.architecture, CcdWriter::fileStems(recovery.architecture)),
        &s, &error);
    return s;
}

} // namespace rosarch
