// libFuzzer target: the build-file readers: package.xml, setup.py, setup.cfg and
// CMakeLists.txt (with add_subdirectory back into itself). The first byte picks the reader.
#include "fuzzsupport.h"
#include "structuremutator.h"
#include "workspace/buildfileparser.h"
#include "workspace/cmakelistsreader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray content = rosarch::fuzz::bytes(data + 1, size - 1);
    QList<rosarch::Diagnostic> diagnostics;
    switch (data[0] % 4) {
    case 0: {
        rosarch::RosPackage package;
        rosarch::BuildFileParser::readPackageXml(content, QStringLiteral("package.xml"), &package,
                                                 &diagnostics);
        break;
    }
    case 1:
        rosarch::BuildFileParser::readSetupPy(content, QStringLiteral("setup.py"), &diagnostics);
        break;
    case 2:
        rosarch::BuildFileParser::readSetupCfg(content, QStringLiteral("setup.cfg"));
        break;
    default: {
        // Every path reads the same content: subdirectories lead back to it.
        rosarch::CMakeListsReader reader([&](const QString &, QByteArray *out) {
            *out = content;
            return true;
        });
        reader.read(QStringLiteral("CMakeLists.txt"), &diagnostics);
        break;
    }
    }
    return 0;
}

ROSARCH_STRUCTURE_MUTATOR
