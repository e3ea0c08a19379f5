// The node list shows what each class declares: a "Parameters" row after its ports with one row
// per declared parameter (name, type, default, read-only, range, description), found by the
// filter, opened only when asked or when the filter matches a parameter, and taking the person
// to the declaration. A class row's tooltip says which description is in effect and where it
// comes from.
#include "document/document.h"
#include "document/nodedescription.h"
#include "suggestions/suggestionreport.h"
#include "support/cacherecovery.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/nodefilterproxymodel.h"

#include <QAbstractItemModelTester>
#include <QLineEdit>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;

namespace {

const QString kFile = QStringLiteral("src/nav/src/controller.cpp");

ParameterDeclaration declared(const QString &name, const QString &type, const QString &defaultValue,
                              int line)
{
    ParameterDeclaration p;
    p.name = name;
    p.type = type;
    p.defaultValue = defaultValue;
    p.hasDefault = !defaultValue.isEmpty();
    p.via = QStringLiteral("declare_parameter");
    p.evidence = {kFile, line, 5, line, 60};
    return p;
}

/// One package with a controller that declares four parameters, a plugin that declares one
/// under its instance name, and a class that declares none.
AtomicNodeList sampleList()
{
    AtomicNodeList list;
    list.workspaceRoot = QStringLiteral("/ws-parameters");
    RosPackage nav;
    nav.name = QStringLiteral("nav");
    nav.buildType = QStringLiteral("ament_cmake");
    list.packages = {nav};

    AtomicNode controller;
    controller.id = QStringLiteral("arc_1");
    controller.className = QStringLiteral("ControllerServer");
    controller.packageName = nav.name;
    controller.evidence = {kFile, 10, 1, 200, 2};
    Port cmd;
    cmd.id = QStringLiteral("p1");
    cmd.name = QStringLiteral("cmd_vel");
    cmd.type = QStringLiteral("geometry_msgs/msg/Twist");
    cmd.evidence = {kFile, 40, 5, 40, 70};
    controller.ports = {cmd};
    ParameterDeclaration frequency = declared(QStringLiteral("controller_frequency"),
                                              QStringLiteral("double"), QStringLiteral("20.0"), 21);
    frequency.description = QStringLiteral("How often the controller runs, in Hz");
    frequency.range = QStringLiteral("[1.0, 100.0]");
    ParameterDeclaration frame =
        declared(QStringLiteral("odom_frame"), QStringLiteral("string"), {}, 22);
    frame.readOnly = true;
    ParameterDeclaration plugins =
        declared(QStringLiteral("controller_plugins"), QStringLiteral("string_array"),
                 QStringLiteral("[FollowPath]"), 23);
    ParameterDeclaration perPlugin =
        declared(QStringLiteral("{source}.topic"), QStringLiteral("string"), {}, 24);
    controller.parameters = {frequency, frame, plugins, perPlugin};
    controller.acceptsUndeclared = true;

    AtomicNode follower;
    follower.id = QStringLiteral("arc_2");
    follower.className = QStringLiteral("FollowPath");
    follower.packageName = nav.name;
    follower.pluginInterface = QStringLiteral("nav_core::Controller");
    follower.evidence = {QStringLiteral("src/nav/src/follow.cpp"), 5, 1, 80, 2};
    follower.parameters = {declared(QStringLiteral("{plugin}.max_vel_x"), QStringLiteral("double"),
                                    QStringLiteral("0.5"), 30)};
    follower.parameters[0].evidence.file = QStringLiteral("src/nav/src/follow.cpp");
    follower.description = QStringLiteral("Follows a path.");

    AtomicNode bare;
    bare.id = QStringLiteral("arc_3");
    bare.className = QStringLiteral("Bare");
    bare.packageName = nav.name;
    bare.evidence = {QStringLiteral("src/nav/src/bare.cpp"), 3, 1, 9, 2};

    list.nodes = {controller, follower, bare};
    return list;
}

QString tipOf(const AtomicNodeModel &model, const QString &nodeId)
{
    return model.nodeIndex(nodeId).data(Qt::ToolTipRole).toString();
}

} // namespace

