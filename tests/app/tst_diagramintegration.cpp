// The composed diagram inside the main window, on tests/data/compose_system: it follows the
// launch tree, a click in it selects the launch tree and the source, it exports, and a
// comparison with a reference model marks extra elements and lists missing ones.
#include "app/diagramcontroller.h"
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "support/acceptedwait.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagramitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"
#include "widgets/suggestionpanel.h"

#include <QGraphicsItem>
#include <QImage>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString instanceNamed(const Document *doc, const QString &nodeName)
{
    for (const NodeInstance &n : doc->launchDependencies().nodes)
        if (n.nodeName == nodeName)
            return n.id;
    return {};
}

/// Marked elements of the current diagram, by key.
QStringList markedKeys(DiagramPanel *panel)
{
    QStringList keys;
    for (QGraphicsItem *item : panel->scene()->items())
        if (auto *d = dynamic_cast<DiagramItem *>(item); d && d->mark() == DiagramMark::Extra)
            keys << d->key();
    keys.sort();
    return keys;
}

} // namespace

class TestDiagramIntegration : public QObject
{
    Q_OBJECT

    MainWindow *m_window = nullptr;

    DiagramPanel *panel() const { return test::child<DiagramPanel>(*m_window); }
    Document *doc() const { return test::child<Document>(*m_window); }

    bool waitForLayout()
    {
        if (!panel()->isLayingOut())
            return true;
        QSignalSpy done(panel(), &DiagramPanel::layoutFinished);
        return done.wait(30000);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        m_window = new MainWindow;
        m_window->resize(1600, 900);
        m_window->show();
        QSignalSpy finished(test::child<StageRunner>(*m_window), &StageRunner::stageFinished);
        m_window->openWorkspace(test::dataDir(QStringLiteral("compose_system/ws")));
        QVERIFY(finished.wait(60000));
        QVERIFY(waitForLayout());
    }

    void cleanupTestCase() { delete m_window; }

    void showsTheRootComposite()
    {
        QCOMPARE(doc()->architecture().composites.size(), 3);
        QCOMPARE(panel()->currentComposite(), QStringLiteral("lf1"));
        QVERIFY2(panel()->message().isEmpty(), qPrintable(panel()->message()));
        // The diagram dock is too small for the whole system at a legible size: it starts as
        // the overview, the two cameras' namespaces one box each.
        QVERIFY(panel()->isCollapsed());
        QVERIFY(panel()->scene()->item(QStringLiteral("namespace:/front")));
        QVERIFY(panel()->scene()->item(QStringLiteral("namespace:/rear")));
        QVERIFY(!panel()->scene()->item(QStringLiteral("part:part1")));
        test::saveScreenshot(*m_window, QStringLiteral("diagram-window-overview.png"));
        QSignalSpy laidOut(panel(), &DiagramPanel::layoutFinished);
        panel()->expandAll();
        QVERIFY(!laidOut.isEmpty() || laidOut.wait(30000));
        QVERIFY(panel()->scene()->item(QStringLiteral("part:part1")));
        test::saveScreenshot(*m_window, QStringLiteral("diagram-window.png"));
    }

    void launchTreeSelectionOpensTheInstancesComposite()
    {
        const QString detector = instanceNamed(doc(), QStringLiteral("detector"));
        QVERIFY(!detector.isEmpty());
        const QString composite = doc()->launchDependencies().node(detector)->launchFileId;
        test::child<LaunchTreePanel>(*m_window)->selectSourceIndex(
            test::child<LaunchTreeModel>(*m_window)->nodeIndex(detector));
        QVERIFY(waitForLayout());
        QCOMPARE(panel()->currentComposite(), composite);
        QCOMPARE(panel()->breadcrumbIds(), (QStringList{QStringLiteral("lf1"), composite}));
        // The breadcrumbs say whose view it is: vision as system includes it.
        const auto *note = panel()->findChild<QLabel *>(QStringLiteral("crumbNote"));
        QVERIFY(note);
        QCOMPARE(note->text(), QStringLiteral("as included by system"));
        QVERIFY(note->toolTip().contains(QLatin1String("on its own")));
        const Composite *c = doc()->architecture().composite(composite);
        QString partId;
        for (const RosNodePart &p : c->parts)
            if (p.instanceId == detector)
                partId = p.id;
        QGraphicsItem *item = panel()->scene()->item(QStringLiteral("part:") + partId);
        QVERIFY(item);
        QVERIFY(item->isSelected());
    }

