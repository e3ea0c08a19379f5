// The Suggestions panel and its item model under offscreen: the model passes
// QAbstractItemModelTester through runs and decisions, pending suggestions appear with their
// columns and counts, selection previews, keyboard accept / reject, filters, accept all, the
// LLM settings dialog (the key shown as present, never its value), and screenshots.
#include "app/suggestioncontroller.h"
#include "document/document.h"
#include "project/project.h"
#include "suggestions/suggestionengine.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/llmsettingsdialog.h"
#include "widgets/suggestionfiltermodel.h"
#include "widgets/suggestionmodel.h"
#include "widgets/suggestionpanel.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;

namespace {

const QString kSecret = QStringLiteral("sk-panel-secret-9876543210");

QString exampleWorkspace()
{
    return QFileInfo(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                         .filePath(QStringLiteral("resources/example_ws")))
        .canonicalFilePath();
}

QStringList row(const QAbstractItemModel &m, int r)
{
    QStringList out;
    for (int c = 0; c < m.columnCount(); ++c)
        out << m.index(r, c).data().toString();
    return out;
}

} // namespace

class TestSuggestionPanel : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_home;
    Recovery m_recovery;
    SuggestionReport m_report;

    /// A Document with the deterministic suggestions on example_ws plus one LLM suggestion.
    void load(Document &doc)
    {
        QFile::remove(ProjectFile::locate(exampleWorkspace()));
        doc.setRecovery(m_recovery);
        doc.session()->setSuggestions(m_report);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_home.isValid());
        qputenv("XDG_DATA_HOME", m_home.filePath(QStringLiteral("data")).toUtf8());
        qputenv("XDG_CONFIG_HOME", m_home.filePath(QStringLiteral("config")).toUtf8());
        qunsetenv("ROSARCH_LLM_ENDPOINT");
        m_recovery = recoverWorkspace(exampleWorkspace());
        m_recovery.nodes.workspaceRoot = exampleWorkspace();
        m_report = SuggestionEngine(exampleWorkspace(), m_recovery, {}).run();
        QCOMPARE(m_report.suggestions.size(), 9);
        // What an LLM reply looks like once checked: another proposal for the same node.
        Suggestion llm = m_report.suggestions.first();
        llm.id = QStringLiteral("s10");
        llm.value = QStringLiteral("Watches the battery charge and warns before it runs low.");
        llm.rationale = QStringLiteral("The module docstring and the publisher of battery_state.");
        llm.origin = {QStringLiteral("llm:qwen2.5-coder"), QStringLiteral("describe_nodes"),
                      QDateTime(QDate(2025, 1, 15), QTime(9, 30), Qt::UTC)};
        m_report.suggestions.append(llm);
    }

    void modelPassesTheTester()
    {
        Document doc;
        SuggestionModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        SuggestionFilterModel proxy;
        proxy.setSourceModel(&model);
        QAbstractItemModelTester proxyTester(
            &proxy, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.rowCount(), 0);
        load(doc);
        QCOMPARE(model.rowCount(), 10);
        QCOMPARE(model.columnCount(), 5);
        proxy.setStatusFilter(Suggestion::Status::Pending);
        QCOMPARE(proxy.rowCount(), 10);
        QVERIFY(doc.session()->acceptSuggestion(QStringLiteral("s1")));
        QCOMPARE(proxy.rowCount(), 9); // left the pending view at once
        QVERIFY(doc.session()->rejectSuggestion(QStringLiteral("s2")));
        doc.session()->acceptAllSuggestions(Suggestion::Kind::NodeDescription);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(proxy.rowCount(), 9);
        proxy.setKindFilter(Suggestion::Kind::SubsystemGrouping);
        QCOMPARE(proxy.rowCount(), 1);
        doc.session()->setSuggestions(m_report); // a new run
        const Suggestion::Status decided = doc.session()->suggestion(QStringLiteral("s2"))->status;
        doc.setRecovery(m_recovery); // the stages again: the suggestions stay, by key
        QCOMPARE(model.rowCount(), 10);
        QCOMPARE(doc.session()->suggestion(QStringLiteral("s2"))->status, decided);
        Recovery other = m_recovery;
        other.nodes.workspaceRoot += QStringLiteral("_elsewhere");
        doc.setRecovery(other); // another workspace: they go
        QCOMPARE(model.rowCount(), 0);
    }

    void pendingSuggestionsAppearWithTheirColumns()
    {
        Document doc;
        SuggestionModel model(&doc);
        SuggestionPanel panel;
        panel.setModel(&model);
        QCOMPARE(panel.countsLabel()->text(), QStringLiteral("No suggestions"));
        load(doc);
        QCOMPARE(panel.view()->model()->rowCount(), 10);
        QCOMPARE(panel.countsLabel()->text(),
                 QStringLiteral("10 pending · 0 accepted · 0 rejected"));
        QCOMPARE(row(model, 0),
                 (QStringList{
                     QStringLiteral("Description"), QStringLiteral("BatteryMonitor"),
                     // a docstring: the repository's words, shown as a quotation
                     QStringLiteral("“Publishes the battery state and a diagnostic when the "
                                    "charge is low.” (quoted from the code)"),
                     QStringLiteral("deterministic"), QStringLiteral("battery_monitor.py:10")}));
        const int group = 8;
        QCOMPARE(model.index(group, SuggestionModel::KindColumn).data().toString(),
                 QStringLiteral("Grouping"));
        QCOMPARE(model.index(group, SuggestionModel::TargetColumn).data().toString(),
                 QStringLiteral("mission"));
        QVERIFY(model.index(group, SuggestionModel::EvidenceColumn)
                    .data()
                    .toString()
                    .contains(QStringLiteral("  +")));
        QCOMPARE(model.index(group, SuggestionModel::ProposalColumn)
                     .data()
                     .toString()
                     .count(QStringLiteral(", ")),
                 3);
        QCOMPARE(row(model, 9).at(SuggestionModel::OriginColumn),
                 QStringLiteral("llm:qwen2.5-coder"));
        QCOMPARE(model.index(0, 0).data(SuggestionModel::IdRole).toString(), QStringLiteral("s1"));
        QVERIFY(!model.index(0, 0).data(Qt::DecorationRole).value<QIcon>().isNull());
        QVERIFY(!model.index(0, 0).data(Qt::ForegroundRole).isValid()); // pending: normal text
    }

    void selectingPreviewsTheChange()
    {
        Document doc;
        SuggestionModel model(&doc);
        SuggestionPanel panel;
        panel.setModel(&model);
        SuggestionController controller(&doc, &panel);
        QList<Evidence> evidence;
        QStringList classes;
        QList<QStringList> instances;
        controller.setPreviews({[&](const Evidence &e) { evidence << e; },
                                [&](const QString &id) { classes << id; },
                                [&](const QStringList &ids) { instances << ids; }});
        load(doc);
        panel.selectSuggestion(QStringLiteral("s1"));
        QCOMPARE(panel.currentSuggestionId(), QStringLiteral("s1"));
        QCOMPARE(classes, QStringList{QStringLiteral("arc_1")});
        QCOMPARE(evidence.size(), 1);
        QCOMPARE(evidence[0].file,
                 QStringLiteral("src/robot_mission/robot_mission/battery_monitor.py"));
        QCOMPARE(evidence[0].line, 10);
        const QString details = panel.details()->toPlainText();
        QVERIFY2(details.contains(QStringLiteral("battery_monitor.py:10")), qPrintable(details));
        QVERIFY(details.contains(QStringLiteral("Origin: deterministic")));
        QVERIFY2(details.contains(QStringLiteral("quoted from the code")), qPrintable(details));

        panel.selectSuggestion(QStringLiteral("s9"));
        QCOMPARE(instances, (QList<QStringList>{{QStringLiteral("n2"), QStringLiteral("n4"),
                                                 QStringLiteral("n6"), QStringLiteral("n7")}}));
        QCOMPARE(evidence.size(), 2);
        QVERIFY(panel.details()->toPlainText().contains(
            doc.session()->suggestion(QStringLiteral("s9"))->rationale));

        // A citation clicked in the details shows those lines.
        const Suggestion *g = doc.session()->suggestion(QStringLiteral("s9"));
        QVERIFY(g->evidence.size() > 1);
        QMetaObject::invokeMethod(panel.details(), "anchorClicked",
                                  Q_ARG(QUrl, QUrl(QStringLiteral("evidence:1"))));
        QCOMPARE(evidence.last(), g->evidence[1].evidence);
    }

    void keyboardAcceptsAndRejects()
    {
        Document doc;
        SuggestionModel model(&doc);
        SuggestionPanel panel;
        panel.setModel(&model);
        SuggestionController controller(&doc, &panel);
        load(doc);
        panel.resize(900, 400);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.selectSuggestion(QStringLiteral("s1"));
        panel.view()->setFocus();

        QTest::keyClick(panel.view(), Qt::Key_Return);
        QCOMPARE(doc.session()->suggestion(QStringLiteral("s1"))->status,
                 Suggestion::Status::Accepted);
        QCOMPARE(doc.atomicNodes().node(QStringLiteral("arc_1"))->description,
                 doc.session()->suggestion(QStringLiteral("s1"))->value);
        QCOMPARE(panel.currentSuggestionId(), QStringLiteral("s2")); // on to the next open one
        QTest::keyClick(panel.view(), Qt::Key_Delete);
        QCOMPARE(doc.session()->suggestion(QStringLiteral("s2"))->status,
                 Suggestion::Status::Rejected);
        QCOMPARE(panel.currentSuggestionId(), QStringLiteral("s3"));
        QCOMPARE(panel.countsLabel()->text(),
                 QStringLiteral("8 pending · 1 accepted · 1 rejected"));
        QCOMPARE(doc.undoStack()->count(), 2);

        // Decided rows are greyed; the rejected proposal is struck out.
        const QBrush grey = QApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        QCOMPARE(model.index(0, 1).data(Qt::ForegroundRole).value<QBrush>(), grey);
        QVERIFY(model.index(1, SuggestionModel::ProposalColumn)
                    .data(Qt::FontRole)
                    .value<QFont>()
                    .strikeOut());
        QVERIFY(!model.index(0, SuggestionModel::ProposalColumn).data(Qt::FontRole).isValid());

        // The buttons follow the current row.
        panel.selectSuggestion(QStringLiteral("s1"));
        QVERIFY(!panel.acceptAction()->isEnabled());
        QVERIFY(panel.rejectAction()->isEnabled());
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(panel.countsLabel()->text(),
                 QStringLiteral("10 pending · 0 accepted · 0 rejected"));
        QVERIFY(panel.acceptAction()->isEnabled());
    }

    void filtersAndAcceptAll()
    {
        Document doc;
        SuggestionModel model(&doc);
        SuggestionPanel panel;
        panel.setModel(&model);
        SuggestionController controller(&doc, &panel);
        load(doc);
        panel.kindFilter()->setCurrentIndex(
            panel.kindFilter()->findData(int(Suggestion::Kind::NodeDescription)));
        QCOMPARE(panel.view()->model()->rowCount(), 9);
        QCOMPARE(panel.acceptAllAction()->text(), QStringLiteral("Accept All Descriptions (9)"));
        QVERIFY(panel.acceptAllAction()->isEnabled());
        panel.acceptAllAction()->trigger();
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(model.count(Suggestion::Status::Accepted), 9);
        QVERIFY(!panel.acceptAllAction()->isEnabled());
        panel.statusFilter()->setCurrentIndex(
            panel.statusFilter()->findData(int(Suggestion::Status::Pending)));
        QCOMPARE(panel.view()->model()->rowCount(), 0);
        panel.kindFilter()->setCurrentIndex(0);
        QCOMPARE(panel.view()->model()->rowCount(), 1); // the grouping
        doc.undoStack()->undo();
        QCOMPARE(panel.view()->model()->rowCount(), 10);
        // Selecting a hidden suggestion clears the filter that hides it.
        QVERIFY(doc.session()->rejectSuggestion(QStringLiteral("s4")));
        panel.selectSuggestion(QStringLiteral("s4"));
        QCOMPARE(panel.currentSuggestionId(), QStringLiteral("s4"));
        QCOMPARE(panel.statusFilter()->currentIndex(), 0);
    }

    void settingsDialogShowsWhetherAKeyIsSetButNeverTheKey()
    {
        qputenv("ROSARCH_LLM_API_KEY", kSecret.toUtf8());
        LlmSettingsDialog dialog;
        LlmSettings in;
        in.endpoint = QStringLiteral("http://localhost:11434/v1");
        in.model = QStringLiteral("qwen2.5-coder");
        in.temperature = 0.2;
        in.connectTimeoutMs = 5000;
        in.requestTimeoutMs = 90000;
        in.maxRetries = 7; // not shown: kept as given
        dialog.setSettings(in, true);
        QCOMPARE(dialog.settings().endpoint, in.endpoint);
        QCOMPARE(dialog.settings().model, in.model);
        QCOMPARE(dialog.settings().temperature, 0.2);
        QCOMPARE(dialog.settings().connectTimeoutMs, 5000);
        QCOMPARE(dialog.settings().requestTimeoutMs, 90000);
        QCOMPARE(dialog.settings().maxRetries, 7);
        QVERIFY(dialog.useLlm());
        QVERIFY(dialog.keyLabel()->text().contains(QStringLiteral("ROSARCH_LLM_API_KEY")));
        for (const QLabel *label : dialog.findChildren<QLabel *>())
            QVERIFY(!label->text().contains(kSecret));
        for (const QLineEdit *edit : dialog.findChildren<QLineEdit *>())
            QVERIFY(!edit->text().contains(kSecret));
        QPushButton *ok = dialog.buttons()->button(QDialogButtonBox::Ok);
        QVERIFY(ok->isEnabled());
        test::saveScreenshot(dialog, QStringLiteral("llm-settings.png"));
        dialog.endpointEdit()->setText(QStringLiteral("localhost:11434"));
        QVERIFY(!ok->isEnabled());
        dialog.useCheck()->setChecked(false); // off: nothing to check, the fields wait
        QVERIFY(ok->isEnabled());
        QVERIFY(!dialog.endpointEdit()->isEnabled());
        qunsetenv("ROSARCH_LLM_API_KEY");
        qunsetenv("OPENAI_API_KEY");
        QVERIFY(LlmSettingsDialog::apiKeyStatus().startsWith(QStringLiteral("Not set")));
    }

    void screenshots()
    {
        Document doc;
        SuggestionModel model(&doc);
        SuggestionPanel panel;
        panel.setModel(&model);
        panel.setLlmDescription(QStringLiteral("LLM off"));
        panel.resize(1100, 460);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        test::saveScreenshot(panel, QStringLiteral("suggestions-empty.png"));
        load(doc);
        QVERIFY(doc.session()->acceptSuggestion(QStringLiteral("s2")));
        QVERIFY(doc.session()->rejectSuggestion(QStringLiteral("s3")));
        panel.setProgressText(QStringLiteral("Done: from the code"));
        panel.selectSuggestion(QStringLiteral("s9"));
        QVERIFY(panel.details()->toPlainText().contains(QStringLiteral("mission")));
        test::saveScreenshot(panel, QStringLiteral("suggestions-review.png"));
        panel.selectSuggestion(QStringLiteral("s10"));
        panel.setRunning(true);
        panel.setProgressText(QStringLiteral("describe_nodes: 1,234 characters received"));
        test::saveScreenshot(panel, QStringLiteral("suggestions-running.png"));
        QVERIFY(!panel.runAction()->isEnabled());
        QVERIFY(panel.cancelAction()->isEnabled());
    }
};

QTEST_MAIN(TestSuggestionPanel)
#include "tst_suggestionpanel.moc"