class TestAtomicNodeParameters : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        // descriptions edited and suggestions accepted here are kept in test-mode projects
        QStandardPaths::setTestModeEnabled(true);
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
    }

    void passesModelTester()
    {
        Document doc;
        AtomicNodeModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setAtomicNodes(sampleList());
        AtomicNodeList fewer = sampleList();
        fewer.nodes[0].parameters.removeLast();
        doc.setAtomicNodes(fewer);
        NodeFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        QAbstractItemModelTester proxyTester(
            &proxy, QAbstractItemModelTester::FailureReportingMode::QtTest);
        proxy.setFilterFixedString(QStringLiteral("frame"));
        proxy.setFilterFixedString(QString());
        QCOMPARE(model.rowCount(), 1);
    }

    void parametersFollowThePorts()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QModelIndex controller = model.nodeIndex(QStringLiteral("arc_1"));
        QCOMPARE(model.rowCount(controller), 2); // cmd_vel, then "Parameters"
        QCOMPARE(model.kind(model.index(0, 0, controller)), AtomicNodeModel::ItemKind::Port);
        const QModelIndex group = model.index(1, 0, controller);
        QCOMPARE(model.kind(group), AtomicNodeModel::ItemKind::Parameters);
        QCOMPARE(group, model.parametersIndex(QStringLiteral("arc_1")));
        QCOMPARE(group.data().toString(), QStringLiteral("Parameters"));
        QCOMPARE(group.siblingAtColumn(AtomicNodeModel::DetailsColumn).data().toString(),
                 QStringLiteral("4 declared · takes any parameter"));
        QCOMPARE(model.rowCount(group), 4);
        QCOMPARE(group.parent(), controller);
        QVERIFY(model.elementId(group).isEmpty());

        const QModelIndex frequency = model.index(0, 0, group);
        QCOMPARE(model.kind(frequency), AtomicNodeModel::ItemKind::Parameter);
        QCOMPARE(frequency.parent(), group);
        QCOMPARE(frequency.parent().parent(), controller);
        QCOMPARE(model.rowCount(frequency), 0);
        QVERIFY(model.flags(frequency) & Qt::ItemNeverHasChildren);
        QVERIFY(!(model.flags(frequency.siblingAtColumn(AtomicNodeModel::DescriptionColumn)) &
                  Qt::ItemIsEditable));
        QCOMPARE(frequency.data().toString(), QStringLiteral("controller_frequency"));
        QCOMPARE(frequency.data(AtomicNodeModel::ParameterNameRole).toString(),
                 QStringLiteral("controller_frequency"));
        QCOMPARE(frequency.data(AtomicNodeModel::NodeIdRole).toString(), QStringLiteral("arc_1"));
        QVERIFY(frequency.data(AtomicNodeModel::PortIdRole).toString().isEmpty());
        QCOMPARE(frequency.siblingAtColumn(AtomicNodeModel::TypeColumn).data().toString(),
                 QStringLiteral("double"));
        QCOMPARE(frequency.siblingAtColumn(AtomicNodeModel::DetailsColumn).data().toString(),
                 QStringLiteral("default: 20.0 · range: [1.0, 100.0]"));
        QCOMPARE(frequency.siblingAtColumn(AtomicNodeModel::DescriptionColumn).data().toString(),
                 QStringLiteral("How often the controller runs, in Hz"));
        QCOMPARE(model
                     .parameterIndex(QStringLiteral("arc_1"), QStringLiteral("odom_frame"),
                                     AtomicNodeModel::DetailsColumn)
                     .data()
                     .toString(),
                 QStringLiteral("no default · read-only"));
        // a name with a part decided at run time reads as an unresolved port's does
        const QModelIndex perPlugin =
            model.parameterIndex(QStringLiteral("arc_1"), QStringLiteral("{source}.topic"));
        QVERIFY(perPlugin.data(Qt::FontRole).value<QFont>().italic());
        QVERIFY(!frequency.data(Qt::FontRole).value<QFont>().italic());

        // the declaration is the row's place in the source
        QCOMPARE(model.evidence(frequency), sampleList().nodes[0].parameters[0].evidence);
        QCOMPARE(model.parameter(frequency)->name, QStringLiteral("controller_frequency"));
        QVERIFY(!model.parameter(group));
        QVERIFY(!model.port(frequency));

        // a class that declares nothing has no "Parameters" row; a plugin without ports has
        // only that row
        QCOMPARE(model.rowCount(model.nodeIndex(QStringLiteral("arc_3"))), 0);
        QVERIFY(!model.parametersIndex(QStringLiteral("arc_3")).isValid());
        const QModelIndex pluginGroup = model.parametersIndex(QStringLiteral("arc_2"));
        QCOMPARE(pluginGroup.row(), 0);
        QCOMPARE(pluginGroup.siblingAtColumn(AtomicNodeModel::DetailsColumn).data().toString(),
                 QStringLiteral("1 declared"));
        QCOMPARE(model.index(0, 0, pluginGroup).data().toString(),
                 QStringLiteral("{plugin}.max_vel_x"));
    }

    void parameterToolTipSaysWhatAndWhere()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QString tip =
            model
                .parameterIndex(QStringLiteral("arc_1"), QStringLiteral("controller_frequency"),
                                AtomicNodeModel::TypeColumn)
                .data(Qt::ToolTipRole)
                .toString();
        for (const QString &part :
             {QStringLiteral("<b>Parameter</b> controller_frequency"),
              QStringLiteral("Declared by ControllerServer"), QStringLiteral("Type: double"),
              QStringLiteral("Default: 20.0"), QStringLiteral("Range: [1.0, 100.0]"),
              QStringLiteral("Description: How often the controller runs, in Hz"),
              QStringLiteral("declare_parameter"),
              QStringLiteral("Declared at src/nav/src/controller.cpp:21")})
            QVERIFY2(tip.contains(part), qPrintable(tip));
        const QString frame =
            model.parameterIndex(QStringLiteral("arc_1"), QStringLiteral("odom_frame"))
                .data(Qt::ToolTipRole)
                .toString();
        QVERIFY2(frame.contains(QStringLiteral("No default")), qPrintable(frame));
        QVERIFY2(frame.contains(QStringLiteral("Read-only")), qPrintable(frame));
        QVERIFY2(frame.contains(QStringLiteral("No description in the code")), qPrintable(frame));
        const QString plugin =
            model.parameterIndex(QStringLiteral("arc_2"), QStringLiteral("{plugin}.max_vel_x"))
                .data(Qt::ToolTipRole)
                .toString();
        QVERIFY2(plugin.contains(QStringLiteral("the name the plugin is loaded under")),
                 qPrintable(plugin));
    }

    // The filter finds a parameter by name or type like a port, keeping the way to it; the
    // panel opens a "Parameters" row only for a match in it.
    void filterFindsParameters()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        AtomicNodePanel panel;
        panel.setModel(&model);
        NodeFilterProxyModel *proxy = panel.proxyModel();
        QTreeView *tree = panel.treeView();
        const auto shown = [&](const QModelIndex &source) { return proxy->mapFromSource(source); };
        const QModelIndex group = model.parametersIndex(QStringLiteral("arc_1"));
        // no filter: the classes show their ports, their parameters wait to be asked for
        QVERIFY(tree->isExpanded(shown(model.nodeIndex(QStringLiteral("arc_1")))));
        QVERIFY(!tree->isExpanded(shown(group)));

        panel.filterEdit()->setText(QStringLiteral("ControllerServer")); // the class itself
        QTRY_COMPARE(proxy->rowCount(proxy->index(0, 0)), 1);
        QTRY_VERIFY(tree->isExpanded(shown(model.nodeIndex(QStringLiteral("arc_1")))));
        QVERIFY(shown(group).isValid());
        QVERIFY(!tree->isExpanded(shown(group))); // its parameters do not match by themselves

        // a match among them opens them
        panel.filterEdit()->setText(QStringLiteral("odom_fr"));
        QTRY_COMPARE(proxy->rowCount(), 1);
        const QModelIndex package = proxy->index(0, 0);
        QCOMPARE(proxy->rowCount(package), 1); // only the class that declares it
        const QModelIndex controller = proxy->index(0, 0, package);
        QCOMPARE(proxy->rowCount(controller), 1); // cmd_vel hidden, "Parameters" kept
        const QModelIndex shownGroup = proxy->index(0, 0, controller);
        QCOMPARE(shownGroup.data().toString(), QStringLiteral("Parameters"));
        QCOMPARE(proxy->rowCount(shownGroup), 1);
        QCOMPARE(proxy->index(0, 0, shownGroup).data().toString(), QStringLiteral("odom_frame"));
        QTRY_VERIFY(tree->isExpanded(shownGroup));

        panel.filterEdit()->setText(QStringLiteral("string_array")); // a type
        QTRY_COMPARE(proxy->rowCount(), 1);
        const QModelIndex byType = shown(
            model.parameterIndex(QStringLiteral("arc_1"), QStringLiteral("controller_plugins")));
        QVERIFY(byType.isValid());
        QCOMPARE(proxy->rowCount(byType.parent()), 1);

        panel.filterEdit()->setText(QStringLiteral("no such name"));
        QTRY_COMPARE(proxy->rowCount(), 0);

        // cleared, the filter closes the "Parameters" rows it opened, but the current one
        panel.filterEdit()->setText(QStringLiteral("odom_fr"));
        QTRY_VERIFY(tree->isExpanded(shown(group)));
        panel.filterEdit()->clear();
        QTRY_COMPARE(proxy->rowCount(shown(model.nodeIndex(QStringLiteral("arc_1")))), 2);
        QTRY_VERIFY(!tree->isExpanded(shown(group)));
        QVERIFY(tree->isExpanded(shown(model.nodeIndex(QStringLiteral("arc_1")))));
        panel.filterEdit()->setText(QStringLiteral("odom_fr"));
        QTRY_VERIFY(tree->isExpanded(shown(group)));
        panel.selectSourceIndex(
            model.parameterIndex(QStringLiteral("arc_1"), QStringLiteral("odom_frame")));
        panel.filterEdit()->clear();
        QTRY_COMPARE(proxy->rowCount(shown(model.nodeIndex(QStringLiteral("arc_1")))), 2);
        QVERIFY(tree->isExpanded(shown(group)));
        QCOMPARE(panel.currentSourceIndex(),
                 model.parameterIndex(QStringLiteral("arc_1"), QStringLiteral("odom_frame")));
    }

    // Double-click or Enter on a parameter asks for its declaration, as on a port.
    void activatingGoesToTheDeclaration()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        AtomicNodePanel panel;
        panel.setModel(&model);
        panel.resize(800, 600);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy asked(&panel, &AtomicNodePanel::evidenceRequested);
        QTreeView *tree = panel.treeView();
        const QModelIndex frequency = panel.proxyModel()->mapFromSource(
            model.parameterIndex(QStringLiteral("arc_1"), QStringLiteral("controller_frequency")));
        QVERIFY(frequency.isValid());
        tree->expand(frequency.parent());
        tree->scrollTo(frequency);
        tree->setCurrentIndex(frequency);
        tree->setFocus();
        QTest::keyClick(tree, Qt::Key_Return);
        QCOMPARE(asked.size(), 1);
        QCOMPARE(asked[0][0].value<Evidence>(), sampleList().nodes[0].parameters[0].evidence);

        tree->doItemsLayout();
        const QRect rect = tree->visualRect(frequency);
        QVERIFY(rect.isValid());
        QCOMPARE(tree->indexAt(rect.center()), frequency);
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, rect.center()); // the press a
        QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {},
                           rect.center()); // double-click needs
        QCOMPARE(asked.size(), 2);
        QCOMPARE(asked.last()[0].value<Evidence>().line, 21);

        // a port too; the "Parameters" row and a class do not ask
        Q_EMIT tree->activated(panel.proxyModel()->mapFromSource(
            model.portIndex(QStringLiteral("arc_1"), QStringLiteral("p1"))));
        QCOMPARE(asked.last()[0].value<Evidence>().line, 40);
        const qsizetype before = asked.size();
        Q_EMIT tree->activated(frequency.parent());
        Q_EMIT tree->activated(frequency.parent().parent());
        QCOMPARE(asked.size(), before);
    }

    // The class tooltip gives the description in effect and says whose it is: the code's,
    // an accepted suggestion's, or a person's.
    void classToolTipSaysWhoseDescription()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QVERIFY2(tipOf(model, QStringLiteral("arc_1"))
                     .contains(QStringLiteral("No description in the code")),
                 qPrintable(tipOf(model, QStringLiteral("arc_1"))));
        QVERIFY(tipOf(model, QStringLiteral("arc_1"))
                    .contains(QStringLiteral("4 declared parameters")));
        QVERIFY2(tipOf(model, QStringLiteral("arc_2"))
                     .contains(QStringLiteral("Description (from the code): Follows a path.")),
                 qPrintable(tipOf(model, QStringLiteral("arc_2"))));
        QCOMPARE(NodeDescription::of(doc, QStringLiteral("arc_2")).source,
                 NodeDescription::Source::Code);

        // an accepted suggestion
        Suggestion s;
        s.id = QStringLiteral("s1");
        s.kind = Suggestion::Kind::NodeDescription;
        s.targetId = QStringLiteral("arc_1");
        s.value = QStringLiteral("Runs the path-following controllers.");
        s.origin.provider = QStringLiteral("deterministic");
        SuggestionReport report;
        report.suggestions = {s};
        doc.session()->setSuggestions(report);
        QVERIFY(tipOf(model, QStringLiteral("arc_1"))
                    .contains(
                        QStringLiteral("No description in the code"))); // pending is not in effect
        QVERIFY(doc.session()->acceptSuggestion(QStringLiteral("s1")));
        QVERIFY2(tipOf(model, QStringLiteral("arc_1"))
                     .contains(QStringLiteral("Description (from an accepted suggestion): Runs "
                                              "the path-following controllers.")),
                 qPrintable(tipOf(model, QStringLiteral("arc_1"))));

        // a person's correction wins over both, and undoing it gives the suggestion back
        QVERIFY(model.setData(
            model.nodeIndex(QStringLiteral("arc_1"), AtomicNodeModel::DescriptionColumn),
            QStringLiteral("Follows paths with plugins.")));
        QVERIFY2(tipOf(model, QStringLiteral("arc_1"))
                     .contains(QStringLiteral("Description (written by a person): Follows "
                                              "paths with plugins.")),
                 qPrintable(tipOf(model, QStringLiteral("arc_1"))));
        QCOMPARE(NodeDescription::of(doc, QStringLiteral("arc_1")).source,
                 NodeDescription::Source::Correction);
        // the correction leaves the declared parameters where they were
        QCOMPARE(model.rowCount(model.parametersIndex(QStringLiteral("arc_1"))), 4);
        doc.undoStack()->undo();
        QVERIFY2(tipOf(model, QStringLiteral("arc_1"))
                     .contains(QStringLiteral("(from an accepted suggestion)")),
                 qPrintable(tipOf(model, QStringLiteral("arc_1"))));
        doc.undoStack()->undo(); // the acceptance
        QVERIFY(tipOf(model, QStringLiteral("arc_1"))
                    .contains(QStringLiteral("No description in the code")));
        QCOMPARE(NodeDescription::of(doc, QStringLiteral("nothing")).source,
                 NodeDescription::Source::None);
    }

    // A class that loads plugins says, where it is launched, which it loads and what they
    // serve: a newcomer reads from the node list which actions the host serves.
    void classToolTipNamesThePluginsItsInstancesLoad()
    {
        Document doc;
        doc.setRecovery(test::recoverUncached(test::dataDir(QStringLiteral("cpp_plugins/ws"))));
        AtomicNodeModel model(&doc);
        QString host;
        QString plugin;
        for (const AtomicNode &n : doc.atomicNodes().nodes) {
            if (n.className == QLatin1String("NavigatorServer"))
                host = n.id;
            if (n.className == QLatin1String("PathFollower"))
                plugin = n.id;
        }
        QVERIFY(!host.isEmpty() && !plugin.isEmpty());
        const QString tip = tipOf(model, host);
        QVERIFY2(tip.contains(QStringLiteral(
                     "Loads, where it is launched: GoalNavigator (serves action drive_to_goal)")),
                 qPrintable(tip));
        QVERIFY2(!tipOf(model, plugin).contains(QStringLiteral("Loads, where it is launched")),
                 qPrintable(tipOf(model, plugin)));
    }
};

QTEST_MAIN(TestAtomicNodeParameters)
#include "tst_atomicnodeparameters.moc"
