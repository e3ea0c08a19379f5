// The Parameters panel: a node instance's parameters as a table that sorts by any column,
// filters, says what is given but not declared, and opens where a value is set.
#include "pipeline/recovery.h"
#include "support/recoverytest.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/parameterpanel.h"
#include "widgets/parametertablemodel.h"

#include <QAbstractItemModelTester>
#include <QHeaderView>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QtTest>

using namespace rosarch;

namespace {

QList<InstanceParameter> parametersOf(const Recovery &r, const QString &node)
{
    for (const NodeInstance &n : r.launch.nodes)
        if (n.nodeName == node)
            return ParameterView(r.nodes).of(n);
    return {};
}

QStringList column(const QAbstractItemModel *model, int c)
{
    QStringList out;
    for (int row = 0; row < model->rowCount(); ++row)
        out << model->index(row, c).data().toString();
    return out;
}

} // namespace

class TestParameterPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tableSortsFiltersAndOpensWhereAValueIsSet()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("params_checks/ws")));
        ParameterPanel panel;
        QAbstractItemModelTester tester(panel.model(),
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        panel.resize(900, 400);
        panel.showParameters(QStringLiteral("/speed_limiter (SpeedLimiter)"),
                             parametersOf(r, QStringLiteral("speed_limiter")), true);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        test::saveScreenshot(panel, QStringLiteral("parameterpanel.png"));
        QCOMPARE(panel.summary(), QStringLiteral("/speed_limiter (SpeedLimiter): 16 parameters "
                                                 "declared, 3 given but not declared"));
        const QAbstractItemModel *shown = panel.table()->model();
        QCOMPARE(column(shown, ParameterTableModel::NameColumn).first(),
                 QStringLiteral("command_frame"));
        // the misspelt key is there, marked as ignored
        const int misspelt = int(column(shown, ParameterTableModel::NameColumn)
                                     .indexOf(QStringLiteral("smoothing_frequncy")));
        QVERIFY(misspelt >= 0);
        QCOMPARE(shown->index(misspelt, ParameterTableModel::DescriptionColumn).data().toString(),
                 QStringLiteral("not declared: ROS 2 ignores this value"));
        QCOMPARE(shown->index(misspelt, ParameterTableModel::SourceColumn).data().toString(),
                 QStringLiteral("drive_params.yaml:8"));

        // a click on the Source header sorts by it
        panel.table()->horizontalHeader()->sectionClicked(ParameterTableModel::SourceColumn);
        panel.table()->sortByColumn(ParameterTableModel::SourceColumn, Qt::AscendingOrder);
        QCOMPARE(column(shown, ParameterTableModel::SourceColumn).first(),
                 QStringLiteral("default"));

        // the filter keeps the rows that mention it in any column
        panel.filter()->setText(QStringLiteral("odom"));
        QCOMPARE(column(shown, ParameterTableModel::NameColumn),
                 (QStringList{QStringLiteral("odom_duration"), QStringLiteral("odom_topic")}));

        // activating a row asks for where its value is set
        QSignalSpy spy(&panel, &ParameterPanel::evidenceRequested);
        const int duration = int(column(shown, ParameterTableModel::NameColumn)
                                     .indexOf(QStringLiteral("odom_duration")));
        emit panel.table()->activated(shown->index(duration, 0));
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toString(),
                 QStringLiteral("src/drive_bringup/config/drive_params.yaml"));
        QCOMPARE(spy.at(0).at(1).toInt(), 13);
    }

    void aClassShowsWhatItDeclares()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("params_checks/ws")));
        const AtomicNode *plugin = nullptr;
        for (const AtomicNode &n : r.nodes.nodes)
            if (n.className == QLatin1String("PurePursuit"))
                plugin = &n;
        QVERIFY(plugin);
        ParameterPanel panel;
        panel.showParameters(plugin->className,
                             ParameterTableModel::declaredOnly(plugin->parameters), false);
        QCOMPARE(panel.summary(), QStringLiteral("PurePursuit declares 3 parameters"));
        QCOMPARE(column(panel.table()->model(), ParameterTableModel::NameColumn),
                 (QStringList{QStringLiteral("{plugin}.desired_linear_vel"),
                              QStringLiteral("{plugin}.lookahead_dist"),
                              QStringLiteral("{plugin}.use_rotate_to_heading")}));
        panel.setMessage(QStringLiteral("Nothing selected."));
        QCOMPARE(panel.model()->rowCount(), 0);
        QVERIFY(panel.table()->isHidden());
    }
};

QTEST_MAIN(TestParameterPanel)
#include "tst_parameterpanel.moc"
