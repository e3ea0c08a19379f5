// The Log's findings table: filter, sort, group and count; hide and accept go to the
// project by key, undo, survive a re-run and a save and reopen; the panel's filter bar and
// next / previous follow what is shown.
#include "document/document.h"
#include "pipeline/recovery.h"
#include "support/acceptedwait.h"
#include "support/testsupport.h"
#include "widgets/diagnosticdetail.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/icons.h"
#include "widgets/logview.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QStandardPaths>
#include <QToolButton>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;

namespace {

Diagnostic finding(Diagnostic::Severity severity, const char *code, const char *file, int line,
                   const char *message, QStringList contexts = {})
{
    Diagnostic d;
    d.severity = severity;
    d.code = QString::fromLatin1(code);
    d.evidence.file = QString::fromLatin1(file);
    d.evidence.line = line;
    d.message = QString::fromLatin1(message);
    d.contexts = std::move(contexts);
    return d;
}

/// Two packages, five findings of three kinds and three severities.
AtomicNodeList sample()
{
    AtomicNodeList list;
    RosPackage alpha;
    alpha.name = QStringLiteral("alpha");
    alpha.path = QStringLiteral("src/alpha");
    RosPackage beta;
    beta.name = QStringLiteral("beta");
    beta.path = QStringLiteral("src/beta");
    list.packages = {alpha, beta};
    using S = Diagnostic::Severity;
    list.diagnostics = {
        finding(S::Warning, "syntax-error", "src/alpha/src/a.cpp", 12, "Could not parse a call."),
        finding(S::Error, "parse-failed", "src/beta/src/b.cpp", 3, "The parser gave up."),
        finding(S::Info, "topic-unheard", "src/beta/beta/talker.py", 40, "/talker publishes /chat.",
                {QStringLiteral("a.launch.py"), QStringLiteral("b.launch.py")}),
        finding(S::Warning, "syntax-error", "src/beta/src/c.cpp", 7, "Unbalanced braces."),
        finding(S::Info, "binary-file", "README.bin", 0, "A file that looks binary."),
    };
    return list;
}

QStringList column(const QAbstractItemModel &model, int column, const QModelIndex &parent = {})
{
    QStringList out;
    for (int row = 0; row < model.rowCount(parent); ++row)
        out << model.index(row, column, parent).data().toString();
    return out;
}

QStringList messages(const QAbstractItemModel &model)
{
    return column(model, DiagnosticModel::MessageColumn);
}

} // namespace

