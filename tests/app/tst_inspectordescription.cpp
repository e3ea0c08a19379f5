// What a node does, in the inspector: every node class and node instance has a description
// row, from the class's own documentation without running Suggestions, replaced by a person's
// description, and saying which source it is; where nothing describes the class it says so.
#include "diagram/diagramlayouter.h"
#include "document/nodedescription.h"
#include "support/cacherecovery.h"
#include "support/correctiongui.h"
#include "support/diagramarchitecture.h"
#include "support/diagramwait.h"
#include "support/testsupport.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test;
using rosarch::test::laidOut;
using EKind = CorrectionController::Element::Kind;

namespace {

QString classIdOf(const Document &doc, const QString &className)
{
    for (const AtomicNode &n : doc.atomicNodes().nodes)
        if (n.className == className)
            return n.id;
    return {};
}

QString instanceOf(const Document &doc, const QString &classId)
{
    for (const NodeInstance &n : doc.launchDependencies().nodes)
        if (n.classId == classId)
            return n.id;
    return {};
}

} // namespace

class TestInspectorDescription : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
    }

    void aClassAndItsInstancesSayWhatTheyDoAndWhoSaysSo()
    {
        Gui gui;
        gui.document.setRecovery(recoverUncached(dataDir(QStringLiteral("compose_system/ws"))));
        const QString commander = classIdOf(gui.document, QStringLiteral("Commander"));
        QVERIFY(!commander.isEmpty());
        const QString instance = instanceOf(gui.document, commander);
        QVERIFY(!instance.isEmpty());
        const auto shown = [&gui](const QString &field) { return gui.inspector.fieldText(field); };

        // from the class's documentation, without any suggestion run
        gui.controller->presenter()->setCurrent({EKind::Class, commander, {}, {}});
        QCOMPARE(shown(QStringLiteral("description")),
                 QStringLiteral("Sends navigation goals and overrides velocity."));
        QCOMPARE(shown(QStringLiteral("descriptionSource")), QStringLiteral("from the code"));
        gui.controller->presenter()->setCurrent({EKind::Instance, instance, {}, {}});
        QCOMPARE(shown(QStringLiteral("description")),
                 QStringLiteral("Sends navigation goals and overrides velocity."));

        // a person's description replaces it, and the inspector says whose it is
        gui.document.session()->setNodeDescription(commander,
                                                   QStringLiteral("Our mission commander."));
        gui.controller->presenter()->setCurrent({EKind::Class, commander, {}, {}});
        QCOMPARE(shown(QStringLiteral("description")), QStringLiteral("Our mission commander."));
        NodeDescription person;
        person.source = NodeDescription::Source::Correction;
        QCOMPARE(shown(QStringLiteral("descriptionSource")), person.sourceText());
        QVERIFY(shown(QStringLiteral("descriptionSource")) != QStringLiteral("from the code"));
        gui.document.undoStack()->undo();
        gui.controller->presenter()->setCurrent({EKind::Instance, instance, {}, {}});
        QCOMPARE(shown(QStringLiteral("descriptionSource")), QStringLiteral("from the code"));
    }

    void anUndocumentedClassSaysSo()
    {
        QTemporaryDir dir;
        const QString pkg = dir.filePath(QStringLiteral("src/beacon"));
        QVERIFY(QDir().mkpath(pkg + QStringLiteral("/beacon")));
        writeFile(pkg + QStringLiteral("/package.xml"),
                  "<package format=\"3\"><name>beacon</name><version>0.1.0</version>"
                  "<description>b</description><maintainer email=\"a@b.c\">a</maintainer>"
                  "<license>MIT</license><export><build_type>ament_python</build_type>"
                  "</export></package>\n");
        writeFile(pkg + QStringLiteral("/beacon/__init__.py"), "");
        writeFile(pkg + QStringLiteral("/beacon/beacon.py"),
                  "from rclpy.node import Node\n\n\nclass Beacon(Node):\n"
                  "    def __init__(self):\n        super().__init__('beacon')\n");
        Gui gui;
        gui.document.setRecovery(recoverUncached(dir.path()));
        const QString beacon = classIdOf(gui.document, QStringLiteral("Beacon"));
        QVERIFY(!beacon.isEmpty());
        gui.controller->presenter()->setCurrent({EKind::Class, beacon, {}, {}});
        QCOMPARE(gui.inspector.fieldText(QStringLiteral("kind")), QStringLiteral("Node class"));
        QCOMPARE(gui.inspector.fieldText(QStringLiteral("description")),
                 QStringLiteral("No description in the code"));
        QVERIFY(gui.inspector.fieldText(QStringLiteral("descriptionSource")).isEmpty());
    }

    void aNodePartsTooltipSaysWhatItsClassDoes()
    {
        Architecture arch = test::diagram::architecture();
        DiagramLayouter layouter;
        DiagramPanel panel(&layouter);
        panel.resize(1200, 800);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QStringList asked;
        panel.setDescriber([&asked](const QString &classId) {
            asked << classId;
            return QStringLiteral("Does %1 things (from the code)").arg(classId);
        });
        QVERIFY(laidOut(panel, [&] { panel.setArchitecture(arch); }));
        const Composite *shown = arch.composite(panel.currentComposite());
        QVERIFY(shown);
        int nodes = 0;
        for (const RosNodePart &part : shown->parts) {
            const QString tip = panel.scene()->toolTip(DiagramBuilder::partKey(part.id));
            if (part.kind != RosNodePart::Kind::Node) {
                QVERIFY2(!tip.contains(QStringLiteral("Does ")), qPrintable(tip));
                continue;
            }
            ++nodes;
            QVERIFY2(
                tip.endsWith(QStringLiteral("Does %1 things (from the code)").arg(part.typeId)),
                qPrintable(tip));
        }
        QVERIFY(nodes > 0);
        QVERIFY(!asked.isEmpty());
    }

    void otherElementsHaveNoDescriptionRow()
    {
        InspectorPanel panel;
        InspectorInfo port;
        port.kind = QStringLiteral("Port (publisher)");
        port.name = QStringLiteral("cmd_vel");
        panel.setElement(port, {});
        QVERIFY(panel.fieldText(QStringLiteral("description")).isEmpty());
        InspectorInfo node = port;
        node.kind = QStringLiteral("Node class");
        node.describable = true;
        node.descriptionSource = QStringLiteral("No description in the code");
        panel.setElement(node, {});
        QCOMPARE(panel.fieldText(QStringLiteral("description")),
                 QStringLiteral("No description in the code"));
    }
};

QTEST_MAIN(TestInspectorDescription)
#include "tst_inspectordescription.moc"
