#include "evaluation/recovereddiagrams.h"
#include "diagram/diagrambuilder.h"
#include "plantuml/acdwriter.h"
#include "plantuml/ccdwriter.h"
#include "plantuml/plantumlreader.h"

#include <QHash>

namespace rosarch {

namespace {

QString drawnKey(const CcdWriter::WrittenElement &e)
{
    using Kind = CcdWriter::WrittenElement::Kind;
    switch (e.kind) {
    case Kind::Part:
        return DiagramBuilder::partKey(e.id);
    case Kind::Channel:
        return DiagramBuilder::channelKey(e.id);
    case Kind::Boundary:
        return DiagramBuilder::boundaryKey(e.id);
    case Kind::Connection:
        return DiagramBuilder::connectionKey(e.id.toInt());
    }
    return {};
}

} // namespace

QList<UmlDiagram> recoveredDiagrams(const AtomicNodeList &nodes, const Architecture &architecture)
{
    QList<UmlDiagram> out;
    const QMap<QString, QString> acdStems = AcdWriter::fileStems(nodes);
    for (const AtomicNode &n : nodes.nodes)
        out += PlantUmlReader::read(AcdWriter::write(n),
                                    QStringLiteral("acd/%1.puml").arg(acdStems.value(n.id)));
    const QMap<QString, QString> ccdStems = CcdWriter::fileStems(architecture);
    for (const Composite *c : architecture.representatives()) {
        QList<CcdWriter::WrittenElement> written;
        const QString text = CcdWriter::write(*c, &written);
        QHash<int, QString> keyByLine;
        for (const CcdWriter::WrittenElement &e : std::as_const(written))
            keyByLine.insert(e.line, drawnKey(e));
        // The reader reads back every element on the line that declares it (a part's type and
        // namespace on the part's line), so the line names the element drawn.
        for (UmlDiagram d : PlantUmlReader::read(
                 text, QStringLiteral("ccd/%1.puml").arg(ccdStems.value(c->instanceId)))) {
            for (UmlElement &e : d.elements)
                e.key = keyByLine.value(e.line);
            out += d;
        }
    }
    return out;
}

} // namespace rosarch
