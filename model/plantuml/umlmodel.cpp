#include "plantuml/umlmodel.h"
#include "plantuml/plantumlreader.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QSet>

namespace rosarch {

bool UmlModel::load(const QString &path, UmlModel *model, QString *error)
{
    *model = {};
    model->path = path;
    const QFileInfo info(path);
    QStringList files;
    if (info.isDir()) {
        QDirIterator it(path, {QStringLiteral("*.puml")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext())
            files << it.next();
        files.sort(); // deterministic order: the report lists diagrams as they were read
    } else if (info.isFile() && info.isReadable()) {
        files << path;
    } else {
        if (error)
            *error = info.exists() ? QStringLiteral("cannot read %1").arg(path)
                                   : QStringLiteral("no such file or folder: %1").arg(path);
        return false;
    }
    for (const QString &file : std::as_const(files)) {
        QFile f(file);
        if (!f.open(QIODevice::ReadOnly)) {
            model->errors << QStringLiteral("%1: cannot be read").arg(file);
            continue;
        }
        model->diagrams.append(PlantUmlReader::read(QString::fromUtf8(f.readAll()), file));
    }
    typeByClassifiers(&model->diagrams);
    return true;
}

void UmlModel::typeByClassifiers(QList<UmlDiagram> *diagrams)
{
    QSet<QString> classifiers;
    for (const UmlDiagram &d : std::as_const(*diagrams))
        if (d.level != UmlLevel::Unknown && !d.name.isEmpty())
            classifiers.insert(d.name);
    for (UmlDiagram &d : *diagrams) {
        for (const UmlDiagram::BareLabel &bare : std::as_const(d.bareParts)) {
            // The part's key is the label's text either way (a name, or the type of an
            // unnamed part); only the type is new.
            if (classifiers.contains(bare.text) && bare.text != d.name) {
                d.elements.append({UmlKind::PartType, QLatin1Char(':') + bare.text, bare.line, {}});
                d.notes << QStringLiteral("line %1: part label '%2' has no ':' and names a "
                                          "classifier of the model; read as the part's type")
                               .arg(bare.line)
                               .arg(bare.text);
            } else {
                d.notes << QStringLiteral("line %1: part label '%2' has no ':'; read as the name")
                               .arg(bare.line)
                               .arg(bare.text);
            }
        }
        d.bareParts.clear();
    }
}

QList<UmlDiagram> UmlModel::ofLevel(UmlLevel level) const
{
    QList<UmlDiagram> out;
    for (const UmlDiagram &d : diagrams)
        if (d.level == level)
            out << d;
    return out;
}

QList<UmlDiagram> UmlModel::unparseable() const
{
    return ofLevel(UmlLevel::Unknown);
}

bool UmlModel::hasLevel(UmlLevel level) const
{
    for (const UmlDiagram &d : diagrams)
        if (d.level == level)
            return true;
    return false;
}

} // namespace rosarch
