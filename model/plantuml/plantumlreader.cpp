#include "plantuml/plantumlreader.h"
#include "plantuml/plantumlacdreader.h"
#include "plantuml/plantumlccdreader.h"
#include "plantuml/plantumldocument.h"
#include "plantuml/plantumlsyntax.h"
#include "plantuml/umlnames.h"

#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>

namespace rosarch {

namespace {

int lineOf(const QString &message)
{
    static const QRegularExpression re(QStringLiteral(R"(^line (\d+):)"));
    const QRegularExpressionMatch m = re.match(message);
    return m.hasMatch() ? m.captured(1).toInt() : 0;
}

void sortByLine(QStringList *messages)
{
    std::stable_sort(messages->begin(), messages->end(),
                     [](const QString &a, const QString &b) { return lineOf(a) < lineOf(b); });
}

/// Without a classifier stereotype: a component with ports next to frames or folders is an ACD.
int guessAcdTop(const PlantUmlDocument &doc)
{
    bool containers = false;
    for (int i = 0; i < doc.size(); ++i)
        containers = containers || doc.at(i).keyword == QLatin1String("frame") ||
                     doc.at(i).keyword == QLatin1String("folder");
    if (!containers)
        return -1;
    for (int i = 0; i < doc.size(); ++i)
        if (doc.isPort(i) && doc.owner(i) >= 0)
            return doc.owner(i);
    return -1;
}

UmlDiagram readBlock(const PlantUmlSyntax &syntax, const QString &file)
{
    UmlDiagram d;
    d.file = file;
    d.notes = syntax.notes;
    d.warnings = syntax.warnings;
    const PlantUmlDocument doc(syntax, &d);
    const int arc = doc.first(UmlNames::AtomicRosNodeClassifier);
    const int crc = doc.first(UmlNames::ComposedRosNodeClassifier);
    const int part = doc.first(UmlNames::RosNodePart);
    if (arc >= 0 && (crc < 0 || arc < crc)) {
        d.level = UmlLevel::Acd;
        PlantUmlAcdReader::read(doc, arc);
    } else if (crc >= 0 || part >= 0) {
        d.level = UmlLevel::Ccd;
        if (crc < 0)
            doc.note(doc.at(part).line,
                     QStringLiteral("no <<ComposedRosNodeClassifier>>; read as a CCD because of "
                                    "its <<RosNodePart>>s"));
        PlantUmlCcdReader::read(doc, crc);
    } else if (const int top = guessAcdTop(doc); top >= 0) {
        d.level = UmlLevel::Acd;
        doc.note(doc.at(top).line,
                 QStringLiteral("no <<AtomicRosNodeClassifier>>; '%1' read as the node of an ACD")
                     .arg(doc.at(top).firstLine()));
        PlantUmlAcdReader::read(doc, top);
    } else {
        doc.warn(1, QStringLiteral("neither an ACD nor a CCD: no <<AtomicRosNodeClassifier>>, "
                                   "<<ComposedRosNodeClassifier>> or <<RosNodePart>> found"));
    }
    if (d.name.isEmpty() && d.level != UmlLevel::Unknown) {
        QString why;
        if (!syntax.title.isEmpty())
            d.name = syntax.title.trimmed();
        else if (!file.isEmpty())
            d.name = d.level == UmlLevel::Ccd
                         ? UmlNames::launchStem(QFileInfo(file).fileName(), &why)
                         : QFileInfo(file).completeBaseName();
        doc.note(1, QStringLiteral("diagram named '%1' after its %2")
                        .arg(d.name, syntax.title.isEmpty() ? QStringLiteral("file")
                                                            : QStringLiteral("title")));
    }
    sortByLine(&d.notes);
    sortByLine(&d.warnings);
    return d;
}

} // namespace

QList<UmlDiagram> PlantUmlReader::read(const QString &text, const QString &file)
{
    QList<UmlDiagram> out;
    for (const PlantUmlSyntax &s : PlantUmlSyntax::parse(text))
        out << readBlock(s, file);
    return out;
}

} // namespace rosarch
