#include "document/document.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/nodefilterproxymodel.h"

#include <QAbstractItemModelTester>
#include <QIcon>
#include <QMenu>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>

using namespace rosarch;

namespace {

Evidence at(const QString &file, int line, int endLine, int column = 1, int endColumn = 0)
{
    return Evidence{file, line, column, endLine, endColumn};
}

/// Two packages: a Python one with one node (two ports) and a C++ one with two nodes.
AtomicNodeList sampleList()
{
    AtomicNodeList list;
    list.workspaceRoot = QStringLiteral("/ws");

    RosPackage alpha;
    alpha.name = QStringLiteral("alpha_py");
    alpha.buildType = QStringLiteral("ament_python");
    alpha.path = QStringLiteral("src/alpha_py");
    alpha.evidence = at(QStringLiteral("src/alpha_py/package.xml"), 3, 3);
    RosPackage beta;
    beta.name = QStringLiteral("beta_cpp");
    beta.buildType = QStringLiteral("ament_cmake");
    beta.path = QStringLiteral("src/beta_cpp");
    beta.evidence = at(QStringLiteral("src/beta_cpp/package.xml"), 4, 4);
    list.packages = {beta, alpha}; // unsorted on purpose: the model sorts by name

    const QString talkerFile = QStringLiteral("src/alpha_py/alpha_py/talker.py");
    AtomicNode talker;
    talker.id = QStringLiteral("arc_1");
    talker.className = QStringLiteral("Talker");
    talker.qualifiedName = QStringLiteral("alpha_py.talker.Talker");
    talker.nodeName = QStringLiteral("talker");
    talker.packageName = alpha.name;
    talker.sourceFiles = {talkerFile};
    talker.compileType = AtomicNode::CompileType::Python;
    talker.baseClasses = {QStringLiteral("Node")};
    talker.executables = {QStringLiteral("talker")};
    talker.evidence = at(talkerFile, 6, 21);
    Port pub =
        test::gui::port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("chatter"),
                        QStringLiteral("std_msgs/msg/String"), {}, at(talkerFile, 11, 11, 26, 70));
    Port sub = test::gui::port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("echo"),
                               QStringLiteral("std_msgs/msg/String"), QStringLiteral("on_echo"),
                               at(talkerFile, 12, 12, 29, 88));
    sub.nameOrigin = NameOrigin::Parameter;
    sub.parameter = QStringLiteral("echo_topic");
    sub.guard = QStringLiteral("self.use_echo");
    pub.via = QStringLiteral("ChatBehaviour");
    pub.viaEvidence = {at(talkerFile, 20, 20), at(QStringLiteral("src/alpha_py/tree.py"), 4, 4)};
    talker.ports = {pub, sub};

    const QString listenerFile = QStringLiteral("src/beta_cpp/src/listener.cpp");
    AtomicNode listener;
    listener.id = QStringLiteral("arc_2");
    listener.className = QStringLiteral("Listener");
    listener.qualifiedName = QStringLiteral("beta_cpp::Listener");
    listener.nodeName = QStringLiteral("listener");
    listener.packageName = beta.name;
    listener.compileType = AtomicNode::CompileType::Cpp;
    listener.baseClasses = {QStringLiteral("rclcpp::Node")};
    listener.plugins = {QStringLiteral("beta_cpp::Listener")};
    listener.evidence = at(listenerFile, 11, 41);
    listener.description = QStringLiteral("Counts messages.");
    Port csub = test::gui::port(QStringLiteral("s1"), PortKind::Subscriber,
                                QStringLiteral("chatter"), QStringLiteral("std_msgs/msg/String"),
                                QStringLiteral("on_message"), at(listenerFile, 17, 18, 21, 90));
    Port srv = test::gui::port(QStringLiteral("ps1"), PortKind::ServiceServer,
                               QStringLiteral("reset"), QStringLiteral("std_srvs/srv/Trigger"),
                               QStringLiteral("on_reset"), at(listenerFile, 19, 20, 16, 99));
    Port dyn =
        test::gui::port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("topic_name_"),
                        QStringLiteral("std_msgs/msg/Int32"), {}, at(listenerFile, 22, 22));
    dyn.nameOrigin = NameOrigin::Expression;
    dyn.nameExpression = QStringLiteral("topic_name_");
    listener.ports = {csub, srv, dyn};

    AtomicNode watchdog;
    watchdog.id = QStringLiteral("arc_3");
    watchdog.className = QStringLiteral("watchdog");
    watchdog.packageName = beta.name;
    watchdog.procedural = true;
    watchdog.evidence = at(QStringLiteral("src/beta_cpp/src/watchdog.cpp"), 5, 5);

    list.nodes = {talker, listener, watchdog};

    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("unresolved-name");
    d.message = QStringLiteral("The topic name of a publisher is not a literal.");
    d.evidence = at(listenerFile, 22, 22);
    list.diagnostics = {d};
    return list;
}

