#pragma once

#include "plantuml/plantumldocument.h"

namespace rosarch {

/// Reads a ComposedClassifierDiagram (blueprint §3) into the CCD element kinds of §4.
class PlantUmlCcdReader
{
public:
    /// `top` is the ComposedRosNodeClassifier component, or -1 when the parts stand alone;
    /// elements, name (when `top` gives one) and notes go to the document's diagram.
    static void read(const PlantUmlDocument &doc, int top);
};

} // namespace rosarch
