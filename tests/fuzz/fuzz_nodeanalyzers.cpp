// libFuzzer target: the Python and C++ node analyzers on one source file of a scratch
// workspace (they read files). The first byte picks the language.
#include "fuzzsupport.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "nodes/python/pythonnodeanalyzer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const bool python = data[0] % 2 == 0;
    const QString relative =
        python ? QStringLiteral("src/pkg/pkg/node.py") : QStringLiteral("src/pkg/src/node.cpp");
    rosarch::fuzz::writeScratch(relative, rosarch::fuzz::bytes(data + 1, size - 1));
    rosarch::Workspace ws;
    ws.root = rosarch::fuzz::scratch().path();
    rosarch::RosPackage pkg;
    pkg.name = QStringLiteral("pkg");
    pkg.path = QStringLiteral("src/pkg");
    pkg.buildType = python ? QStringLiteral("ament_python") : QStringLiteral("ament_cmake");
    ws.packages << pkg;
    rosarch::SourceFile file;
    file.path = relative;
    file.language =
        python ? rosarch::SourceFile::Language::Python : rosarch::SourceFile::Language::Cpp;
    file.size = qint64(size - 1);
    ws.files << file;
    if (python)
        rosarch::PythonNodeAnalyzer(ws).analyze();
    else
        rosarch::CppNodeAnalyzer(ws).analyze();
    return 0;
}
