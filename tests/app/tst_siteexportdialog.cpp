// File → Export Architecture Site… in the main window on the GUI fixture: the dialog offers
// what `rosarch site` offers (folder, title, source-URL pattern, commit), refuses a pattern
// without {path} with a sentence that says so, writes the site off the UI thread, and
// remembers its fields for the workspace.
#include "app/appsettings.h"
#include "app/commands/siteexport.h"
#include "app/mainwindow.h"
#include "app/siteexportdialog.h"
#include "app/stagerunner.h"
#include "support/guifixture.h"
#include "support/testsupport.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::gui;

namespace {

/// The action as a person finds it: in the File menu of the menu bar.
QAction *exportSiteAction(MainWindow &w)
{
    for (QAction *menuAction : w.menuBar()->actions()) {
        QMenu *menu = menuAction->menu();
        if (!menu || menu->title() != QLatin1String("&File"))
            continue;
        for (QAction *a : menu->actions())
            if (a->objectName() == QLatin1String("exportSiteAction"))
                return a;
    }
    return nullptr;
}

/// What the dialog showed, read while it is open.
struct Seen
{
    bool found = false;
    QString problem;
    bool exportEnabled = false;
    QString folder;
    QString title;
    QString sourceUrl;
    QString commit;
};

QLineEdit *field(QDialog *dialog, const char *name)
{
    return dialog->findChild<QLineEdit *>(QLatin1String(name));
}

QString fileText(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

} // namespace

class TestSiteExportDialog : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QVERIFY(m_dir.isValid());
        QVERIFY(QFileInfo(fixture()).isDir());
    }

    void menuActionWritesTheSite()
    {
        MainWindow w;
        w.resize(1200, 800);
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(fixture());
        QVERIFY(finished.wait(60000));
        QAction *action = exportSiteAction(w);
        QVERIFY2(action, "no Export Architecture Site action in the File menu");
        QVERIFY(action->isEnabled());

        const QString folder = m_dir.filePath(QStringLiteral("site"));
        Seen seen;
        QTimer::singleShot(0, this, [&] {
            auto *dialog = qobject_cast<SiteExportDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            seen.found = true;
            auto *problem = dialog->findChild<QLabel *>(QStringLiteral("siteProblem"));
            QPushButton *ok = dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
            field(dialog, "siteFolder")->setText(folder);
            field(dialog, "siteTitle")->setText(QStringLiteral("Talkers"));
            // A pattern without {path} cannot link a file: refused with what to write.
            QTest::keyClicks(field(dialog, "siteSourceUrl"),
                             QStringLiteral("https://example.org/robot/blob/{commit}/"));
            seen.problem = problem->isVisible() ? problem->text() : QString();
            seen.exportEnabled = ok->isEnabled();
            QTest::keyClicks(field(dialog, "siteSourceUrl"), QStringLiteral("{path}#L{line}"));
            field(dialog, "siteCommit")->setText(QStringLiteral("v1.2"));
            if (ok->isEnabled())
                QTest::mouseClick(ok, Qt::LeftButton);
            else
                dialog->reject();
        });
        action->trigger();
        QVERIFY2(seen.found, "the action opened no SiteExportDialog");
        QVERIFY2(seen.problem.contains(QLatin1String("{path}")), qPrintable(seen.problem));
        QVERIFY(!seen.exportEnabled);

        // The site is written by a worker; its job object goes when it reported.
        QPointer<SiteExport> job = w.findChild<SiteExport *>();
        QVERIFY2(job, "no export job started");
        QTRY_VERIFY_WITH_TIMEOUT(job.isNull(), 120000);

        const QString index = fileText(QDir(folder).filePath(QStringLiteral("index.html")));
        QVERIFY2(!index.isEmpty(), "no index.html written");
        QVERIFY2(index.contains(QLatin1String("<title>Talkers</title>")), "not the given title");
        const QString talker =
            fileText(QDir(folder).filePath(QStringLiteral("nodes/py_talker.Talker.html")));
        QVERIFY2(!talker.isEmpty(), "no node page for the Talker");
        // Its source links follow the pattern, with the given commit and the file's path.
        static const QRegularExpression link(
            QStringLiteral("href=\"https://example\\.org/robot/blob/v1\\.2/([^\"#]*)#L(\\d+)\""));
        const QRegularExpressionMatch m = link.match(talker);
        QVERIFY2(m.hasMatch(), "no source link by the pattern on the Talker's page");
        QVERIFY2(talker.contains(QLatin1String("src/py_talker/py_talker/talker.py#L")),
                 qPrintable(m.captured(0)));
        QVERIFY(m.captured(2).toInt() > 0);
        QVERIFY(!talker.contains(QLatin1String("href=\"../../")));
    }

    void fieldsAreRememberedPerWorkspace()
    {
        // The fields the previous test exported with come back for the same workspace.
        const QVariantMap stored = AppSettings().siteExport(fixture());
        QCOMPARE(stored.value(QStringLiteral("title")).toString(), QStringLiteral("Talkers"));
        SiteExportDialog dialog(fixture());
        QCOMPARE(field(&dialog, "siteTitle")->text(), QStringLiteral("Talkers"));
        QCOMPARE(field(&dialog, "siteSourceUrl")->text(),
                 QStringLiteral("https://example.org/robot/blob/{commit}/{path}#L{line}"));
        QCOMPARE(field(&dialog, "siteCommit")->text(), QStringLiteral("v1.2"));
        QCOMPARE(QDir::fromNativeSeparators(field(&dialog, "siteFolder")->text()),
                 m_dir.filePath(QStringLiteral("site")));
        // Another workspace starts from the defaults.
        SiteExportDialog other(m_dir.path());
        QVERIFY(field(&other, "siteTitle")->text().isEmpty());
        QVERIFY(field(&other, "siteSourceUrl")->text().isEmpty());
    }

    void commitIsNeededOutsideGit()
    {
        // A temporary folder is in no repository: {commit} has nothing to come from.
        SiteExportDialog dialog(m_dir.path());
        field(&dialog, "siteFolder")->setText(m_dir.filePath(QStringLiteral("elsewhere")));
        field(&dialog, "siteSourceUrl")
            ->setText(QStringLiteral("https://example.org/{commit}/{path}#L{line}"));
        QVERIFY(dialog.problem().isEmpty());
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
        const QString said = dialog.findChild<QLabel *>(QStringLiteral("siteProblem"))->text();
        QVERIFY2(said.contains(QLatin1String("not in a git repository")), qPrintable(said));
        // Given a commit, the same pattern is accepted and links to it.
        field(&dialog, "siteCommit")->setText(QStringLiteral("main"));
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(dialog.options().commit, QStringLiteral("main"));
        QCOMPARE(dialog.options().title, QDir(m_dir.path()).dirName());
    }

    void emptyFolderIsRefused()
    {
        SiteExportDialog dialog(fixture());
        field(&dialog, "siteFolder")->clear();
        QVERIFY(dialog.problem().contains(QLatin1String("folder")));
        QVERIFY(!dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->isEnabled());
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
    }
};

QTEST_MAIN(TestSiteExportDialog)
#include "tst_siteexportdialog.moc"
