#pragma once

// Shared helpers for tests that run the stages on generated workspaces: a healthy package to
// put next to something hostile, and what a recovery found, as text to compare.
#include "pipeline/recovery.h"
#include "support/testsupport.h"

#include <QStringList>

namespace rosarch::test {

/// A Python package `pkg` with one healthy node class, Good (publishing `out`), started as
/// `good`; `moreScripts` adds console scripts ("victim = pkg.victim:main").
inline void healthyPythonPackage(const QString &root, const QByteArray &moreScripts = {})
{
    writeFile(root + "/src/pkg/package.xml",
              "<package format=\"3\"><name>pkg</name><export><build_type>ament_python"
              "</build_type></export></package>\n");
    writeFile(root + "/src/pkg/pkg/__init__.py", "");
    writeFile(root + "/src/pkg/pkg/good.py",
              "from rclpy.node import Node\nfrom std_msgs.msg import String\n\n"
              "class Good(Node):\n    def __init__(self):\n        super().__init__('good')\n"
              "        self.pub = self.create_publisher(String, 'out', 10)\n");
    writeFile(root + "/src/pkg/setup.py",
              "from setuptools import setup\nsetup(name='pkg', entry_points={'console_scripts': "
              "['good = pkg.good:main'" +
                  (moreScripts.isEmpty() ? QByteArray() : ", '" + moreScripts + "'") + "]})\n");
}

/// The class names of the recovered atomic nodes, in the list's order.
inline QStringList classNames(const Recovery &r)
{
    QStringList out;
    for (const AtomicNode &n : r.nodes.nodes)
        out << n.className;
    return out;
}

/// "file: message" of every diagnostic of all three stages with this code.
inline QStringList diagnosticsWithCode(const Recovery &r, const QString &code)
{
    QStringList out;
    for (const QList<Diagnostic> *list :
         {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics})
        for (const Diagnostic &d : *list)
            if (d.code == code)
                out << d.evidence.file + QStringLiteral(": ") + d.message;
    return out;
}

} // namespace rosarch::test
