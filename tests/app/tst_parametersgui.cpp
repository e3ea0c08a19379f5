// The window's parameter features as a user meets them: the Parameters tab follows the node
// instance selected in the launch tree, and File › Export NoDL writes one description per node
// class.
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "pipeline/recovery.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/parameterpanel.h"

#include <QDockWidget>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

class TestParametersGui : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parametersFollowTheSelectionAndExportToNodl()
    {
        MainWindow w;
        w.resize(1500, 900);
        w.show();
        QVERIFY(test::child<QDockWidget>(w, QStringLiteral("parametersDock"))
                    ->isVisible()); // a tab beside the log from the start
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(test::dataDir(QStringLiteral("params_checks/ws")));
        QTRY_VERIFY_WITH_TIMEOUT(!test::child<Document>(w)->launchDependencies().nodes.isEmpty(),
                                 60000);
        QTRY_VERIFY_WITH_TIMEOUT(test::child<LaunchTreeModel>(w)->rowCount() > 0, 10000);

        QString followId;
        for (const NodeInstance &n : test::child<Document>(w)->launchDependencies().nodes)
            if (n.nodeName == QLatin1String("follow_server"))
                followId = n.id;
        QVERIFY(!followId.isEmpty());
        test::child<LaunchTreePanel>(w)->selectSourceIndex(
            test::child<LaunchTreeModel>(w)->nodeIndex(followId));
        QCOMPARE(test::child<ParameterPanel>(w)->summary(),
                 QStringLiteral("/follow_server (FollowServer): 7 parameters declared, 2 given "
                                "but not declared"));
        test::child<QDockWidget>(w, QStringLiteral("parametersDock"))->raise();
        test::saveScreenshot(w, QStringLiteral("parameters_tab.png"));

        QTemporaryDir out;
        QVERIFY(w.exportNodlTo(out.path()));
        const QByteArray document =
            test::readFile(out.filePath(QStringLiteral("drive_servers/speed_limiter.nodl.json")));
        QVERIFY2(!document.isEmpty(), "no NoDL document for the speed limiter");
        const QJsonObject parameters = QJsonDocument::fromJson(document)
                                           .object()
                                           .value(QStringLiteral("parameters"))
                                           .toObject();
        QCOMPARE(parameters.value(QStringLiteral("smoothing_frequency"))
                     .toObject()
                     .value(QStringLiteral("type"))
                     .toString(),
                 QStringLiteral("double"));
    }
};

QTEST_MAIN(TestParametersGui)
#include "tst_parametersgui.moc"
