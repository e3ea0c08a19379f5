// Bad input never stops a run: each broken file gives a diagnostic, the rest is recovered.
#include "nodes/nodeanalyzer.h"
#include "support/testsupport.h"
#include "workspace/sourcereader.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using test::writeFile;

namespace {
int count(const QList<Diagnostic> &ds, const QString &code, const QString &file)
{
    int n = 0;
    for (const Diagnostic &d : ds)
        if (d.code == code && d.evidence.file == file)
            ++n;
    return n;
}

const QByteArray kGoodNode =
    "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n\n"
    "class Good(Node):\n    def __init__(self):\n        super().__init__('good')\n"
    "        self.pub = self.create_publisher(String, 'out', 10)\n";
} // namespace

class TestBadInput : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void brokenFilesDoNotStopTheRun()
    {
        QTemporaryDir dir;
        const QString root = dir.path();
        writeFile(root + "/pkg/package.xml",
                  "<package><name>pkg</name><export><build_type>ament_python</build_type></"
                  "export></package>");
        writeFile(root + "/pkg/pkg/good.py", kGoodNode);
        writeFile(root + "/pkg/pkg/broken.py",
                  "from rclpy.node import Node\nclass Broken(Node:\n  def (:\n");
        writeFile(root + "/pkg/pkg/binary.py", QByteArray("\x7f"
                                                          "ELF\0\0\0\x01garbage",
                                                          16));
        writeFile(root + "/pkg/pkg/huge.py", QByteArray(5 * 1024 * 1024, 'x'));
        writeFile(root + "/cpp_pkg/package.xml", "<package><name>cpp_pkg</name>");
        writeFile(root + "/cpp_pkg/src/broken.cpp",
                  "class X : public rclcpp::Node { void f() { if ( }\n");
        writeFile(root + "/cpp_pkg/CMakeLists.txt", "add_executable(x src/broken.cpp\n");
        QVERIFY(QFile::link(root + "/pkg", root + "/pkg/pkg/loop"));

        const AtomicNodeList list = recoverAtomicNodes(root);
        QStringList classes;
        for (const AtomicNode &n : list.nodes)
            classes << n.className;
        QVERIFY2(classes.contains(QStringLiteral("Good")), qPrintable(classes.join(',')));
        QCOMPARE(count(list.diagnostics, QStringLiteral("binary-file"),
                       QStringLiteral("pkg/pkg/binary.py")),
                 1);
        QCOMPARE(count(list.diagnostics, QStringLiteral("file-too-large"),
                       QStringLiteral("pkg/pkg/huge.py")),
                 1);
        QCOMPARE(
            count(list.diagnostics, QStringLiteral("symlink-loop"), QStringLiteral("pkg/pkg/loop")),
            1);
        QVERIFY(count(list.diagnostics, QStringLiteral("syntax-error"),
                      QStringLiteral("pkg/pkg/broken.py")) >= 1);
        QVERIFY(count(list.diagnostics, QStringLiteral("syntax-error"),
                      QStringLiteral("cpp_pkg/src/broken.cpp")) >= 1);
        QCOMPARE(count(list.diagnostics, QStringLiteral("malformed-xml"),
                       QStringLiteral("cpp_pkg/package.xml")),
                 1);
        for (const Diagnostic &d : list.diagnostics)
            QVERIFY2(!d.message.isEmpty(), qPrintable(d.code));
    }

    void readerRefusesWhatItCannotAnalyse()
    {
        QTemporaryDir dir;
        QDir(dir.path()).mkpath(QStringLiteral("folder.py"));
        writeFile(dir.filePath(QStringLiteral("small.py")), "x = 1\n");
        writeFile(dir.filePath(QStringLiteral("big.py")), QByteArray(2048, 'y'));
        const SourceReader reader(dir.path(), 1024);
        QList<Diagnostic> diagnostics;
        QByteArray content;
        QVERIFY(reader.read(QStringLiteral("small.py"), &content, &diagnostics));
        QCOMPARE(content, QByteArray("x = 1\n"));
        QVERIFY(!reader.read(QStringLiteral("big.py"), &content, &diagnostics));
        QVERIFY(!reader.read(QStringLiteral("missing.py"), &content, &diagnostics));
        QVERIFY(!reader.read(QStringLiteral("folder.py"), &content, &diagnostics));
        QCOMPARE(diagnostics.size(), 3);
        QCOMPARE(diagnostics[0].code, QStringLiteral("file-too-large"));
        QCOMPARE(diagnostics[1].code, QStringLiteral("unreadable-file"));
        QCOMPARE(diagnostics[2].code, QStringLiteral("unreadable-file"));
        QVERIFY(diagnostics[1].message.contains(QStringLiteral("missing.py")));
    }

    void cancellationStopsTheStage()
    {
        StageControl control;
        control.canceled = [] { return true; };
        const AtomicNodeList list =
            recoverAtomicNodes(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                   .filePath(QStringLiteral("resources/example_ws")),
                               control);
        QVERIFY(list.canceled);
        QVERIFY(list.nodes.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestBadInput)
#include "tst_badinput.moc"
