// The project file as a desktop user expects it: Save / Save As / Open Project
// through the window, the modified indicator, recent projects, Save / Discard / Cancel before
// changes are replaced, the autosave side file and the offer to recover it after a crash, and
// a broken or newer project file explained and kept.
#include "app/appsettings.h"
#include "app/mainwindow.h"
#include "app/projectcontroller.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "project/project.h"
#include "suggestions/suggestionengine.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/logview.h"

#include <QAbstractButton>
#include <QAction>
#include <QDir>
#include <QDirIterator>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace rosarch;

namespace {

/// A copy of resources/example_ws in `dir`: a workspace the tests may write a project into.
QString copyExampleWorkspace(const QTemporaryDir &dir)
{
    const QString source =
        QDir(QStringLiteral(ROSARCH_SOURCE_DIR)).filePath(QStringLiteral("resources/example_ws"));
    const QString target = dir.filePath(QStringLiteral("example_ws"));
    QDirIterator it(source, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString copy = QDir(target).filePath(QDir(source).relativeFilePath(file));
        QDir().mkpath(QFileInfo(copy).path());
        QFile::copy(file, copy);
    }
    return QFileInfo(target).canonicalFilePath();
}

/// Opens `workspace` in `w` and waits for stages 1-3.
bool openAndRun(MainWindow &w, const QString &workspace)
{
    QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
    w.openWorkspace(workspace);
    return finished.wait(60000);
}

/// The deterministic suggestions of the open model; accepts the first description and returns
/// its value.
QString decideOne(MainWindow &w)
{
    Document *doc = test::child<Document>(w);
    const Recovery model{doc->atomicNodes(), doc->launchDependencies(), doc->architecture()};
    doc->session()->setSuggestions(
        SuggestionEngine(doc->workspaceRoot(), model, SuggestionEngine::Options()).run());
    for (const Suggestion &s : doc->session()->suggestions())
        if (s.kind == Suggestion::Kind::NodeDescription) {
            doc->session()->acceptSuggestion(s.id);
            return s.value;
        }
    return {};
}

QMessageBox *box(const QWidget &w, const QString &name)
{
    for (QMessageBox *b : w.findChildren<QMessageBox *>(name))
        if (b->isVisible())
            return b;
    return nullptr;
}

void answer(QMessageBox *b, QMessageBox::StandardButton button)
{
    b->button(button)->click();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

qsizetype storedDecisions(const QString &file)
{
    Project p;
    QString error;
    return ProjectFile::read(file, &p, &error) ? p.decisions.size() : -1;
}

} // namespace

class TestProjectFile : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
    }

    void saveMarksCleanAndOpenProjectRestores()
    {
        QTemporaryDir dir;
        const QString ws = copyExampleWorkspace(dir);
        const QString file = ProjectFile::defaultPath(ws);
        QString value;
        {
            MainWindow w;
            w.show();
            QVERIFY(openAndRun(w, ws));
            QVERIFY(w.windowTitle().contains(QStringLiteral("example_ws[*]")));
            QVERIFY(!w.isWindowModified());
            QVERIFY(!box(w, QStringLiteral("recoverAutosaveBox")));
            value = decideOne(w);
            QVERIFY(!value.isEmpty());
            QVERIFY(w.isWindowModified());
            QVERIFY(test::child<Document>(w)->session()->isModified());
            QVERIFY(!QFileInfo::exists(file)); // nothing written before Save

            test::child<ProjectController>(w)->saveAction()->trigger();
            QVERIFY(QFileInfo::exists(file)); // into the workspace, not the application data
            QVERIFY(test::readFile(file).contains(value.toUtf8()));
            QCOMPARE(storedDecisions(file), 1);
            QVERIFY(!w.isWindowModified());
            QCOMPARE(test::child<Document>(w)->session()->projectPath(), file);
            QVERIFY(!QFileInfo::exists(ProjectFile::autosavePath(file)));
            QCOMPARE(AppSettings().recentProjects().value(0), file);

            // Undo marks it modified, redo back to the saved state clears it.
            test::child<Document>(w)->undoStack()->undo();
            QVERIFY(w.isWindowModified());
            test::child<Document>(w)->undoStack()->redo();
            QVERIFY(!w.isWindowModified());

            // The project holds the launch options as well.
            LaunchOptions options;
            options.arguments = {{QStringLiteral("robot"), QStringLiteral("r7")}};
            test::child<Document>(w)->session()->setLaunchOptions(options);
            QVERIFY(w.isWindowModified());
            QVERIFY(test::child<ProjectController>(w)->save());
            QVERIFY(test::readFile(file).contains("\"r7\""));
            w.close();
            QVERIFY(!w.isVisible()); // nothing unsaved: no question
        }
        // Open Project on the file opens its workspace with its decisions and launch options.
        MainWindow again;
        again.show();
        QSignalSpy finished(test::child<StageRunner>(again), &StageRunner::stageFinished);
        QVERIFY(test::child<ProjectController>(again)->openProject(file));
        QCOMPARE(again.workspace(), ws);
        QCOMPARE(test::child<Document>(again)->session()->launchOptions().arguments.value(
                     QStringLiteral("robot")),
                 QStringLiteral("r7"));
        QVERIFY(finished.wait(60000));
        QCOMPARE(test::child<Document>(again)->session()->decisions().size(), 1);
        bool described = false;
        for (const AtomicNode &n : test::child<Document>(again)->atomicNodes().nodes)
            described |= n.description == value;
        QVERIFY(described);
        QVERIFY(!again.isWindowModified());
    }

    void saveAsElsewhereNamesTheWorkspace()
    {
        QTemporaryDir dir;
        QTemporaryDir elsewhere;
        const QString ws = copyExampleWorkspace(dir);
        MainWindow w;
        QVERIFY(openAndRun(w, ws));
        const QString value = decideOne(w);
        // outside the workspace: an absolute path; inside a subfolder: relative
        const QString outside = elsewhere.filePath(QStringLiteral("review.project.json"));
        test::child<ProjectController>(w)->setFileChooser(
            [&](const QString &, const QString &start, bool forSaving) {
                return forSaving && start == ProjectFile::defaultPath(ws) ? outside : QString();
            });
        test::child<ProjectController>(w)->saveAsAction()->trigger();
        QVERIFY(!w.isWindowModified());
        Project saved;
        QString error;
        QVERIFY2(ProjectFile::read(outside, &saved, &error), qPrintable(error));
        QCOMPARE(saved.workspace, ws);
        QCOMPARE(ProjectFile::workspaceOf(outside, saved), ws);
        QVERIFY(!QFileInfo::exists(ProjectFile::defaultPath(ws)));
        QVERIFY(w.windowTitle().contains(QStringLiteral("review.project.json")));

        const QString inside = QDir(ws).filePath(QStringLiteral("docs/arch.project.json"));
        QVERIFY(test::child<ProjectController>(w)->saveTo(inside));
        QVERIFY(ProjectFile::read(inside, &saved, &error));
        QCOMPARE(saved.workspace, QStringLiteral(".."));
        QCOMPARE(ProjectFile::workspaceOf(inside, saved), ws);

        // The file saved outside opens in another window with its decision.
        MainWindow other;
        QSignalSpy finished(test::child<StageRunner>(other), &StageRunner::stageFinished);
        QVERIFY(test::child<ProjectController>(other)->openProject(outside));
        QVERIFY(finished.wait(60000));
        QCOMPARE(test::child<Document>(other)->session()->projectPath(), outside);
        QCOMPARE(test::child<Document>(other)->session()->decisions().size(), 1);
        QCOMPARE(test::child<Document>(other)->session()->decisions().first().proposal, value);

        // Recent projects, newest first; a file that is gone is greyed.
        QCOMPARE(AppSettings().recentProjects().mid(0, 2), (QStringList{outside, inside}));
        QFile::remove(inside);
        test::child<ProjectController>(other)->updateRecentMenu();
        const QList<QAction *> actions =
            test::child<ProjectController>(other)->recentMenu()->actions();
        QVERIFY(actions.size() >= 3);
        QVERIFY(actions.at(0)->text().contains(QStringLiteral("review.project.json")));
        QVERIFY(actions.at(0)->isEnabled());
        QVERIFY(actions.at(1)->text().contains(QStringLiteral("arch.project.json")));
        QVERIFY(!actions.at(1)->isEnabled());
    }

    void unsavedChangesAskBeforeClosing()
    {
        QTemporaryDir dir;
        const QString ws = copyExampleWorkspace(dir);
        MainWindow w;
        w.show();
        QVERIFY(openAndRun(w, ws));
        decideOne(w);
        test::child<Document>(w)->session()->setAutosaveInterval(50);
        QTRY_VERIFY(QFileInfo::exists(test::child<Document>(w)->session()->autosaveFile()));
        QVERIFY(!QFileInfo::exists(ProjectFile::defaultPath(ws)));

        // Cancel: the window stays, modified.
        w.close();
        QMessageBox *ask = box(w, QStringLiteral("unsavedChangesBox"));
        QVERIFY(ask);
        QVERIFY(ask->text().contains(QStringLiteral("example_ws")));
        // It names the file Save writes: the workspace's project file, not the one kept
        // under the application data until then.
        QVERIFY2(
            ask->informativeText().contains(QDir::toNativeSeparators(ProjectFile::defaultPath(ws))),
            qPrintable(ask->informativeText()));
        QVERIFY(w.isVisible());
        answer(ask, QMessageBox::Cancel);
        QVERIFY(w.isVisible());
        QVERIFY(w.isWindowModified());

        // Opening another workspace asks as well; Cancel keeps this one.
        QTemporaryDir otherDir;
        const QString otherWs = copyExampleWorkspace(otherDir);
        w.openWorkspace(otherWs);
        ask = box(w, QStringLiteral("unsavedChangesBox"));
        QVERIFY(ask);
        answer(ask, QMessageBox::Cancel);
        QCOMPARE(w.workspace(), ws);

        // Discard: the window closes, nothing is written and the side file goes.
        w.close();
        ask = box(w, QStringLiteral("unsavedChangesBox"));
        QVERIFY(ask);
        answer(ask, QMessageBox::Discard);
        QVERIFY(!w.isVisible());
        QVERIFY(!QFileInfo::exists(ProjectFile::defaultPath(ws)));
        QVERIFY(!QFileInfo::exists(test::child<Document>(w)->session()->autosaveFile()));
    }

    void saveFromTheQuestionWritesTheProject()
    {
        QTemporaryDir dir;
        const QString ws = copyExampleWorkspace(dir);
        MainWindow w;
        w.show();
        QVERIFY(openAndRun(w, ws));
        const QString value = decideOne(w);
        w.close();
        QMessageBox *ask = box(w, QStringLiteral("unsavedChangesBox"));
        QVERIFY(ask);
        answer(ask, QMessageBox::Save);
        QVERIFY(!w.isVisible());
        QVERIFY(test::readFile(ProjectFile::defaultPath(ws)).contains(value.toUtf8()));
    }

    void aCrashLeavesChangesToRecover()
    {
        QTemporaryDir dir;
        const QString ws = copyExampleWorkspace(dir);
        const QString side = ProjectFile::autosavePath(ProjectFile::locate(ws));
        QString value;
        {
            auto *w = new MainWindow;
            QVERIFY(openAndRun(*w, ws));
            test::child<Document>(*w)->session()->setAutosaveInterval(50);
            value = decideOne(*w);
            QTRY_VERIFY(QFileInfo::exists(side)); // the autosave, not the project
            QVERIFY(!QFileInfo::exists(ProjectFile::defaultPath(ws)));
            QVERIFY(test::readFile(side).contains(value.toUtf8()));
            delete w; // gone without Save or Discard: the side file stays
        }
        QVERIFY(QFileInfo::exists(side));
        {
            // Discard: the side file goes, the project is as saved (empty).
            MainWindow w;
            QVERIFY(openAndRun(w, ws));
            QMessageBox *offer = box(w, QStringLiteral("recoverAutosaveBox"));
            QVERIFY(offer);
            // names when the changes were kept
            QVERIFY2(offer->text().contains(
                         QString::number(QFileInfo(side).lastModified().date().year())),
                     qPrintable(offer->text()));
            QVERIFY(test::child<Document>(w)->session()->decisions().isEmpty());
            test::writeFile(side + QStringLiteral(".copy"), test::readFile(side));
            answer(offer, QMessageBox::Discard);
            QVERIFY(!QFileInfo::exists(side));
            QVERIFY(test::child<Document>(w)->session()->decisions().isEmpty());
            QVERIFY(!w.isWindowModified());
        }
        QVERIFY(QFile::rename(side + QStringLiteral(".copy"), side));
        // Recover: the decision is back, as modified state.
        MainWindow w;
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(ws);
        QMessageBox *offer = box(w, QStringLiteral("recoverAutosaveBox"));
        QVERIFY(offer);
        answer(offer, QMessageBox::Yes); // Recover, before the stages finish
        QVERIFY(finished.wait(60000));
        QCOMPARE(test::child<Document>(w)->session()->decisions().size(), 1);
        bool described = false;
        for (const AtomicNode &n : test::child<Document>(w)->atomicNodes().nodes)
            described |= n.description == value;
        QVERIFY(described);
        QVERIFY(w.isWindowModified());
        QVERIFY(test::child<ProjectController>(w)->save());
        QCOMPARE(storedDecisions(ProjectFile::defaultPath(ws)), 1);
        QVERIFY(!QFileInfo::exists(side));
        QVERIFY(!QFileInfo::exists(ProjectFile::autosavePath(ProjectFile::defaultPath(ws))));
    }

    void aBrokenProjectIsExplainedAndKept_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("reason");
        QTest::newRow("not json") << QByteArray("{ \"version\": 1, ") << QStringLiteral("JSON");
        QTest::newRow("newer") << QByteArray("{\"version\": 99, \"future\": true}")
                               << QStringLiteral("newer rosarch");
    }

    void aBrokenProjectIsExplainedAndKept()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString ws = copyExampleWorkspace(dir);
        const QString file = ProjectFile::defaultPath(ws);
        test::writeFile(file, content);
        MainWindow w;
        w.show();
        QVERIFY(openAndRun(w, ws));
        QMessageBox *error = box(w, QStringLiteral("projectErrorBox"));
        QVERIFY(error);
        QVERIFY2(error->text().contains(file), qPrintable(error->text()));
        QVERIFY2(error->text().contains(reason), qPrintable(error->text()));
        QVERIFY2(error->text().contains(QStringLiteral("kept as")), qPrintable(error->text()));
        QVERIFY(test::child<LogView>(w)->logEdit()->toPlainText().contains(file));
        const QStringList kept =
            QDir(ws).entryList({QStringLiteral("rosarch.project.json.unreadable-*")});
        QCOMPARE(kept.size(), 1);
        QCOMPARE(test::readFile(QDir(ws).filePath(kept.first())), content);
        QCOMPARE(test::readFile(file), content); // not written over by opening
        answer(error, QMessageBox::Ok);

        // Save writes a good project; the unreadable one stays where it was kept.
        decideOne(w);
        QVERIFY(test::child<ProjectController>(w)->save());
        QCOMPARE(storedDecisions(file), 1);
        QCOMPARE(test::readFile(QDir(ws).filePath(kept.first())), content);

        // Open Project on a broken file says so and opens nothing.
        const QString broken = dir.filePath(QStringLiteral("broken.project.json"));
        test::writeFile(broken, content);
        QVERIFY(!test::child<ProjectController>(w)->openProject(broken));
        error = box(w, QStringLiteral("projectErrorBox"));
        QVERIFY(error);
        QVERIFY(error->text().contains(broken));
        QCOMPARE(test::child<Document>(w)->session()->projectPath(), file);
        QCOMPARE(test::readFile(broken), content);
        answer(error, QMessageBox::Ok);
    }

    void newProjectStartsEmptyAndSaveAsks()
    {
        QTemporaryDir dir;
        const QString ws = copyExampleWorkspace(dir);
        MainWindow w;
        QVERIFY(openAndRun(w, ws));
        decideOne(w);
        QVERIFY(test::child<ProjectController>(w)->save());
        test::child<ProjectController>(w)->newAction()->trigger();
        QVERIFY(test::child<Document>(w)->session()->isUntitled());
        QVERIFY(test::child<Document>(w)->session()->decisions().isEmpty());
        QVERIFY(w.windowTitle().contains(QStringLiteral("new project")));
        const QString chosen = dir.filePath(QStringLiteral("fresh.project.json"));
        int asked = 0;
        test::child<ProjectController>(w)->setFileChooser(
            [&](const QString &, const QString &start, bool forSaving) {
                ++asked;
                return forSaving && start == ProjectFile::defaultPath(ws) ? chosen : QString();
            });
        test::child<ProjectController>(w)->saveAction()->trigger();
        QCOMPARE(asked, 1);
        QCOMPARE(storedDecisions(chosen), 0);
        QCOMPARE(storedDecisions(ProjectFile::defaultPath(ws)), 1); // the old one untouched
        QCOMPARE(test::child<Document>(w)->session()->projectPath(), chosen);
    }
};

QTEST_MAIN(TestProjectFile)
#include "tst_projectfile.moc"
