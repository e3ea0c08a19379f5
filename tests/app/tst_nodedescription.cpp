// A node's description without running Suggestions: the class's own documentation (a
// docstring, a comment block above the class) is in effect until a suggestion is accepted or a
// person writes one, and the views are told whose it is.
#include "document/document.h"
#include "document/nodedescription.h"
#include "support/cacherecovery.h"
#include "support/testsupport.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace rosarch;

namespace {

QString idOf(const Document &doc, const QString &className)
{
    for (const AtomicNode &n : doc.atomicNodes().nodes)
        if (n.className == className)
            return n.id;
    return {};
}

} // namespace

class TestNodeDescription : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
    }

    void theCodeDescribesAClassUntilAPersonDoes()
    {
        Document doc;
        doc.setRecovery(test::recoverUncached(test::dataDir(QStringLiteral("compose_system/ws"))));
        const QString commander = idOf(doc, QStringLiteral("Commander"));
        QVERIFY(!commander.isEmpty());
        QVERIFY(doc.atomicNodes().node(commander)->description.isEmpty()); // none was accepted
        NodeDescription d = NodeDescription::of(doc, commander);
        QCOMPARE(d.text, QStringLiteral("Sends navigation goals and overrides velocity."));
        QCOMPARE(d.source, NodeDescription::Source::Code);
        QCOMPARE(d.sourceText(), QStringLiteral("from the code"));

        doc.session()->setNodeDescription(commander, QStringLiteral("Our mission commander."));
        d = NodeDescription::of(doc, commander);
        QCOMPARE(d.text, QStringLiteral("Our mission commander."));
        QCOMPARE(d.source, NodeDescription::Source::Correction);
        doc.undoStack()->undo();
        QCOMPARE(NodeDescription::of(doc, commander).source, NodeDescription::Source::Code);
    }

    void anEditOfTheFileIsReadAgain()
    {
        QTemporaryDir dir;
        const QString pkg = dir.filePath(QStringLiteral("src/beacon"));
        QVERIFY(QDir().mkpath(pkg + QStringLiteral("/beacon")));
        test::writeFile(pkg + QStringLiteral("/package.xml"),
                        "<package format=\"3\"><name>beacon</name><version>0.1.0</version>"
                        "<description>b</description><maintainer email=\"a@b.c\">a</maintainer>"
                        "<license>MIT</license><export><build_type>ament_python</build_type>"
                        "</export></package>\n");
        test::writeFile(pkg + QStringLiteral("/beacon/__init__.py"), "");
        const QString source = pkg + QStringLiteral("/beacon/beacon.py");
        test::writeFile(source, "from rclpy.node import Node\n\n\nclass Beacon(Node):\n"
                                "    def __init__(self):\n        super().__init__('beacon')\n");
        Document doc;
        doc.setRecovery(test::recoverUncached(dir.path()));
        const QString beacon = idOf(doc, QStringLiteral("Beacon"));
        QVERIFY(!beacon.isEmpty());
        QCOMPARE(NodeDescription::of(doc, beacon).source, NodeDescription::Source::None);
        QCOMPARE(NodeDescription::of(doc, beacon).sourceText(),
                 QStringLiteral("No description in the code"));

        // a comment written above the class, the class on the same line: read again, since
        // the file's time changed
        test::writeFile(source, "from rclpy.node import Node\n\n# Blinks where the robot is.\n"
                                "class Beacon(Node):\n"
                                "    def __init__(self):\n        super().__init__('beacon')\n");
        QFile edited(source);
        QVERIFY(edited.open(QIODevice::ReadWrite));
        QVERIFY(edited.setFileTime(QDateTime::currentDateTime().addSecs(60),
                                   QFileDevice::FileModificationTime));
        edited.close();
        const NodeDescription d = NodeDescription::of(doc, beacon);
        QCOMPARE(d.text, QStringLiteral("Blinks where the robot is."));
        QCOMPARE(d.source, NodeDescription::Source::Code);
    }
};

QTEST_GUILESS_MAIN(TestNodeDescription)
#include "tst_nodedescription.moc"