    void diagramClickSelectsLaunchTreeAndSource()
    {
        const QString planner = instanceNamed(doc(), QStringLiteral("planner"));
        panel()->showComposite(QStringLiteral("lf1"));
        QVERIFY(waitForLayout());
        Q_EMIT panel()->partActivated(planner); // what a click on the part emits
        const QModelIndex current = test::child<LaunchTreePanel>(*m_window)->currentSourceIndex();
        QCOMPARE(current.data(LaunchTreeModel::InstanceIdRole).toString(), planner);
        // The launch line of the instance shows in the source view.
        QCOMPARE(test::child<SourceView>(*m_window)->currentFile(),
                 QStringLiteral("src/planning/launch/system.launch.py"));
        QCOMPARE(panel()->currentComposite(), QStringLiteral("lf1")); // no jump elsewhere
    }

    void portClickSelectsInstanceAndNodePort()
    {
        const QString rectifier = instanceNamed(doc(), QStringLiteral("rectifier"));
        const NodeInstance *n = doc()->launchDependencies().node(rectifier);
        Q_EMIT panel()->portActivated(rectifier,
                                      QStringLiteral("p1")); // what a click on the port emits
        QCOMPARE(test::child<LaunchTreePanel>(*m_window)
                     ->currentSourceIndex()
                     .data(LaunchTreeModel::InstanceIdRole)
                     .toString(),
                 rectifier);
        const QModelIndex port = test::child<AtomicNodePanel>(*m_window)->currentSourceIndex();
        QCOMPARE(port.data(AtomicNodeModel::NodeIdRole).toString(), n->classId);
        QCOMPARE(port.data(AtomicNodeModel::PortIdRole).toString(), QStringLiteral("p1"));
        QCOMPARE(test::child<SourceView>(*m_window)->currentFile(),
                 QStringLiteral("src/vision/src/rectifier.cpp"));
    }

    void pendingGroupingIsPreviewedWithoutChangingTheModel()
    {
        const QStringList members{instanceNamed(doc(), QStringLiteral("planner")),
                                  instanceNamed(doc(), QStringLiteral("backup_planner"))};
        test::child<DiagramController>(*m_window)->previewGrouping(QStringLiteral("planning"),
                                                                   members, QStringLiteral("lf1"));
        QVERIFY(waitForLayout());
        QCOMPARE(panel()->currentComposite(), QStringLiteral("lf1"));
        QStringList grouped;
        for (const RosNodePart &p : panel()->architecture().composite(QStringLiteral("lf1"))->parts)
            if (p.subsystem == QLatin1String("planning"))
                grouped << p.name;
        QCOMPARE(grouped,
                 (QStringList{QStringLiteral("planner"), QStringLiteral("backup_planner")}));
        QVERIFY(panel()->scene()->item(QStringLiteral("subsystem:planning")));
        for (const RosNodePart &p : doc()->architecture().composite(QStringLiteral("lf1"))->parts)
            QVERIFY(p.subsystem.isEmpty()); // only a preview
        test::child<DiagramController>(*m_window)->previewGrouping({}, {}, {});
        QVERIFY(waitForLayout());
        QVERIFY(!panel()->scene()->item(QStringLiteral("subsystem:planning")));
    }

