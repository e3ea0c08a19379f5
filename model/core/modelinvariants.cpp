#include "core/modelinvariants.h"

#include <QRegularExpression>
#include <QSet>

namespace rosarch {

namespace {

// A ROS name, where a placeholder an instance fills (`{plugin}`, `{sources}`,
// `{plugin:CostmapLayer}`) stands for a name part.
bool isRosName(QString name)
{
    static const QRegularExpression placeholder(QStringLiteral(R"(\{[A-Za-z0-9_.:]+\})"));
    static const QRegularExpression ros(QStringLiteral("^(~/?|/)?[A-Za-z_][A-Za-z0-9_/~]*$"));
    name.replace(placeholder, QStringLiteral("x"));
    return ros.match(name).hasMatch();
}

} // namespace

QStringList modelInvariantViolations(const AtomicNodeList &nodes)
{
    QStringList out;
    for (const AtomicNode &n : nodes.nodes) {
        if (!n.nodeName.isEmpty() && !isRosName(n.nodeName))
            out << QStringLiteral("%1: node name '%2' is no ROS name").arg(n.className, n.nodeName);
        QSet<QString> seen;
        for (const Port &p : n.ports) {
            if (p.nameOrigin != NameOrigin::Expression && !p.name.isEmpty() && !isRosName(p.name))
                out << QStringLiteral("%1: port name '%2' is no ROS name").arg(n.className, p.name);
            const QString key = QStringLiteral("%1 %2 %3 %4:%5:%6")
                                    .arg(int(p.kind))
                                    .arg(p.name, p.type, p.evidence.file)
                                    .arg(p.evidence.line)
                                    .arg(p.evidence.column);
            if (seen.contains(key))
                out << QStringLiteral("%1: port '%2' listed twice").arg(n.className, p.name);
            seen.insert(key);
        }
    }
    return out;
}

} // namespace rosarch
