// The GUI's comparisons: File › Compare Architecture with a git revision and with an
// artifact folder (the Architecture changes dock, coloured by kind of change), and File ›
// Export and Render with PlantUML (SVGs by the real PlantUML, in the background).
#include "app/appsettings.h"
#include "app/comparecontroller.h"
#include "app/mainwindow.h"
#include "app/rendercontroller.h"
#include "app/stagerunner.h"
#include "diff/gitrevision.h"
#include "document/document.h"
#include "support/chatrepo.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/architecturediffview.h"

#include <QDockWidget>
#include <QMessageBox>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTreeWidget>
#include <QtTest>

using namespace rosarch;

namespace {

/// Every change row of the view as "mark element: what", group by group.
QStringList rows(const QTreeWidget *tree, QList<QColor> *colours = nullptr)
{
    QStringList out;
    for (int g = 0; g < tree->topLevelItemCount(); ++g) {
        const QTreeWidgetItem *group = tree->topLevelItem(g);
        for (int i = 0; i < group->childCount(); ++i) {
            const QTreeWidgetItem *item = group->child(i);
            out << QStringLiteral("%1 %2: %3").arg(item->text(0), item->text(1), item->text(2));
            if (colours)
                *colours << item->foreground(0).color();
        }
    }
    return out;
}

void openAndRun(MainWindow &w, const QString &workspace)
{
    QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
    w.openWorkspace(workspace);
    QVERIFY(finished.wait(60000));
}

} // namespace

class TestCompareAndRender : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_repo.isValid());
        QVERIFY(test::chat::createRepository(m_repo.path()));
    }

    void compareWithRevision()
    {
        MainWindow w;
        w.resize(1400, 900);
        w.show();
        openAndRun(w, m_repo.path());
        QSignalSpy done(test::child<CompareController>(w), &CompareController::finished);
        test::child<CompareController>(w)->compareWithRevision(QStringLiteral("HEAD~1"));
        QVERIFY(done.wait(60000));
        QVERIFY(w.findChild<QDockWidget *>(QStringLiteral("changesDock"))->isVisible());
        QList<QColor> colours;
        const QStringList shown = rows(test::child<ArchitectureDiffView>(w)->tree(), &colours);
        QCOMPARE(shown.size(), 6);
        QVERIFY(shown.contains(QStringLiteral("~ renamed topic: /chatter → /chat")));
        QVERIFY(shown.contains(
            QStringLiteral("+ added port: subscriber clock (rosgraph_msgs/msg/Clock)")));
        QVERIFY(shown.contains(
            QStringLiteral("+ added connection: /hearer subscribes to topic /clock")));
        // Added, removed and changed rows differ in colour, not only in the mark.
        const int added = int(shown.indexOf(
            QStringLiteral("+ added port: subscriber clock (rosgraph_msgs/msg/Clock)")));
        const int renamed = int(shown.indexOf(QStringLiteral("~ renamed topic: /chatter → /chat")));
        QVERIFY(colours.at(added) != colours.at(renamed));
        QVERIFY(test::child<ArchitectureDiffView>(w)->summary().startsWith(
            QLatin1String("6 changes from revision HEAD~1 to the current model: 3 added")));
        test::saveScreenshot(w, QStringLiteral("compare_revision.png"));

        // The same revision against itself: nothing changed, and the view says so.
        test::child<CompareController>(w)->compareWithRevision(QStringLiteral("HEAD"));
        QVERIFY(done.wait(60000));
        QVERIFY(rows(test::child<ArchitectureDiffView>(w)->tree()).isEmpty());
        QVERIFY(test::child<ArchitectureDiffView>(w)->summary().startsWith(
            QLatin1String("No architecture changes")));

        // A revision that does not exist: git's message, no changes, no crash.
        test::child<CompareController>(w)->compareWithRevision(QStringLiteral("no-such-revision"));
        QVERIFY(done.wait(60000));
        QVERIFY2(test::child<ArchitectureDiffView>(w)->summary().contains(
                     QLatin1String("Cannot compare")),
                 qPrintable(test::child<ArchitectureDiffView>(w)->summary()));
    }

    void compareWithArtifactFolder()
    {
        // An export of the current model compared with the model: no change.
        QTemporaryDir out;
        MainWindow w;
        openAndRun(w, m_repo.path());
        QSignalSpy rendered(test::child<RenderController>(w), &RenderController::rendered);
        AppSettings().setPlantUmlJar(QStringLiteral(ROSARCH_PLANTUML_JAR));
        QVERIFY(test::child<RenderController>(w)->exportAndRender(out.path()));
        QVERIFY(test::child<RenderController>(w)->isRendering());
        QVERIFY(rendered.wait(120000));
        QVERIFY2(rendered.first().at(0).toBool(), qPrintable(rendered.first().at(1).toString()));
        const QStringList pictures = rendered.first().at(2).toStringList();
        QCOMPARE(pictures.size(), 3); // Speaker, Hearer, chat
        for (const QString &svg : pictures)
            QVERIFY2(test::readFile(svg).contains("<svg"), qPrintable(svg));
        QVERIFY(test::readFile(out.filePath(QStringLiteral("ccd/chat.svg"))).contains("hearer"));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("mermaid/chat.md"))));

        QSignalSpy done(test::child<CompareController>(w), &CompareController::finished);
        test::child<CompareController>(w)->compareWithFolder(out.path());
        QVERIFY(done.wait(60000));
        QVERIFY(test::child<CompareController>(w)->changes().isEmpty());
        // A folder that is a workspace is recovered and compared: the older revision.
        QTemporaryDir old;
        QString error;
        QVERIFY(GitRevision::checkout(m_repo.path(), QStringLiteral("HEAD~1"), old.path(), &error));
        test::child<CompareController>(w)->compareWithFolder(old.path());
        QVERIFY(done.wait(60000));
        QCOMPARE(test::child<CompareController>(w)->changes().size(), 6);
    }

    void aChosenJarThatIsGoneIsSaidNotReplaced()
    {
        MainWindow w;
        openAndRun(w, m_repo.path());
        AppSettings().setPlantUmlJar(QStringLiteral("/no/such/plantuml.jar"));
        QTemporaryDir out;
        QSignalSpy rendered(test::child<RenderController>(w), &RenderController::rendered);
        QVERIFY(!test::child<RenderController>(w)->exportAndRender(out.path()));
        QVERIFY(!test::child<RenderController>(w)->isRendering());
        QVERIFY(!QFile::exists(out.filePath(QStringLiteral("atomic_nodes.json"))));
        QMessageBox *box = w.findChild<QMessageBox *>();
        QVERIFY(box);
        QVERIFY2(box->text().contains(QLatin1String("/no/such/plantuml.jar")),
                 qPrintable(box->text()));
        QCOMPARE(rendered.size(), 0);
        AppSettings().setPlantUmlJar(QString());
    }

private:
    QTemporaryDir m_repo;
};

QTEST_MAIN(TestCompareAndRender)
#include "tst_compareandrender.moc"
