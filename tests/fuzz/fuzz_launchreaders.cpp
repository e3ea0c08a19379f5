// libFuzzer target: the three launch-file readers (XML, YAML, Python), each on the input, the
// YAML parameter-file reader with its node matching and rewrites, and the evaluator of
// `$(eval ...)` expressions. The first byte picks one, so one corpus covers them all.
#include "fuzzsupport.h"
#include "launch/python/pythonlauncheval.h"
#include "launch/python/pythonlaunchreader.h"
#include "launch/xmlyaml/parameterfile.h"
#include "launch/xmlyaml/xmllaunchreader.h"
#include "launch/xmlyaml/yamllaunchreader.h"
#include "structuremutator.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray content = rosarch::fuzz::bytes(data + 1, size - 1);
    switch (data[0] % 4) {
    case 0:
        rosarch::XmlLaunchReader::isLaunchFile(content);
        rosarch::XmlLaunchReader::read(content, QStringLiteral("f.launch.xml"));
        break;
    case 1:
        rosarch::YamlLaunchReader::isLaunchFile(content);
        rosarch::YamlLaunchReader::read(content, QStringLiteral("f.launch.yaml"));
        {
            rosarch::ParameterFile params =
                rosarch::ParameterFile::read(content, QStringLiteral("p.yaml"));
            params.forNode(QStringLiteral("/ns/node"));
            params.rewrite({{QStringLiteral("a"), QStringLiteral("b")},
                            {QStringLiteral("=x"), QStringLiteral("y")}},
                           QStringLiteral("root"));
            params.forNode(QStringLiteral("/root/ns/node"));
        }
        break;
    case 2:
        rosarch::PythonLaunchReader::isLaunchFile(content);
        rosarch::PythonLaunchReader::read(content, QStringLiteral("f.launch.py"));
        break;
    default: {
        QString value;
        rosarch::PythonLaunchEval::evaluate(QString::fromUtf8(content), &value);
        break;
    }
    }
    return 0;
}

ROSARCH_STRUCTURE_MUTATOR