    void selectedSuggestionsArePreviewed()
    {
        const AtomicNode &planner = *std::find_if(
            doc()->atomicNodes().nodes.cbegin(), doc()->atomicNodes().nodes.cend(),
            [](const AtomicNode &n) { return n.className == QLatin1String("Planner"); });
        Suggestion description;
        description.id = QStringLiteral("s1");
        description.kind = Suggestion::Kind::NodeDescription;
        description.targetId = planner.id;
        description.value = QStringLiteral("Plans velocity commands from detections.");
        Suggestion grouping;
        grouping.id = QStringLiteral("s2");
        grouping.kind = Suggestion::Kind::SubsystemGrouping;
        grouping.targetId = QStringLiteral("lf1");
        grouping.value = QStringLiteral("planning");
        grouping.memberIds = {instanceNamed(doc(), QStringLiteral("planner")),
                              instanceNamed(doc(), QStringLiteral("backup_planner"))};
        SuggestionReport report;
        report.suggestions = {description, grouping};
        doc()->session()->setSuggestions(report);

        test::child<SuggestionPanel>(*m_window)->selectSuggestion(QStringLiteral("s1"));
        const QModelIndex cell = test::child<AtomicNodeModel>(*m_window)->nodeIndex(
            planner.id, AtomicNodeModel::DescriptionColumn);
        QCOMPARE(cell.data().toString(),
                 QStringLiteral("Plans velocity commands from detections. (suggested)"));
        QVERIFY(cell.data(Qt::FontRole).value<QFont>().italic());
        QVERIFY(doc()->atomicNodes().node(planner.id)->description.isEmpty()); // only a preview

        test::child<SuggestionPanel>(*m_window)->selectSuggestion(QStringLiteral("s2"));
        QVERIFY(waitForLayout());
        QCOMPARE(cell.data().toString(), QString()); // the description preview ended
        QVERIFY(panel()->scene()->item(QStringLiteral("subsystem:planning")));

        doc()->session()->acceptSuggestion(
            QStringLiteral("s2")); // accepted: drawn as the model, not a preview
        QVERIFY(test::acceptedSettled(*doc()));
        QVERIFY(waitForLayout());
        QVERIFY(panel()->scene()->item(QStringLiteral("subsystem:planning")));
        test::saveScreenshot(*panel(), QStringLiteral("diagram-subsystem.png"));
        QTemporaryDir out;
        QVERIFY(m_window->exportArtifactsTo(out.path()));
        QVERIFY(test::readFile(out.filePath(QStringLiteral("architecture.json")))
                    .contains("\"subsystem\": \"planning\""));
        QVERIFY(test::readFile(out.filePath(QStringLiteral("ccd/system.puml")))
                    .contains("<<Subsystem>>"));
        doc()->undoStack()->undo();
        QVERIFY(test::acceptedSettled(*doc()));
        QVERIFY(waitForLayout());
        doc()->session()->setSuggestions({});
        test::child<DiagramController>(*m_window)->previewGrouping({}, {}, {});
        QVERIFY(waitForLayout());
        QVERIFY(!panel()->scene()->item(QStringLiteral("subsystem:planning")));
    }

    void acceptedPortNameIsComposedAgain()
    {
        const AtomicNode &commander = *std::find_if(
            doc()->atomicNodes().nodes.cbegin(), doc()->atomicNodes().nodes.cend(),
            [](const AtomicNode &n) { return n.className == QLatin1String("Commander"); });
        Suggestion name;
        name.id = QStringLiteral("s3");
        name.kind = Suggestion::Kind::NameResolution;
        name.targetId = commander.id + QStringLiteral("/p2"); // f'report_{id(self)}'
        name.value = QStringLiteral("~/report");
        SuggestionReport report;
        report.suggestions = {name};
        doc()->session()->setSuggestions(report);
        doc()->session()->acceptSuggestion(QStringLiteral("s3"));
        QVERIFY(test::acceptedSettled(*doc()));
        const auto reportPort = [this]() -> const PartPort * {
            for (const RosNodePart &p :
                 panel()->architecture().composite(QStringLiteral("lf1"))->parts)
                if (p.name == QLatin1String("commander"))
                    for (const PartPort &port : p.ports)
                        if (port.id == QLatin1String("p2"))
                            return &port;
            return nullptr;
        };
        QVERIFY(reportPort());
        QVERIFY(reportPort()->resolved);
        QCOMPARE(reportPort()->name, QStringLiteral("/commander/report"));
        bool promoted = false; // no one listens inside: it becomes a boundary port
        for (const BoundaryPort &b :
             panel()->architecture().composite(QStringLiteral("lf1"))->boundary)
            promoted = promoted || b.name == QLatin1String("/commander/report");
        QVERIFY(promoted);
        doc()->undoStack()->undo();
        QVERIFY(test::acceptedSettled(*doc()));
        QVERIFY(!reportPort()->resolved);
        doc()->session()->setSuggestions({});
        QVERIFY(waitForLayout());
    }

