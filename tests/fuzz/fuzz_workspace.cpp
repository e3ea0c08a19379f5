// libFuzzer target: a whole workspace built from the input, all three stages in process. The
// input's parts (split at byte 0x01) become, in order, an XML launch file, a Python launch
// file, a YAML launch file, a package's CMakeLists.txt, its C++ node and a Python node, beside
// one healthy package; the run must end, and no class may list a port twice.
#include "core/modelinvariants.h"
#include "fuzzsupport.h"
#include "pipeline/recovery.h"
#include "structuremutator.h"

#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    setenv("ROSARCH_NO_CACHE", "1", 1); // every run analyses its files; nothing is kept
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using rosarch::fuzz::writeScratch;
    const QList<QByteArray> parts = rosarch::fuzz::bytes(data, size).split('\x01');
    QDir(rosarch::fuzz::scratch().filePath(QStringLiteral("ws"))).removeRecursively();
    writeScratch(QStringLiteral("ws/src/pkg/package.xml"),
                 "<package format=\"3\"><name>pkg</name><export><build_type>ament_python"
                 "</build_type></export></package>\n");
    writeScratch(QStringLiteral("ws/src/pkg/setup.py"),
                 "from setuptools import setup\nsetup(name='pkg', entry_points={'console_scripts':"
                 " ['good = pkg.good:main', 'other = pkg.other:main']})\n");
    writeScratch(
        QStringLiteral("ws/src/pkg/pkg/good.py"),
        "from rclpy.node import Node\nfrom std_msgs.msg import String\n\nclass Good(Node):\n"
        "    def __init__(self):\n        super().__init__('good')\n"
        "        self.create_publisher(String, 'out', 10)\n");
    writeScratch(QStringLiteral("ws/src/cpp/package.xml"),
                 "<package format=\"3\"><name>cpp</name></package>\n");
    const QStringList files = {
        QStringLiteral("ws/src/pkg/launch/a.launch.xml"),
        QStringLiteral("ws/src/pkg/launch/b.launch.py"),
        QStringLiteral("ws/src/pkg/launch/c.launch.yaml"),
        QStringLiteral("ws/src/cpp/CMakeLists.txt"),
        QStringLiteral("ws/src/cpp/src/node.cpp"),
        QStringLiteral("ws/src/pkg/pkg/other.py"),
    };
    for (qsizetype i = 0; i < parts.size() && i < files.size(); ++i)
        writeScratch(files.at(i), parts.at(i));
    const rosarch::Recovery r =
        rosarch::recoverWorkspace(rosarch::fuzz::scratch().filePath(QStringLiteral("ws")));
    for (const QString &violation : rosarch::modelInvariantViolations(r.nodes))
        if (violation.endsWith(QLatin1String("listed twice")))
            std::abort(); // the same port twice is a defect whatever the input
    return 0;
}

ROSARCH_STRUCTURE_MUTATOR
