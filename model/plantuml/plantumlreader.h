#pragma once

#include "plantuml/umldiagram.h"

#include <QList>
#include <QString>

namespace rosarch {

/// Reads PlantUML text, hand-written or ours, into canonical diagrams (blueprint §3 "Reading",
/// §4). Tolerates the variants of §3, notes what it normalized and warns about what it skipped;
/// it never fails: a diagram it cannot place has level Unknown.
class PlantUmlReader
{
public:
    /// One diagram per @startuml block (the whole text when there is none). `file` is kept in
    /// the diagrams and names them (by its stem) when nothing inside does.
    static QList<UmlDiagram> read(const QString &text, const QString &file = {});
};

} // namespace rosarch
