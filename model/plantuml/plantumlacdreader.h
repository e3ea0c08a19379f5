#pragma once

#include "plantuml/plantumldocument.h"

namespace rosarch {

/// Reads an AtomicClassifierDiagram (blueprint §3) into the ACD element kinds of §4.
class PlantUmlAcdReader
{
public:
    /// `top` is the component of the AtomicRosNodeClassifier; elements, name and notes go to
    /// the document's diagram.
    static void read(const PlantUmlDocument &doc, int top);
};

} // namespace rosarch
