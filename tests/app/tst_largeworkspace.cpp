// The window on a large workspace (1,000 packages, generated): the stages run, the result
// arrives in the views, the status bar says which stage is at how many files, the log says how
// long each stage took, and the UI thread never stops answering for long (a generous limit
// here; rosarch-stallbench measures it strictly on real workspaces).
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "syntheticworkspace.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/nodefilterproxymodel.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeView>
#include <QtTest>

#include <functional>

using namespace rosarch;

namespace {

constexpr int kPackages = 1000;
constexpr int kGroup = 10; ///< every 10th package's launch file includes the next nine

#if defined(__SANITIZE_ADDRESS__)
constexpr qint64 kStallLimitMs = 10000; // AddressSanitizer makes everything several times slower
#else
constexpr qint64 kStallLimitMs = 2000;
#endif

/// The longest time the UI thread did not get to a 10 ms timer while it was watched.
class StallWatch
{
public:
    StallWatch()
    {
        m_clock.start();
        m_timer.setInterval(10);
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            const qint64 now = m_clock.elapsed();
            m_longest = std::max(m_longest, now - m_last);
            m_last = now;
        });
        m_timer.start();
    }
    qint64 longest() const { return m_longest; }

private:
    QElapsedTimer m_clock;
    QTimer m_timer;
    qint64 m_last = 0;
    qint64 m_longest = 0;
};

} // namespace

