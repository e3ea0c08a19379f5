#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "plantuml/umldiagram.h"

#include <QList>

namespace rosarch {

/// The recovered model as the evaluator sees it: every ACD and CCD rosarch would export,
/// written and read back through the PlantUML reader, so a comparison with a reference in
/// the GUI scores exactly what `rosarch eval` would score on the exported files. Every CCD
/// element carries the key of the element the composed diagram draws for it (UmlElement::key).
QList<UmlDiagram> recoveredDiagrams(const AtomicNodeList &nodes, const Architecture &architecture);

} // namespace rosarch
