// libFuzzer target: the tolerant PlantUML reader (reference models are written by hand).
#include "fuzzsupport.h"
#include "plantuml/plantumlreader.h"
#include "plantuml/umlmodel.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QList<rosarch::UmlDiagram> diagrams =
        rosarch::PlantUmlReader::read(QString::fromUtf8(rosarch::fuzz::bytes(data, size)));
    rosarch::UmlModel::typeByClassifiers(&diagrams);
    return 0;
}