class TestDiagnosticModel : public QObject
{
    Q_OBJECT
    QTemporaryDir m_ws;
    Recovery m_recovered;

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                 .filePath(QStringLiteral("projects")))
            .removeRecursively();
        test::copyTree(test::dataDir(QStringLiteral("check_roots/ws")), m_ws.path());
        m_recovered = recoverWorkspace(m_ws.path());
        QVERIFY(!m_recovered.architecture.diagnostics.isEmpty());
    }

    void init()
    {
        QFile::remove(QDir(m_ws.path()).filePath(QStringLiteral("rosarch.project.json")));
        const QString project = ProjectFile::locate(m_ws.path());
        QFile::remove(project);
        QFile::remove(ProjectFile::autosavePath(project));
    }

    void showsEveryColumn()
    {
        Document doc;
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.rowCount(), 0);
        doc.setAtomicNodes(sample());
        QCOMPARE(model.total(), 5);
        QCOMPARE(model.shown(), 5);
        QCOMPARE(column(model, DiagnosticModel::SeverityColumn),
                 (QStringList{"Warning", "Error", "Info", "Warning", "Info"}));
        QCOMPARE(model.index(0, DiagnosticModel::KindColumn).data().toString(),
                 QStringLiteral("syntax-error — Syntax error"));
        QCOMPARE(column(model, DiagnosticModel::PackageColumn),
                 (QStringList{"alpha", "beta", "beta", "beta", ""}));
        QCOMPARE(model.index(1, DiagnosticModel::FileColumn).data().toString(),
                 QStringLiteral("src/beta/src/b.cpp:3"));
        QCOMPARE(column(model, DiagnosticModel::ContextsColumn),
                 (QStringList{"", "", "2", "", ""}));
        QVERIFY(model.index(2, 0)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("2 system")));
    }

    void filtersAndCounts()
    {
        Document doc;
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setAtomicNodes(sample());
        QCOMPARE(model.codeCounts(), (QMap<QString, int>{{QStringLiteral("binary-file"), 1},
                                                         {QStringLiteral("parse-failed"), 1},
                                                         {QStringLiteral("syntax-error"), 2},
                                                         {QStringLiteral("topic-unheard"), 1}}));
        QCOMPARE(model.packageCounts(),
                 (QMap<QString, int>{
                     {QString(), 1}, {QStringLiteral("alpha"), 1}, {QStringLiteral("beta"), 3}}));
        QCOMPARE(model.severityCount(Diagnostic::Severity::Info), 2);

        DiagnosticModel::Filter f;
        f.infos = false;
        model.setFilter(f);
        QCOMPARE(messages(model), (QStringList{"Could not parse a call.", "The parser gave up.",
                                               "Unbalanced braces."}));
        f = {};
        f.code = QStringLiteral("syntax-error");
        f.package = QStringLiteral("beta");
        model.setFilter(f);
        QCOMPARE(messages(model), QStringList{"Unbalanced braces."});
        QCOMPARE(model.shown(), 1);
        QCOMPARE(model.total(), 5);
        f = {};
        f.text = QStringLiteral("TALKER"); // any case, in the file too
        model.setFilter(f);
        QCOMPARE(messages(model), QStringList{"/talker publishes /chat."});
        f.text = QStringLiteral("Syntax error"); // the kind's title
        model.setFilter(f);
        QCOMPARE(model.shown(), 2);

        // The combos count what the rest of the filter shows: severities and text apply, the
        // combo's own choice does not (so the other kinds stay offered with their counts).
        QCOMPARE(model.codeCounts(), (QMap<QString, int>{{QStringLiteral("syntax-error"), 2}}));
        QCOMPARE(model.packageCounts(),
                 (QMap<QString, int>{{QStringLiteral("alpha"), 1}, {QStringLiteral("beta"), 1}}));
        f = {};
        f.infos = false;
        f.package = QStringLiteral("beta");
        model.setFilter(f);
        QCOMPARE(model.codeCounts(), (QMap<QString, int>{{QStringLiteral("parse-failed"), 1},
                                                         {QStringLiteral("syntax-error"), 1}}));
        QCOMPARE(model.packageCounts().value(QStringLiteral("beta")), 2);
        QCOMPARE(model.packageCounts().value(QStringLiteral("alpha")), 1);
    }

    void groupsByKindAndPackage()
    {
        Document doc;
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setAtomicNodes(sample());
        model.setGrouping(DiagnosticModel::Grouping::Kind);
        QCOMPARE(model.rowCount(), 4);
        const QModelIndex syntax = model.index(0, 0);
        QVERIFY(syntax.data(DiagnosticModel::GroupRole).toBool());
        QCOMPARE(syntax.data().toString(),
                 QStringLiteral("syntax-error — Syntax error (2 findings)"));
        QCOMPARE(model.rowCount(syntax), 2);
        QCOMPARE(model.index(1, DiagnosticModel::MessageColumn, syntax).data().toString(),
                 QStringLiteral("Unbalanced braces."));
        QVERIFY(!model.diagnostic(syntax));
        QCOMPARE(model.diagnostic(model.index(0, 0, syntax))->evidence.line, 12);

        model.setGrouping(DiagnosticModel::Grouping::Package);
        QCOMPARE(column(model, 0), (QStringList{"alpha (1 finding)", "beta (3 findings)",
                                                "(no package) (1 finding)"}));
        // The filter applies inside the groups; a group with nothing left goes.
        DiagnosticModel::Filter f;
        f.errors = false;
        f.infos = false;
        model.setFilter(f);
        QCOMPARE(column(model, 0), (QStringList{"alpha (1 finding)", "beta (1 finding)"}));
        model.setGrouping(DiagnosticModel::Grouping::None);
        QCOMPARE(model.rowCount(), 2);
        QCOMPARE(model.rowCount(model.index(0, 0)), 0);
    }

    void sortsByEveryColumn_data()
    {
        QTest::addColumn<int>("column");
        QTest::addColumn<QStringList>("ascending");
        QTest::newRow("severity") << int(DiagnosticModel::SeverityColumn)
                                  << QStringList{"Info", "Info", "Warning", "Warning", "Error"};
        QTest::newRow("kind") << int(DiagnosticModel::KindColumn)
                              << QStringList{"binary-file", "parse-failed", "syntax-error",
                                             "syntax-error", "topic-unheard"};
        QTest::newRow("package") << int(DiagnosticModel::PackageColumn)
                                 << QStringList{"", "alpha", "beta", "beta", "beta"};
        // by path, then by line as a number
        QTest::newRow("file") << int(DiagnosticModel::FileColumn)
                              << QStringList{"README.bin", "src/alpha/src/a.cpp:12",
                                             "src/beta/beta/talker.py:40", "src/beta/src/b.cpp:3",
                                             "src/beta/src/c.cpp:7"};
        QTest::newRow("message") << int(DiagnosticModel::MessageColumn)
                                 << QStringList{"/talker publishes /chat.",
                                                "A file that looks binary.",
                                                "Could not parse a call.", "The parser gave up.",
                                                "Unbalanced braces."};
        QTest::newRow("systems") << int(DiagnosticModel::ContextsColumn)
                                 << QStringList{"", "", "", "", "2"};
    }

    void sortsByEveryColumn()
    {
        QFETCH(int, column);
        QFETCH(QStringList, ascending);
        Document doc;
        DiagnosticModel model(&doc);
        doc.setAtomicNodes(sample());
        QSortFilterProxyModel proxy;
        proxy.setSortRole(DiagnosticModel::SortRole);
        proxy.setSourceModel(&model);
        proxy.sort(column, Qt::AscendingOrder);
        QStringList shown = ::column(proxy, column);
        if (column == DiagnosticModel::KindColumn)
            for (QString &s : shown)
                s = s.section(QStringLiteral(" — "), 0, 0);
        QCOMPARE(shown, ascending);
    }

    void hideAndAcceptUndoAndPersist()
    {
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setRecovery(m_recovered);
        const int total = model.total();
        QVERIFY(total >= 3);
        QSignalSpy changed(&model, &DiagnosticModel::findingsChanged);
        const QString first = model.index(0, 0).data(DiagnosticModel::KeyRole).toString();
        const QString second = model.index(1, 0).data(DiagnosticModel::KeyRole).toString();
        QCOMPARE(model.markFindings({model.index(0, 0)}, FindingMark::Status::Hidden), 1);
        QCOMPARE(model.markFindings({model.index(0, 0)}, FindingMark::Status::Accepted,
                                    QStringLiteral("the map comes from a bag")),
                 1);
        QVERIFY(changed.count() >= 2);
        QCOMPARE(model.shown(), total - 2);
        QCOMPARE(doc.session()->findingMarks().size(), 2);
        const FindingMark accepted = *doc.session()->project().finding(second);
        QCOMPARE(accepted.status, FindingMark::Status::Accepted);
        QCOMPARE(accepted.reason, QStringLiteral("the map comes from a bag"));
        QCOMPARE(accepted.author, ProjectSession::author());
        QVERIFY(accepted.time.isValid());
        QVERIFY(doc.session()->isModified());

        // Shown again (greyed, marked) by the toggles.
        DiagnosticModel::Filter f;
        f.showHidden = true;
        model.setFilter(f);
        QCOMPARE(model.shown(), total - 1);
        QCOMPARE(model.index(0, 0).data(DiagnosticModel::KeyRole).toString(), first);
        QVERIFY(model.index(0, 0).data().toString().contains(QStringLiteral("hidden")));
        QVERIFY(model.index(0, 0).data(Qt::ForegroundRole).isValid());
        QCOMPARE(model.mark(model.index(0, 0))->status, FindingMark::Status::Hidden);
        QCOMPARE(model.index(0, 0).data(Qt::DecorationRole).value<QIcon>().cacheKey(),
                 Icons::severity(model.diagnostic(model.index(0, 0))->severity).cacheKey());
        // An accepted finding does not look set aside: a tick, the normal colour, and who
        // accepted it and why in its tooltip.
        f.showHidden = false;
        f.showAccepted = true;
        model.setFilter(f);
        const QModelIndex acceptedRow = model.index(0, 0);
        QCOMPARE(acceptedRow.data(DiagnosticModel::KeyRole).toString(), second);
        QVERIFY(acceptedRow.data().toString().contains(QStringLiteral("accepted")));
        QCOMPARE(acceptedRow.data(Qt::DecorationRole).value<QIcon>().cacheKey(),
                 Icons::accepted().cacheKey());
        QVERIFY(!acceptedRow.data(Qt::ForegroundRole).isValid());
        QVERIFY(!acceptedRow.data(Qt::FontRole).isValid());
        QVERIFY(acceptedRow.data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("the map comes from a bag")));
        model.setFilter({});

        // Undo takes the accept back, redo puts it back.
        doc.undoStack()->undo();
        QVERIFY(test::acceptedSettled(doc));
        QCOMPARE(model.shown(), total - 1);
        QVERIFY(!doc.session()->project().finding(second));
        doc.undoStack()->redo();
        QVERIFY(test::acceptedSettled(doc));
        QCOMPARE(model.shown(), total - 2);

        // A re-run (F5) of the same workspace keeps them: they are keyed, not positional.
        doc.setRecovery(recoverWorkspace(m_ws.path()));
        QCOMPARE(model.total(), total);
        QCOMPARE(model.shown(), total - 2);

        // Saved and opened again.
        const QString file = QDir(m_ws.path()).filePath(QStringLiteral("rosarch.project.json"));
        QVERIFY(doc.session()->saveAs(file));
        Project onDisk;
        QString error;
        QVERIFY2(ProjectFile::read(file, &onDisk, &error), qPrintable(error));
        QCOMPARE(onDisk.findings.size(), 2);
        QVERIFY(ProjectFile::toJson(onDisk).contains("\"version\": 2"));
        Document reopened;
        DiagnosticModel again(&reopened);
        reopened.setRecovery(m_recovered);
        QCOMPARE(reopened.session()->findingMarks(), doc.session()->findingMarks());
        QCOMPARE(again.shown(), total - 2);

        // Restoring a finding removes its mark.
        f.showHidden = true;
        again.setFilter(f);
        QCOMPARE(again.restoreFindings({again.index(0, 0)}), 1);
        QCOMPARE(reopened.session()->findingMarks().size(), 1);
    }

    void checksFollowTheCorrectedModel()
    {
        // The Log shows the checks of the model a person corrected, as the diagram and the
        // exports do: removing the node that publishes /odom_raw takes the planner's misspelt
        // /odom_raws finding away (nothing is like it any more).
        Document doc;
        doc.session()->setAutosaveInterval(60000);
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setRecovery(m_recovered);
        const auto misspelt = [&model] {
            return messages(model).filter(QStringLiteral("/odom_raws")).size();
        };
        QCOMPARE(misspelt(), 1);
        const QStringList before = messages(model);
        // Odometry runs in two systems, both of which report the finding (two contexts).
        QList<Correction> removals;
        for (const NodeInstance &n : doc.launchDependencies().nodes) {
            if (n.nodeName != QLatin1String("odometry"))
                continue;
            Correction remove;
            remove.kind = Correction::Kind::Remove;
            remove.target = doc.session()->keyOf(n.id);
            removals.append(remove);
        }
        QCOMPARE(removals.size(), 2);
        QSignalSpy changed(&model, &DiagnosticModel::findingsChanged);
        QCOMPARE(doc.session()->addCorrections(removals, QStringLiteral("Remove odometry")).size(),
                 2);
        QVERIFY(test::acceptedSettled(doc)); // the checks run on the model as accepted
        QVERIFY(changed.count() >= 1);
        QCOMPARE(misspelt(), 0);
        QVERIFY(messages(model) != before);
        doc.undoStack()->undo();
        QVERIFY(test::acceptedSettled(doc));
        QCOMPARE(messages(model), before);
    }

    void oldProjectsStillLoadAndMarksSurviveTheirOwnVersion()
    {
        Project p;
        QString error;
        QVERIFY2(ProjectFile::fromJson("{\"version\": 1, \"launch\": {\"root\": \"a.launch.py\"}}",
                                       &p, &error),
                 qPrintable(error));
        QVERIFY(p.findings.isEmpty());
        QVERIFY(ProjectFile::toJson(p).contains("\"version\": 1"));
        p.findings = {
            {QStringLiteral("syntax-error:00ff"), FindingMark::Status::Hidden, {}, {}, {}}};
        Project back;
        QVERIFY2(ProjectFile::fromJson(ProjectFile::toJson(p), &back, &error), qPrintable(error));
        QCOMPARE(back, p);
        QVERIFY(!ProjectFile::fromJson(
            "{\"version\": 2, \"findings\": [{\"key\": \"x\", \"status\": \"maybe\"}]}", &back,
            &error));
        QVERIFY(!ProjectFile::fromJson("{\"version\": 4}", &back, &error));
        QVERIFY(error.contains(QStringLiteral("newer")));
    }

    void marksByAnOldKeyStillApply()
    {
        // A project written before the per-system findings were merged names a finding by its
        // per-system key: the merged finding answers to it.
        Document doc;
        DiagnosticModel model(&doc);
        AtomicNodeList list = sample();
        list.diagnostics[2].aliases = {QStringLiteral("topic-unheard:0123456789abcdef")};
        doc.setAtomicNodes(list);
        QCOMPARE(doc.session()->markFindings({QStringLiteral("topic-unheard:0123456789abcdef")},
                                             FindingMark::Status::Accepted),
                 1);
        QCOMPARE(model.shown(), 4);
        DiagnosticModel::Filter f;
        f.showAccepted = true;
        model.setFilter(f);
        QCOMPARE(model.restoreFindings({model.index(2, 0)}), 1);
        QVERIFY(doc.session()->findingMarks().isEmpty());
    }

    void panelFiltersAndStepsInViewOrder()
    {
        Document doc;
        DiagnosticModel model(&doc);
        LogView view;
        view.setModel(&model);
        QSignalSpy titles(&view, &LogView::titleChanged);
        QSignalSpy evidence(&view, &LogView::evidenceRequested);
        doc.setAtomicNodes(sample());
        QCOMPARE(view.title(), QStringLiteral("Log — 5 findings"));
        QVERIFY(!titles.isEmpty());
        QTreeView *tree = view.diagnosticsView();
        DiagnosticFilterBar *bar = view.filterBar();
        QVERIFY(bar->kindCombo()->itemText(0).contains(QStringLiteral("(5)")));

        // Errors off: the title counts what is shown.
        bar->severityButton(Diagnostic::Severity::Error)->click();
        QCOMPARE(tree->model()->rowCount(), 4);
        QCOMPARE(view.title(), QStringLiteral("Log — 5 findings, 4 shown"));

        // Next goes through what is shown only, in the view's order (sorted by file here).
        tree->sortByColumn(DiagnosticModel::FileColumn, Qt::DescendingOrder);
        const auto currentMessage = [&] {
            return tree->currentIndex()
                .siblingAtColumn(DiagnosticModel::MessageColumn)
                .data()
                .toString();
        };
        view.selectNextDiagnostic();
        QCOMPARE(currentMessage(), QStringLiteral("Unbalanced braces."));
        view.selectNextDiagnostic();
        QCOMPARE(currentMessage(), QStringLiteral("/talker publishes /chat."));
        QCOMPARE(evidence.count(), 2);
        QCOMPARE(evidence.last().first().value<Evidence>().line, 40);
        // The detail explains the kind, with the systems it was seen in.
        QVERIFY(view.detail()->toPlainText().contains(QStringLiteral("Publisher that nobody")));
        QVERIFY(view.detail()->toPlainText().contains(QStringLiteral("b.launch.py")));
        view.selectPreviousDiagnostic();
        QCOMPARE(currentMessage(), QStringLiteral("Unbalanced braces."));
        view.selectPreviousDiagnostic(); // wraps
        QCOMPARE(currentMessage(), QStringLiteral("A file that looks binary."));

        // Grouped by kind: steps go group by group, never onto a group row.
        const int severityWidth = tree->columnWidth(DiagnosticModel::SeverityColumn);
        bar->groupingCombo()->setCurrentIndex(1);
        QCOMPARE(tree->model()->rowCount(), 3);
        // The rows sit indented under their group: the severity's column widens by as much
        // (before, "Warning" was cut to "War…").
        QCOMPARE(tree->columnWidth(DiagnosticModel::SeverityColumn),
                 severityWidth + tree->indentation());
        tree->setCurrentIndex({});
        QStringList order;
        for (int i = 0; i < 4; ++i) {
            view.selectNextDiagnostic();
            order << currentMessage();
        }
        // The groups sort too (by their label, descending here).
        QCOMPARE(order, (QStringList{"/talker publishes /chat.", "Unbalanced braces.",
                                     "Could not parse a call.", "A file that looks binary."}));

        // The search field narrows it down after typing stops.
        bar->groupingCombo()->setCurrentIndex(0);
        QCOMPARE(tree->columnWidth(DiagnosticModel::SeverityColumn), severityWidth);
        bar->searchEdit()->setText(QStringLiteral("braces"));
        QTRY_COMPARE(tree->model()->rowCount(), 1);
        bar->searchEdit()->clear();
        QTRY_COMPARE(tree->model()->rowCount(), 4);

        // Hide with the shortcut of the table: the finding goes, the next one is selected.
        view.show();
        view.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&view));
        tree->setFocus();
        view.selectNextDiagnostic();
        const QString hidden = currentMessage();
        QTest::keyClick(tree, Qt::Key_H);
        QCOMPARE(tree->model()->rowCount(), 3);
        QVERIFY(!messages(*tree->model()).contains(hidden));
        QVERIFY(!currentMessage().isEmpty());
        bar->showHiddenBox()->setChecked(true);
        QCOMPARE(tree->model()->rowCount(), 4);
        doc.undoStack()->undo();
        QVERIFY(test::acceptedSettled(doc));
        bar->showHiddenBox()->setChecked(false);
        QCOMPARE(tree->model()->rowCount(), 4);
    }
};

QTEST_MAIN(TestDiagnosticModel)
#include "tst_diagnosticmodel.moc"
