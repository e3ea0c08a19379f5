// The workspace watcher: which changes ask for which re-run, debounced into one request, the
// tool's own files ignored; and in the window, an edit on disk re-runs the stages and the
// model shows the change.
#include "app/appsettings.h"
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "app/workspacewatcher.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "support/testsupport.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::gui;
using Rerun = WorkspaceWatcher::Rerun;

namespace {

void edit(const QString &file, const QByteArray &from, const QByteArray &to)
{
    QByteArray text = test::readFile(file);
    QVERIFY2(text.contains(from), qPrintable(file));
    text.replace(from, to);
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate)); // in place, as many editors do
    QCOMPARE(f.write(text), text.size());
}

bool hasPort(const Document &document, const QString &name)
{
    for (const AtomicNode &n : document.atomicNodes().nodes)
        for (const Port &p : n.ports)
            if (p.name == name)
                return true;
    return false;
}

} // namespace

class TestWorkspaceWatcher : public QObject
{
    Q_OBJECT

    QTemporaryDir m_temp;
    QString m_ws;

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QVERIFY(m_temp.isValid());
    }

    void init()
    {
        QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                 .filePath(QStringLiteral("projects")))
            .removeRecursively();
        m_ws = m_temp.filePath(QString::fromLatin1(QTest::currentTestFunction()));
        test::copyTree(fixture(), m_ws);
    }

    void classifiesChanges_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<int>("rerun"); // -1 none, else Rerun
        const int none = -1, launch = int(Rerun::Launch), all = int(Rerun::All);
        QTest::newRow("C++ source") << kListener << all;
        QTest::newRow("Python source") << kTalker << all;
        QTest::newRow("Python launch") << kDemoLaunch << launch;
        QTest::newRow("XML launch") << kListenerLaunch << launch;
        QTest::newRow("YAML launch") << kExtraLaunch << launch;
        QTest::newRow("parameter file") << QStringLiteral("src/a/config/params.yaml") << launch;
        QTest::newRow("package.xml") << QStringLiteral("src/a/package.xml") << all;
        QTest::newRow("CMakeLists.txt") << QStringLiteral("src/a/CMakeLists.txt") << all;
        QTest::newRow("setup.cfg") << QStringLiteral("src/a/setup.cfg") << all;
        QTest::newRow("project") << QStringLiteral("rosarch.project.json") << none;
        QTest::newRow("autosave") << QStringLiteral(".rosarch.project.json.autosave") << none;
        QTest::newRow("build output") << QStringLiteral("build/a/x.cpp") << none;
        QTest::newRow("hidden folder") << QStringLiteral(".git/x.py") << none;
        QTest::newRow("readme") << QStringLiteral("src/a/README.md") << none;
    }
    void classifiesChanges()
    {
        QFETCH(QString, path);
        QFETCH(int, rerun);
        const std::optional<Rerun> r = WorkspaceWatcher::rerunFor(path);
        QCOMPARE(r ? int(*r) : -1, rerun);
    }

    void aSourceEditAsksForEveryStage()
    {
        WorkspaceWatcher watcher;
        watcher.setWorkspace(m_ws);
        QTRY_VERIFY(watcher.isWatching());
        QVERIFY(watcher.watchesFiles());
        QSignalSpy asked(&watcher, &WorkspaceWatcher::rerunRequested);
        edit(m_ws + QLatin1Char('/') + kListener, "chatter", "chatter2");
        QVERIFY(asked.wait(10000));
        QCOMPARE(asked.count(), 1);
        QCOMPARE(asked.at(0).at(0).value<Rerun>(), Rerun::All);
        QCOMPARE(asked.at(0).at(1).toStringList(), QStringList{kListener});
    }

    void launchEditsAskForStagesTwoAndThreeAndOwnFilesAreIgnored()
    {
        WorkspaceWatcher watcher;
        watcher.setWorkspace(m_ws);
        QTRY_VERIFY(watcher.isWatching());
        QSignalSpy asked(&watcher, &WorkspaceWatcher::rerunRequested);
        // A burst: the tool's own files, then two launch files; one request for the two.
        test::writeFile(m_ws + QStringLiteral("/rosarch.project.json"), "{}");
        test::writeFile(m_ws + QStringLiteral("/.rosarch.project.json.autosave"), "{}");
        edit(m_ws + QLatin1Char('/') + kExtraLaunch, "launch", "launch ");
        edit(m_ws + QLatin1Char('/') + kListenerLaunch, "<launch>", "<launch> ");
        QVERIFY(asked.wait(10000));
        QCOMPARE(asked.count(), 1);
        QCOMPARE(asked.at(0).at(0).value<Rerun>(), Rerun::Launch);
        QCOMPARE(asked.at(0).at(1).toStringList(), (QStringList{kExtraLaunch, kListenerLaunch}));
    }

    void aNewFileIsSeenAndWatched()
    {
        WorkspaceWatcher watcher;
        watcher.setWorkspace(m_ws);
        QTRY_VERIFY(watcher.isWatching());
        QSignalSpy asked(&watcher, &WorkspaceWatcher::rerunRequested);
        const QString added = QStringLiteral("src/py_talker/py_talker/extra.py");
        test::writeFile(m_ws + QLatin1Char('/') + added, "x = 1\n");
        QVERIFY(asked.wait(10000));
        QCOMPARE(asked.last().at(1).toStringList(), QStringList{added});
        // and an edit of it later, in place
        edit(m_ws + QLatin1Char('/') + added, "x = 1", "x = 2");
        QVERIFY(asked.wait(10000));
        QCOMPARE(asked.last().at(1).toStringList(), QStringList{added});
    }

    void switchedOffItAsksForNothing()
    {
        WorkspaceWatcher watcher;
        watcher.setWorkspace(m_ws);
        QTRY_VERIFY(watcher.isWatching());
        watcher.setEnabled(false);
        QSignalSpy asked(&watcher, &WorkspaceWatcher::rerunRequested);
        edit(m_ws + QLatin1Char('/') + kListener, "chatter", "chatter2");
        watcher.setEnabled(true); // watching anew: what changed before is not asked for
        QTRY_VERIFY(watcher.isWatching());
        edit(m_ws + QLatin1Char('/') + kTalker, "chatter", "chatter3");
        QVERIFY(asked.wait(10000));
        QCOMPARE(asked.count(), 1);
        QCOMPARE(asked.at(0).at(1).toStringList(), QStringList{kTalker});
    }

    void theWindowRerunsAndShowsTheChange()
    {
        MainWindow w;
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(m_ws);
        QVERIFY(finished.wait(60000));
        QVERIFY(hasPort(*test::child<Document>(w), QStringLiteral("chatter")));
        QVERIFY(!hasPort(*test::child<Document>(w), QStringLiteral("chatter_renamed")));

        QSignalSpy started(test::child<StageRunner>(w), &StageRunner::stageStarted);
        edit(m_ws + QLatin1Char('/') + kTalker, "'chatter'", "'chatter_renamed'");
        QVERIFY(finished.wait(60000));
        QCOMPARE(started.count(), 1);
        QVERIFY(hasPort(*test::child<Document>(w), QStringLiteral("chatter_renamed")));
        QVERIFY(AppSettings().watchWorkspace());
    }
};

QTEST_MAIN(TestWorkspaceWatcher)
#include "tst_workspacewatcher.moc"
