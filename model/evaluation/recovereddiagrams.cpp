#include "recovereddiagrams.h"
#include "acdwriter.h"
#include "ccdwriter.h"
#include "plantumlreader.h"

namespace rosarch {

QList<UmlDiagram> recoveredDiagrams(const AtomicNodeList &nodes, const Architecture &architecture)
{
    QList<UmlDiagram> out;
    const QMap<QString, QString> acdStems = AcdWriter::fileStems(nodes);
    for (const AtomicNode &n : nodes.nodes)
        out += PlantUmlReader::read(AcdWriter::write(n),
                                    QStringLiteral("acd/%1.puml").arg(acdStems.value(n.id)));
    const QMap<QString, QString> ccdStems = CcdWriter::fileStems(architecture);
    for (const Composite *c : architecture.representatives())
        out += PlantUmlReader::read(
            CcdWriter::write(*c), QStringLiteral("ccd/%1.puml").arg(ccdStems.value(c->instanceId)));
    return out;
}

} // namespace rosarch
