// Rows of *Architecture changes* select what they are about: a port in the node list, a part in
// the launch tree and the diagram, a topic in the diagram; a removed element, not in the model
// shown, is said in the status bar. On the example workspace, the changes written as
// ArchitectureDiff writes them for elements of the model shown.
#include "app/mainwindow.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "support/diagramwait.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/architecturediffview.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"

#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

using namespace rosarch;
using Kind = ArchitectureChange::Kind;

class TestChangeSelection : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    MainWindow *m_window = nullptr;

    Document *doc() const { return test::child<Document>(*m_window); }
    DiagramPanel *diagram() const { return test::child<DiagramPanel>(*m_window); }
    QTreeWidget *tree() const { return test::child<ArchitectureDiffView>(*m_window)->tree(); }

    /// Makes the row of the `i`th change current, as a click on it does.
    void choose(int i)
    {
        QTreeWidgetItem *row = nullptr;
        for (int g = 0; g < tree()->topLevelItemCount() && !row; ++g)
            for (int r = 0; r < tree()->topLevelItem(g)->childCount(); ++r)
                if (tree()->topLevelItem(g)->child(r)->data(0, Qt::UserRole).toInt() == i)
                    row = tree()->topLevelItem(g)->child(r);
        QVERIFY(row);
        tree()->setCurrentItem(row);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
        QVERIFY(m_dir.isValid());
        const QString ws = m_dir.filePath(QStringLiteral("ws"));
        test::copyTree(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                           .filePath(QStringLiteral("resources/example_ws")),
                       ws);
        m_window = new MainWindow;
        m_window->resize(1600, 1000);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        m_window->openWorkspace(ws);
        QTRY_VERIFY_WITH_TIMEOUT(!doc()->architecture().composites.isEmpty(), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(
            !diagram()->isLayingOut() && !diagram()->currentComposite().isEmpty(), 30000);
    }

    void cleanupTestCase() { delete m_window; }

    void rowsSelectTheirElement()
    {
        // A port of a class, a node part of a launch file and a topic of its composite, as
        // ArchitectureDiff describes them; and a class that is gone.
        const Recovery &now = doc()->accepted();
        const AtomicNode *cls = nullptr;
        for (const AtomicNode &n : now.nodes.nodes)
            if (!cls && n.ports.size() > 1 && !n.ports.at(1).name.isEmpty())
                cls = &n;
        QVERIFY(cls);
        const Port &port = cls->ports.at(1);
        const Composite *c = nullptr;
        for (const Composite &x : now.architecture.composites)
            if (!c && !x.file.isEmpty() && !x.channels.isEmpty() &&
                std::any_of(x.parts.cbegin(), x.parts.cend(),
                            [](const RosNodePart &p) { return p.kind == RosNodePart::Kind::Node; }))
                c = &x;
        QVERIFY(c);
        const RosNodePart *part = nullptr;
        for (const RosNodePart &p : c->parts)
            if (!part && p.kind == RosNodePart::Kind::Node)
                part = &p;
        // a topic drawn in its composite (not inside a collapsed namespace)
        if (diagram()->currentComposite() != c->instanceId)
            QVERIFY(test::laidOut(*diagram(), [&] { diagram()->showComposite(c->instanceId); }));
        const Channel *drawn = nullptr;
        for (const Channel &ch : c->channels)
            if (!drawn && diagram()->scene()->item(DiagramBuilder::channelKey(ch.id)))
                drawn = &ch;
        QVERIFY(drawn);
        const Channel &channel = *drawn;
        const QString ns = part->nameSpace == QLatin1String("/") ? QString() : part->nameSpace;
        const QList<ArchitectureChange> changes{
            {Kind::Added,
             QStringLiteral("port"),
             cls->className,
             {},
             QStringLiteral("%1 %2 (%3)").arg(portKindName(port.kind), port.name, port.type)},
            {Kind::Added,
             QStringLiteral("part"),
             c->file,
             {},
             ns + u'/' + part->name + QStringLiteral(" : ") + part->typeName},
            {Kind::Renamed, channelKindName(channel.kind), c->file, QStringLiteral("/old_name"),
             channel.name},
            {Kind::Removed,
             QStringLiteral("node class"),
             QStringLiteral("Gone"),
             QStringLiteral("gone_pkg/Gone"),
             {}},
        };
        test::child<ArchitectureDiffView>(*m_window)->setChanges(changes, QStringLiteral("before"),
                                                                 QStringLiteral("now"));

        choose(0);
        QCOMPARE(test::child<AtomicNodeModel>(*m_window)->elementId(
                     test::child<AtomicNodePanel>(*m_window)->currentSourceIndex()),
                 cls->id + u'/' + port.id);

        choose(1);
        QCOMPARE(test::child<LaunchTreePanel>(*m_window)
                     ->currentSourceIndex()
                     .data(LaunchTreeModel::InstanceIdRole)
                     .toString(),
                 part->instanceId);
        QCOMPARE(diagram()->currentComposite(), c->instanceId);
        QTRY_VERIFY(!diagram()->isLayingOut());
        QVERIFY(diagram()->selectedKeys().size() == 1);

        choose(2);
        QTRY_VERIFY(!diagram()->isLayingOut());
        QTRY_COMPARE(diagram()->selectedKeys(),
                     QStringList{DiagramBuilder::channelKey(channel.id)});

        choose(3);
        QVERIFY2(m_window->statusBar()->currentMessage().contains(QLatin1String("removed")),
                 qPrintable(m_window->statusBar()->currentMessage()));
    }
};

QTEST_MAIN(TestChangeSelection)
#include "tst_changeselection.moc"