    void comparisonMarksExtraAndListsMissing()
    {
        QTemporaryDir reference;
        // The reference lacks the detector that the recovery has: the detector is extra.
        QVERIFY(QFile::copy(
            test::dataDir(QStringLiteral("compose_system/broken/vision_missing_detector.puml")),
            reference.filePath(QStringLiteral("vision.puml"))));
        QString error;
        const QString report = test::child<DiagramController>(*m_window)->compareWithReference(
            reference.path(), &error);
        QVERIFY2(!report.isEmpty(), qPrintable(error));
        QVERIFY(report.contains(QLatin1String("FP RosNodePart: detector")));
        const LevelEvaluation *ccd =
            test::child<DiagramController>(*m_window)->comparison().level(UmlLevel::Ccd);
        QVERIFY(ccd);
        QVERIFY(ccd->micro.precision < 1.0);
        QCOMPARE(ccd->micro.recall, 1.0);

        panel()->showComposite(QStringLiteral("lf2"));
        QVERIFY(waitForLayout());
        const Composite *vision = doc()->architecture().composite(QStringLiteral("lf2"));
        QString detectorPart;
        for (const RosNodePart &p : vision->parts)
            if (p.name == QLatin1String("detector"))
                detectorPart = p.id;
        const QStringList marked = markedKeys(panel());
        QVERIFY2(marked.contains(QStringLiteral("part:") + detectorPart),
                 qPrintable(marked.join(' ')));
        for (const QString &key : marked) // only the detector and its connections
            QVERIFY2(key == QStringLiteral("part:") + detectorPart ||
                         key.startsWith(QLatin1String("connection:")),
                     qPrintable(key));
        test::saveScreenshot(*m_window, QStringLiteral("diagram-comparison.png"));

        // Against the hand-checked expected model nothing is marked and every score is 1.
        const QString exact = test::child<DiagramController>(*m_window)->compareWithReference(
            test::dataDir(QStringLiteral("compose_system/expected")), &error);
        QVERIFY(!exact.isEmpty());
        for (const LevelEvaluation &l :
             test::child<DiagramController>(*m_window)->comparison().levels)
            QCOMPARE(l.micro.f1, 1.0);
        QVERIFY(waitForLayout());
        QVERIFY(markedKeys(panel()).isEmpty());

        QVERIFY(test::child<DiagramController>(*m_window)
                    ->compareWithReference(QStringLiteral("/nonexistent/reference"), &error)
                    .isEmpty());
        QVERIFY(!error.isEmpty());
    }

    void exportsTheShownDiagram()
    {
        QTemporaryDir out;
        const QString svg = out.filePath(QStringLiteral("vision.svg"));
        const QString png = out.filePath(QStringLiteral("vision.png"));
        QVERIFY(test::child<DiagramController>(*m_window)->exportDiagram(svg));
        QVERIFY(test::child<DiagramController>(*m_window)->exportDiagram(png));
        QVERIFY(test::readFile(svg).contains("rectifier"));
        QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() > 200);
        // The JSON and PlantUML artifacts include stage 3.
        QVERIFY(m_window->exportArtifactsTo(out.path()));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("ccd/system.puml"))));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("architecture.json"))));
    }
};

QTEST_MAIN(TestDiagramIntegration)
#include "tst_diagramintegration.moc"
