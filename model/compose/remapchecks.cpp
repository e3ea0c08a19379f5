#include "compose/remapchecks.h"
#include "compose/checkscope.h"
#include "compose/composer.h"
#include "core/packageversion.h"
#include "core/rosnames.h"

#include <QHash>
#include <QSet>

#include <algorithm>

namespace rosarch {

namespace {

/// Whether `from` names a topic that a transport plugin advertises beside an image or point
/// cloud port (`~/output/image/compressed`): image_transport and point_cloud_transport publish
/// one topic per plugin under the port's name, which a launch file may remap; so does
/// cuda_blackboard (`~/output/pointcloud/cuda`).
bool renamesTransportTopic(const AtomicNode &cls, const QString &from)
{
    static const QStringList imagePlugins{
        QStringLiteral("compressed"), QStringLiteral("compressedDepth"), QStringLiteral("theora"),
        QStringLiteral("zstd"),       QStringLiteral("ffmpeg"),          QStringLiteral("h264")};
    // point_cloud_transport's plugins, and cuda_blackboard's negotiated GPU topic
    static const QStringList cloudPlugins{QStringLiteral("draco"), QStringLiteral("zlib"),
                                          QStringLiteral("zstd"), QStringLiteral("cuda")};
    const qsizetype slash = from.lastIndexOf(QLatin1Char('/'));
    if (slash <= 0)
        return false;
    const QString base = from.left(slash);
    const QString plugin = from.mid(slash + 1);
    const auto probe = [](const QString &name) {
        return RosNames::expand(name, QStringLiteral("/__probe"), QStringLiteral("__node"));
    };
    for (const Port &p : cls.ports) {
        const QStringList *plugins =
            p.type == QLatin1String("sensor_msgs/msg/Image")         ? &imagePlugins
            : p.type == QLatin1String("sensor_msgs/msg/PointCloud2") ? &cloudPlugins
                                                                     : nullptr;
        if (plugins && plugins->contains(plugin) && probe(p.name) == probe(base))
            return true;
    }
    return false;
}

/// " The launch file's package, a 0.52.0, is of a newer release than the node's, b 0.43.0: …"
/// when the package holding `launchFile` has a newer version than the node's package: the
/// remap may be written for another version of the node (one that has the port, or had it).
/// "" otherwise.
QString versionHint(const AtomicNodeList &nodes, const QString &launchFile,
                    const QString &nodePackage)
{
    const RosPackage *holder = nullptr;
    const RosPackage *node = nullptr;
    for (const RosPackage &p : nodes.packages) {
        if (p.name == nodePackage)
            node = &p;
        if (launchFile.startsWith(p.path + QLatin1Char('/')) &&
            (!holder || p.path.size() > holder->path.size()))
            holder = &p;
    }
    if (!holder || !node || holder == node)
        return {};
    if (holder->version.isEmpty() || node->version.isEmpty() ||
        compareVersions(holder->version, node->version) <= 0)
        return {};
    return QStringLiteral(" The launch file's package, %1 %2, is of a newer release than the "
                          "node's, %3 %4: the remap may be written for another version of the "
                          "node.")
        .arg(holder->name, holder->version, node->name, node->version);
}

} // namespace

void RemapChecks::run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                      QList<Diagnostic> *out)
{
    const QSet<QString> systems = CheckScope::judgedInstances(launch);
    struct Rule
    {
        QString text;
        Evidence evidence;
        QString hint; ///< when the launch file's package is newer than the node's
        bool used = false;
        bool decidable = true;
    };
    QList<Rule> rules;
    QHash<QString, int> index;
    // "package\nfrom" of the rules a launch file of the node's own package gives it: such a rule
    // is in the node's own release too, so a newer launch package is no explanation for it.
    QHash<QString, QString> packagePaths; // name -> folder
    for (const RosPackage &p : nodes.packages)
        packagePaths.insert(p.name, p.path + QLatin1Char('/'));
    QSet<QString> ownPackageRules;
    for (const NodeInstance &n : launch.nodes)
        if (const QString path = packagePaths.value(n.package);
            !path.isEmpty() && n.evidence.file.startsWith(path))
            for (const auto &[from, to] : n.remaps)
                ownPackageRules.insert(n.package + QLatin1Char('\n') + from);
    for (const NodeInstance &n : launch.nodes) {
        const AtomicNode *cls = nodes.node(n.classId);
        if (!cls || !n.active || !systems.contains(n.launchFileId))
            continue;
        QList<int> used;
        Composer::resolvePorts(*cls, n, nullptr, &used);
        const bool allResolved = std::all_of(cls->ports.begin(), cls->ports.end(),
                                             [](const Port &p) { return p.isResolved(); });
        for (qsizetype i = 0; i < n.remaps.size(); ++i) {
            const auto &[from, to] = n.remaps.at(i);
            if (!RosNames::isNameRule(from))
                continue;
            // A scoped SetRemap reaches nodes of several files: the rule is judged as a whole.
            const QString key = from + QLatin1Char('\n') + to;
            int at = index.value(key, -1);
            if (at < 0) {
                at = int(rules.size());
                index.insert(key, at);
                rules.append({QStringLiteral("%1:=%2").arg(from, to), n.evidence,
                              ownPackageRules.contains(n.package + QLatin1Char('\n') + from)
                                  ? QString()
                                  : versionHint(nodes, n.evidence.file, n.package)});
            }
            rules[at].used =
                rules[at].used || used.contains(int(i)) || renamesTransportTopic(*cls, from);
            rules[at].decidable = rules[at].decidable && allResolved && !to.isEmpty();
        }
    }
    for (const Rule &r : std::as_const(rules))
        if (!r.used && r.decidable)
            out->append(
                {Diagnostic::Severity::Warning,
                 QStringLiteral("remap-unmatched"),
                 QStringLiteral("The remap %1 matches no port of the nodes it applies to.%2")
                     .arg(r.text, r.hint),
                 r.evidence,
                 {}});
}

} // namespace rosarch