class TestLargeWorkspace : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                 .filePath(QStringLiteral("projects")))
            .removeRecursively();
    }

    void aThousandPackagesArriveWithoutFreezingTheWindow()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // kept for rosarch-stallbench when asked
        dir.setAutoRemove(qEnvironmentVariableIsEmpty("ROSARCH_KEEP_LARGE_WORKSPACE"));
        QString error;
        QVERIFY2(SyntheticWorkspace::generate(dir.path(), kPackages, kGroup, &error),
                 qPrintable(error));
        if (!dir.autoRemove())
            qInfo("workspace kept in %s", qPrintable(dir.path()));

        MainWindow w;
        w.resize(1400, 900);
        w.show();
        QStringList statusMessages;
        connect(w.statusBar(), &QStatusBar::messageChanged, this,
                [&](const QString &m) { statusMessages << m; });
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        QSignalSpy progressed(test::child<StageRunner>(w), &StageRunner::stageProgressed);
        QSignalSpy timed(test::child<StageRunner>(w), &StageRunner::stageTimed);
        StallWatch watch;
        w.openWorkspace(dir.path());
        QVERIFY(finished.wait(120000));
        QTest::qWait(300); // what the result sets off (diagram, views) runs

        // The result arrived, in the document and in the views.
        const AtomicNodeList &nodes = test::child<Document>(w)->atomicNodes();
        QCOMPARE(nodes.nodes.size(), kPackages);
        QCOMPARE(test::child<AtomicNodeModel>(w)->rowCount(), kPackages); // one package row each
        const QModelIndex relay =
            test::child<AtomicNodeModel>(w)->nodeIndex(nodes.nodes.first().id);
        QVERIFY(relay.isValid());
        QCOMPARE(test::child<AtomicNodeModel>(w)->rowCount(relay),
                 3); // two publishers, one subscription
        const LaunchDependencies &launch = test::child<Document>(w)->launchDependencies();
        QCOMPARE(launch.launchFiles.size(), kPackages + 1);
        QVERIFY2(launch.nodes.size() >= kPackages,
                 qPrintable(QString::number(launch.nodes.size())));
        QVERIFY(test::child<LaunchTreeModel>(w)->rowCount() > 0);

        // The diagram of the root including every group's launch file: built off the UI thread
        // (it has more elements than the panel builds inline), laid out and drawn.
        DiagramPanel *panel = test::child<DiagramPanel>(w);
        const Composite *all = panel->architecture().composite(panel->currentComposite());
        QVERIFY(all);
        QCOMPARE(all->stem, QStringLiteral("all"));
        QVERIFY(all->parts.size() + all->channels.size() + all->boundary.size() +
                    all->connections.size() >
                DiagramPanel::kInlineBuildElements);
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isLayingOut(), 60000);
        QVERIFY2(panel->message().isEmpty(), qPrintable(panel->message()));
        QVERIFY(!panel->scene()->isEmpty());

        // Per-stage progress with file counts, and the time each stage took, in the log.
        QSet<int> stages;
        for (const QList<QVariant> &p : std::as_const(progressed))
            if (p.at(1).toInt() > 0)
                stages.insert(p.at(3).toInt());
        QVERIFY(stages.contains(1));
        QVERIFY(stages.contains(2));
        QVERIFY(stages.contains(3));
        QVERIFY2(std::any_of(statusMessages.cbegin(), statusMessages.cend(),
                             [](const QString &m) {
                                 return m.startsWith(QStringLiteral("Stage 1: atomic nodes — ")) &&
                                        m.endsWith(QStringLiteral(" files"));
                             }),
                 qPrintable(statusMessages.join(u'\n')));
        QCOMPARE(timed.size(), 3);
        const QString log = test::child<LogView>(w)->logEdit()->toPlainText();
        for (const QString &line : {QStringLiteral("Stage 1 (atomic nodes) took "),
                                    QStringLiteral("Stage 2 (launch files) took "),
                                    QStringLiteral("Stage 3 (composition) took "),
                                    QStringLiteral("Showing the result in the window took ")})
            QVERIFY2(log.contains(line), qPrintable(line));

        // Typing into the launch tree's filter, as a person looking for a node: every key
        // shows at once, the filter follows a pause in typing (filtering a tree this size is
        // no longer cheap), and then the way to the matches is open, within a budget of rows
        // (before: every kept row was expanded, for seconds on navigation2).
        QLineEdit *filter = test::child<LaunchTreePanel>(w)->filterEdit();
        QTreeView *launchTree = test::child<LaunchTreePanel>(w)->treeView();
        filter->setFocus();
        QTest::keyClicks(filter, QStringLiteral("r"));
        QTRY_COMPARE(
            test::child<LaunchTreePanel>(w)->proxyModel()->filterRegularExpression().pattern(),
            QStringLiteral("r"));
        QTest::keyClicks(filter, QStringLiteral("elay_999"));
        QCOMPARE(filter->text(), QStringLiteral("relay_999"));
        QTRY_COMPARE(
            test::child<LaunchTreePanel>(w)->proxyModel()->filterRegularExpression().pattern(),
            QStringLiteral("relay_999"));
        QModelIndex match;
        std::function<void(const QModelIndex &)> find = [&](const QModelIndex &parent) {
            for (int r = 0; r < launchTree->model()->rowCount(parent) && !match.isValid(); ++r) {
                const QModelIndex i = launchTree->model()->index(r, 0, parent);
                if (i.data().toString() == QLatin1String("relay_999"))
                    match = i;
                else
                    find(i);
            }
        };
        find({});
        QVERIFY(match.isValid());
        for (QModelIndex p = match.parent(); p.isValid(); p = p.parent())
            QVERIFY2(launchTree->isExpanded(p), qPrintable(p.data().toString()));
        filter->clear();
        QTRY_VERIFY(test::child<LaunchTreePanel>(w)
                        ->proxyModel()
                        ->filterRegularExpression()
                        .pattern()
                        .isEmpty());

        // A second run finds nothing new: the views stay.
        QTest::keyClick(&w, Qt::Key_F5);
        QVERIFY(finished.wait(120000));
        QVERIFY(test::child<StageRunner>(w)->resultUnchanged());
        QCOMPARE(test::child<AtomicNodeModel>(w)->rowCount(), kPackages);
        QVERIFY(test::child<LogView>(w)->logEdit()->toPlainText().contains(
            QStringLiteral("the result is the same as the one shown")));
        QTest::qWait(100);

        QVERIFY2(
            watch.longest() < kStallLimitMs,
            qPrintable(QStringLiteral("the UI thread stalled for %1 ms").arg(watch.longest())));

        // The window goes (at the end of this scope) while the diagram of the big root is built
        // again (Expand All): the build's worker is waited for and its result goes nowhere.
        panel->expandAll();
        QVERIFY(panel->isBuilding());
    }
};

QTEST_MAIN(TestLargeWorkspace)
#include "tst_largeworkspace.moc"