QImage imageOf(const QVariant &decoration)
{
    return decoration.value<QIcon>().pixmap(16, 16).toImage();
}

bool hasOpaquePixels(const QImage &image)
{
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (qAlpha(image.pixel(x, y)) > 128)
                return true;
    return false;
}

} // namespace

class TestAtomicNodeModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        // descriptions edited here are kept in the projects of the workspaces, in test mode
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
        model.setData(model.nodeIndex(QStringLiteral("arc_1"), AtomicNodeModel::DescriptionColumn),
                      QStringLiteral("Greets."));
        doc.undoStack()->undo();
        doc.setAtomicNodes(AtomicNodeList());
        doc.setAtomicNodes(sampleList());
        QCOMPARE(model.rowCount(), 2);
    }

    void rowCounts()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        QCOMPARE(model.rowCount(), 2);
        QCOMPARE(model.columnCount(), int(AtomicNodeModel::ColumnCount));
        const QModelIndex alpha = model.index(0, 0);
        const QModelIndex beta = model.index(1, 0);
        QCOMPARE(alpha.data().toString(), QStringLiteral("alpha_py"));
        QCOMPARE(beta.data().toString(), QStringLiteral("beta_cpp"));
        QCOMPARE(model.rowCount(alpha), 1);
        QCOMPARE(model.rowCount(beta), 2);
        QCOMPARE(model.rowCount(model.index(0, 0, alpha)), 2); // Talker: pub + sub
        QCOMPARE(model.rowCount(model.index(0, 0, beta)), 3);  // Listener
        QCOMPARE(model.rowCount(model.index(1, 0, beta)), 0);  // watchdog
        QCOMPARE(model.rowCount(model.index(0, 0, model.index(0, 0, alpha))), 0); // a port
        QCOMPARE(model.kind(alpha), AtomicNodeModel::ItemKind::Package);
        QCOMPARE(model.kind(model.index(0, 0, alpha)), AtomicNodeModel::ItemKind::Node);
        QCOMPARE(model.kind(model.index(1, 2, model.index(0, 0, alpha))),
                 AtomicNodeModel::ItemKind::Port);
        // parent() round trip for a port in a non-first package and node
        const QModelIndex srv = model.index(1, 0, model.index(0, 0, beta));
        QCOMPARE(srv.parent(), model.index(0, 0, beta));
        QCOMPARE(srv.parent().parent(), beta);
    }

    void displayData()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QModelIndex alpha = model.packageIndex(QStringLiteral("alpha_py"));
        QCOMPARE(alpha.siblingAtColumn(AtomicNodeModel::TypeColumn).data().toString(),
                 QStringLiteral("ament_python"));
        QVERIFY(alpha.siblingAtColumn(AtomicNodeModel::DetailsColumn)
                    .data()
                    .toString()
                    .contains(QStringLiteral("src/alpha_py")));

        const QModelIndex talker = model.nodeIndex(QStringLiteral("arc_1"));
        QCOMPARE(talker.data().toString(), QStringLiteral("Talker"));
        QCOMPARE(talker.siblingAtColumn(AtomicNodeModel::TypeColumn).data().toString(),
                 QStringLiteral("Node"));
        const QString details =
            talker.siblingAtColumn(AtomicNodeModel::DetailsColumn).data().toString();
        QVERIFY2(details.contains(QStringLiteral("node: talker")), qPrintable(details));
        QVERIFY2(details.contains(QStringLiteral("exec: talker")), qPrintable(details));
        QVERIFY2(details.contains(QStringLiteral("Python")), qPrintable(details));

        const QString listenerDetails =
            model.nodeIndex(QStringLiteral("arc_2"), AtomicNodeModel::DetailsColumn)
                .data()
                .toString();
        QVERIFY2(listenerDetails.contains(QStringLiteral("plugin: beta_cpp::Listener")),
                 qPrintable(listenerDetails));
        QVERIFY(listenerDetails.contains(QStringLiteral("C++")));
        QCOMPARE(model.nodeIndex(QStringLiteral("arc_2"), AtomicNodeModel::DescriptionColumn)
                     .data()
                     .toString(),
                 QStringLiteral("Counts messages."));
        QCOMPARE(
            model.nodeIndex(QStringLiteral("arc_3"), AtomicNodeModel::TypeColumn).data().toString(),
            QStringLiteral("procedural node"));

        const QModelIndex sub = model.portIndex(QStringLiteral("arc_1"), QStringLiteral("s1"));
        QCOMPARE(sub.data().toString(), QStringLiteral("echo"));
        QCOMPARE(sub.siblingAtColumn(AtomicNodeModel::TypeColumn).data().toString(),
                 QStringLiteral("std_msgs/msg/String"));
        QCOMPARE(sub.siblingAtColumn(AtomicNodeModel::DetailsColumn).data().toString(),
                 QStringLiteral("callback: on_echo · param: echo_topic · guard: self.use_echo"));
        QCOMPARE(sub.data(AtomicNodeModel::NodeIdRole).toString(), QStringLiteral("arc_1"));
        QCOMPARE(sub.data(AtomicNodeModel::PortIdRole).toString(), QStringLiteral("s1"));

        const QModelIndex dyn = model.portIndex(QStringLiteral("arc_2"), QStringLiteral("p1"));
        QVERIFY(dyn.data(Qt::FontRole).value<QFont>().italic());
        QVERIFY(dyn.siblingAtColumn(AtomicNodeModel::DetailsColumn)
                    .data()
                    .toString()
                    .contains(QStringLiteral("unresolved: topic_name_")));
        QVERIFY(!sub.data(Qt::FontRole).value<QFont>().italic());
    }

    void controlCharactersAreShownAsEscapes()
    {
        // A class or port named with a terminal sequence or a newline shows escaped,
        // one line per row.
        AtomicNodeList list = sampleList();
        list.nodes[0].className = QStringLiteral("Talk\x1b[2Jer\nTwo");
        list.nodes[0].ports[0].name = QStringLiteral("chat\x07ter");
        Document doc;
        doc.setAtomicNodes(list);
        AtomicNodeModel model(&doc);
        QCOMPARE(model.nodeIndex(QStringLiteral("arc_1")).data().toString(),
                 QStringLiteral("Talk\\x1b[2Jer\\x0aTwo"));
        QCOMPARE(model.portIndex(QStringLiteral("arc_1"), QStringLiteral("p1")).data().toString(),
                 QStringLiteral("chat\\x07ter"));
    }

    void iconsAreDrawnAndDistinct()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QModelIndex pkg = model.packageIndex(QStringLiteral("beta_cpp"));
        const QModelIndex node = model.nodeIndex(QStringLiteral("arc_2"));
        const QModelIndex sub = model.portIndex(QStringLiteral("arc_2"), QStringLiteral("s1"));
        const QModelIndex srv = model.portIndex(QStringLiteral("arc_2"), QStringLiteral("ps1"));
        const QModelIndex pub = model.portIndex(QStringLiteral("arc_2"), QStringLiteral("p1"));
        QList<QImage> images;
        for (const QModelIndex &index : {pkg, node, sub, srv, pub}) {
            const QImage image = imageOf(index.data(Qt::DecorationRole));
            QVERIFY2(!image.isNull() && hasOpaquePixels(image),
                     qPrintable(index.data().toString()));
            for (const QImage &other : std::as_const(images))
                QVERIFY(image != other);
            images.append(image);
        }
        QVERIFY(
            !node.siblingAtColumn(AtomicNodeModel::TypeColumn).data(Qt::DecorationRole).isValid());
    }

    // A pluginlib plugin shows as such: its interface in the type column, and the tooltip says
    // who gets its ports.
    void pluginsShowTheirInterface()
    {
        AtomicNodeList list = sampleList();
        AtomicNode plugin;
        plugin.id = QStringLiteral("arc_4");
        plugin.className = QStringLiteral("PathFollower");
        plugin.qualifiedName = QStringLiteral("beta_cpp::PathFollower");
        plugin.packageName = QStringLiteral("beta_cpp");
        plugin.pluginInterface = QStringLiteral("nav_core::Controller");
        plugin.evidence = at(QStringLiteral("src/beta_cpp/src/follower.cpp"), 9, 9);
        list.nodes.append(plugin);
        Document doc;
        doc.setAtomicNodes(list);
        AtomicNodeModel model(&doc);
        QCOMPARE(
            model.nodeIndex(QStringLiteral("arc_4"), AtomicNodeModel::TypeColumn).data().toString(),
            QStringLiteral("plugin: nav_core::Controller"));
        const QString details =
            model.nodeIndex(QStringLiteral("arc_4"), AtomicNodeModel::DetailsColumn)
                .data()
                .toString();
        QVERIFY2(details.contains(QStringLiteral("plugin: beta_cpp::PathFollower")),
                 qPrintable(details));
        const QString tip =
            model.nodeIndex(QStringLiteral("arc_4")).data(Qt::ToolTipRole).toString();
        QVERIFY2(tip.startsWith(QStringLiteral("<b>pluginlib plugin</b>")), qPrintable(tip));
        QVERIFY2(tip.contains(QStringLiteral("nav_core::Controller plugin")), qPrintable(tip));
    }

    // The context menu of a port made through a helper walks the chain: one entry per call
    // site, then the creating call, each asking the source view for its place.
    void contextMenuWalksTheChain()
    {
        AtomicNodeList list = sampleList();
        Port &p = list.nodes[0].ports[0];
        p.via = QStringLiteral("Sensor");
        p.viaEvidence = {at(QStringLiteral("src/alpha_py/alpha_py/talker.py"), 30, 30),
                         at(QStringLiteral("src/alpha_py/alpha_py/sensor.py"), 7, 7)};
        Document doc;
        doc.setAtomicNodes(list);
        AtomicNodeModel model(&doc);
        AtomicNodePanel panel;
        panel.setModel(&model);
        QSignalSpy asked(&panel, &AtomicNodePanel::evidenceRequested);
        QMenu menu;
        panel.addChainActions(&menu, model.portIndex(QStringLiteral("arc_1"), p.id));
        QList<QAction *> steps;
        for (QAction *a : menu.actions())
            if (!a->isSeparator())
                steps << a;
        QCOMPARE(steps.size(), 3);
        QCOMPARE(steps[0]->text(),
                 QStringLiteral("1. Handed over at src/alpha_py/alpha_py/talker.py:30"));
        QVERIFY2(steps[2]->text().startsWith(QStringLiteral("3. Created in Sensor at ")),
                 qPrintable(steps[2]->text()));
        steps[1]->trigger();
        steps[2]->trigger();
        QCOMPARE(asked.size(), 2);
        QCOMPARE(asked[0][0].value<Evidence>().line, 7);
        QCOMPARE(asked[1][0].value<Evidence>(), p.evidence);

        QMenu plain; // a port the node makes itself has no chain
        panel.addChainActions(&plain,
                              model.portIndex(QStringLiteral("arc_2"), QStringLiteral("p1")));
        QVERIFY(plain.actions().isEmpty());
    }

    void toolTipsSayWhatAndWhere()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QString pkgTip =
            model.packageIndex(QStringLiteral("alpha_py")).data(Qt::ToolTipRole).toString();
        QVERIFY2(pkgTip.contains(QStringLiteral("src/alpha_py/package.xml:3")), qPrintable(pkgTip));
        QVERIFY(pkgTip.contains(QStringLiteral("package")));

        const QString nodeTip =
            model.nodeIndex(QStringLiteral("arc_2")).data(Qt::ToolTipRole).toString();
        QVERIFY2(nodeTip.contains(QStringLiteral("src/beta_cpp/src/listener.cpp:11")),
                 qPrintable(nodeTip));
        QVERIFY(nodeTip.contains(QStringLiteral("beta_cpp::Listener")));
        QVERIFY(nodeTip.contains(QStringLiteral("rclcpp::Node")));

        const QString portTip = model.portIndex(QStringLiteral("arc_2"), QStringLiteral("ps1"))
                                    .data(Qt::ToolTipRole)
                                    .toString();
        QVERIFY2(portTip.contains(QStringLiteral("src/beta_cpp/src/listener.cpp:19")),
                 qPrintable(portTip));
        QVERIFY(portTip.contains(QStringLiteral("Service server")));
        QVERIFY(portTip.contains(QStringLiteral("std_srvs/srv/Trigger")));
        QVERIFY(portTip.contains(QStringLiteral("on_reset")));
        // a port made by a helper says how the node reaches it
        const QString viaTip = model.portIndex(QStringLiteral("arc_1"), QStringLiteral("p1"))
                                   .data(Qt::ToolTipRole)
                                   .toString();
        QVERIFY2(viaTip.contains(QStringLiteral("ChatBehaviour")), qPrintable(viaTip));
        QVERIFY2(viaTip.contains(
                     QStringLiteral("src/alpha_py/alpha_py/talker.py:20 → src/alpha_py/tree.py:4")),
                 qPrintable(viaTip));
        // tooltips are on every column, not just the name
        QCOMPARE(model
                     .portIndex(QStringLiteral("arc_2"), QStringLiteral("ps1"),
                                AtomicNodeModel::DetailsColumn)
                     .data(Qt::ToolTipRole)
                     .toString(),
                 portTip);
    }

    void descriptionEditIsUndoable()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QModelIndex description =
            model.nodeIndex(QStringLiteral("arc_2"), AtomicNodeModel::DescriptionColumn);
        QVERIFY(model.flags(description) & Qt::ItemIsEditable);
        QVERIFY(!(model.flags(description.siblingAtColumn(0)) & Qt::ItemIsEditable));
        QVERIFY(!(model.flags(model.portIndex(QStringLiteral("arc_2"), QStringLiteral("s1"),
                                              AtomicNodeModel::DescriptionColumn)) &
                  Qt::ItemIsEditable));
        QVERIFY(!model.setData(description.siblingAtColumn(0), QStringLiteral("x")));

        const AtomicNodeList before = doc.atomicNodes();
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QVERIFY(model.setData(description, QStringLiteral("Counts and resets.")));
        const AtomicNodeList after = doc.atomicNodes();
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.first().at(0).toModelIndex().row(), description.row());
        QCOMPARE(description.data().toString(), QStringLiteral("Counts and resets."));
        QCOMPARE(after.node(QStringLiteral("arc_2"))->description,
                 QStringLiteral("Counts and resets."));
        QVERIFY(!(before.nodes == after.nodes));

        doc.undoStack()->undo();
        QVERIFY(doc.atomicNodes().nodes == before.nodes);
        QCOMPARE(description.data().toString(), QStringLiteral("Counts messages."));
        QCOMPARE(changed.count(), 2);
        doc.undoStack()->redo();
        QVERIFY(doc.atomicNodes().nodes == after.nodes);
        QCOMPARE(description.data().toString(), QStringLiteral("Counts and resets."));

        // the same text again is no change and no command
        QVERIFY(model.setData(description, QStringLiteral("Counts and resets.")));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void resetsWithTheDocument()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        model.setData(model.nodeIndex(QStringLiteral("arc_1"), AtomicNodeModel::DescriptionColumn),
                      QStringLiteral("Greets."));
        QSignalSpy aboutToReset(&model, &QAbstractItemModel::modelAboutToBeReset);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);

        AtomicNodeList smaller = sampleList();
        smaller.packages.removeLast(); // alpha_py
        smaller.nodes.removeFirst();   // Talker
        doc.setAtomicNodes(smaller);
        QCOMPARE(aboutToReset.count(), 1);
        QCOMPARE(reset.count(), 1);
        QCOMPARE(model.rowCount(), 1);
        QCOMPARE(model.index(0, 0).data().toString(), QStringLiteral("beta_cpp"));
        QVERIFY(!model.nodeIndex(QStringLiteral("arc_1")).isValid());
        QCOMPARE(doc.undoStack()->count(), 0);

        // a node whose package has no package.xml still shows, under its package name
        AtomicNodeList orphan = sampleList();
        orphan.packages.clear();
        doc.setAtomicNodes(orphan);
        QCOMPARE(model.rowCount(), 2);
        QVERIFY(model.packageIndex(QStringLiteral("alpha_py")).isValid());
        QVERIFY(!model.evidence(model.packageIndex(QStringLiteral("alpha_py"))).isValid());
    }

    void innermostElementAtLine()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        const QString listener = QStringLiteral("src/beta_cpp/src/listener.cpp");
        QCOMPARE(model.indexAt(listener, 18),
                 model.portIndex(QStringLiteral("arc_2"), QStringLiteral("s1")));
        QCOMPARE(model.indexAt(listener, 19),
                 model.portIndex(QStringLiteral("arc_2"), QStringLiteral("ps1")));
        QCOMPARE(model.indexAt(listener, 25), model.nodeIndex(QStringLiteral("arc_2")));
        QVERIFY(!model.indexAt(listener, 45).isValid());
        QVERIFY(!model.indexAt(QStringLiteral("elsewhere.cpp"), 18).isValid());
        QCOMPARE(model.evidence(model.indexAt(listener, 20)).line, 19);
    }

    void filterMatchesNameAndType()
    {
        Document doc;
        doc.setAtomicNodes(sampleList());
        AtomicNodeModel model(&doc);
        NodeFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        QAbstractItemModelTester tester(&proxy,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);

        proxy.setFilterFixedString(QStringLiteral("listener"));
        QCOMPARE(proxy.rowCount(), 1);
        const QModelIndex beta = proxy.index(0, 0);
        QCOMPARE(beta.data().toString(), QStringLiteral("beta_cpp"));
        QCOMPARE(proxy.rowCount(beta), 1);                    // watchdog hidden
        QCOMPARE(proxy.rowCount(proxy.index(0, 0, beta)), 3); // a matching node keeps its ports

        proxy.setFilterFixedString(QStringLiteral("srv/Trigger")); // a type
        QCOMPARE(proxy.rowCount(), 1);
        const QModelIndex node = proxy.index(0, 0, proxy.index(0, 0));
        QCOMPARE(node.data().toString(), QStringLiteral("Listener"));
        QCOMPARE(proxy.rowCount(node), 1);
        QCOMPARE(proxy.index(0, 0, node).data().toString(), QStringLiteral("reset"));

        proxy.setFilterFixedString(QStringLiteral("on_echo")); // details are not searched
        QCOMPARE(proxy.rowCount(), 0);
        proxy.setFilterFixedString(QString());
        QCOMPARE(proxy.rowCount(), 2);
    }

    void diagnosticModelShowsMessages()
    {
        Document doc;
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.rowCount(), 0);
        doc.setAtomicNodes(sampleList());
        QCOMPARE(model.rowCount(), 1);
        const QModelIndex message = model.index(0, DiagnosticModel::MessageColumn);
        QCOMPARE(message.data().toString(),
                 QStringLiteral("The topic name of a publisher is not a literal."));
        QCOMPARE(model.index(0, DiagnosticModel::FileColumn).data().toString(),
                 QStringLiteral("src/beta_cpp/src/listener.cpp:22"));
        QVERIFY(model.index(0, DiagnosticModel::KindColumn)
                    .data()
                    .toString()
                    .startsWith(QStringLiteral("unresolved-name")));
        const QModelIndex severity = model.index(0, DiagnosticModel::SeverityColumn);
        QCOMPARE(severity.data().toString(), QStringLiteral("Warning"));
        QVERIFY(hasOpaquePixels(imageOf(severity.data(Qt::DecorationRole))));
        QVERIFY(message.data(Qt::ToolTipRole).toString().contains(QStringLiteral("Warning")));
    }
};

QTEST_MAIN(TestAtomicNodeModel)
#include "tst_atomicnodemodel.moc"
