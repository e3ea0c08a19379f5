#pragma once

#include "plantuml/umldiagram.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// All diagrams read from a folder of PlantUML files (or from one file): a reference model
/// written by hand, or a recovered one.
struct UmlModel
{
    QString path;               ///< what was loaded
    QList<UmlDiagram> diagrams; ///< in file order (sorted paths), Unknown-level ones included
    QStringList errors;         ///< files that could not be read

    /// Reads every `*.puml` below `path` (recursively, sorted) or the single file `path`.
    /// Returns false, with `error` set, when `path` is neither a readable file nor a folder.
    static bool load(const QString &path, UmlModel *model, QString *error);
    /// Blueprint §3: a part label without a colon that names a classifier of `diagrams` (an
    /// ACD's class or a CCD's launch stem) is that part's type; any other is read as the
    /// part's name. Adds the part_type element, and a note either way. load() calls it.
    static void typeByClassifiers(QList<UmlDiagram> *diagrams);
    /// Diagrams of one level.
    QList<UmlDiagram> ofLevel(UmlLevel level) const;
    /// The diagrams that are neither an ACD nor a CCD (nothing recognisable in them).
    QList<UmlDiagram> unparseable() const;
    /// True when the model has diagrams of `level`.
    bool hasLevel(UmlLevel level) const;
};

} // namespace rosarch
