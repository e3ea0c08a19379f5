// From the source to the model on a helper several classes share: a line of the helper that
// makes a port of each class leads to the class the person came from, not to whichever class
// comes first.
#include "app/traceability.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"

#include <QtTest>

using namespace rosarch;

namespace {

const QString kHelper = QStringLiteral("src/shared/include/shared/make_ports.hpp");

Evidence at(const QString &file, int line, int endLine = 0)
{
    return {file, line, 5, endLine > 0 ? endLine : line, 60};
}

/// Two classes of one package whose publisher is made by the same helper line.
AtomicNodeList sharedHelper()
{
    AtomicNodeList list;
    list.workspaceRoot = QStringLiteral("/ws");
    RosPackage shared;
    shared.name = QStringLiteral("shared");
    shared.buildType = QStringLiteral("ament_cmake");
    shared.path = QStringLiteral("src/shared");
    shared.evidence = at(QStringLiteral("src/shared/package.xml"), 3);
    list.packages = {shared};
    const auto node = [&](const QString &id, const QString &name, const QString &file) {
        AtomicNode n;
        n.id = id;
        n.className = name;
        n.nodeName = name.toLower();
        n.packageName = shared.name;
        n.compileType = AtomicNode::CompileType::Cpp;
        n.evidence = at(file, 10, 40);
        n.ports = {test::gui::port(QStringLiteral("p1"), PortKind::Publisher,
                                   QStringLiteral("status"), QStringLiteral("std_msgs/msg/String"),
                                   {}, at(kHelper, 12)),
                   test::gui::port(QStringLiteral("s1"), PortKind::Subscriber,
                                   name.toLower() + QStringLiteral("_in"),
                                   QStringLiteral("std_msgs/msg/String"), {}, at(file, 20))};
        return n;
    };
    list.nodes = {node(QStringLiteral("arc_1"), QStringLiteral("Alpha"),
                       QStringLiteral("src/shared/src/alpha.cpp")),
                  node(QStringLiteral("arc_2"), QStringLiteral("Beta"),
                       QStringLiteral("src/shared/src/beta.cpp"))};
    return list;
}

} // namespace

class TestHelperTrace : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void aSharedHelperLineKeepsTheClassThePersonCameFrom()
    {
        Document document;
        document.setAtomicNodes(sharedHelper());
        AtomicNodeModel nodeModel(&document);
        AtomicNodePanel nodePanel;
        nodePanel.setModel(&nodeModel);
        LaunchTreeModel launchModel(&document);
        LaunchTreePanel launchPanel;
        launchPanel.setModel(&launchModel);
        SourceView source;
        Traceability trace(&nodeModel, &nodePanel, &launchModel, &launchPanel, &source);
        const auto currentClass = [&] {
            const AtomicNode *n = nodeModel.node(nodePanel.currentSourceIndex());
            return n ? n->id : QString();
        };
        const auto currentPort = [&] {
            const Port *p = nodeModel.port(nodePanel.currentSourceIndex());
            return p ? p->id : QString();
        };

        // on Beta's own subscriber, the cursor goes to the helper's line: Beta's publisher
        nodePanel.selectSourceIndex(
            nodeModel.portIndex(QStringLiteral("arc_2"), QStringLiteral("s1")));
        QCOMPARE(currentClass(), QStringLiteral("arc_2"));
        Q_EMIT source.cursorLineChanged(kHelper, 12);
        QCOMPARE(currentClass(), QStringLiteral("arc_2"));
        QCOMPARE(currentPort(), QStringLiteral("p1"));

        // and from Alpha, Alpha's
        nodePanel.selectSourceIndex(nodeModel.nodeIndex(QStringLiteral("arc_1")));
        Q_EMIT source.cursorLineChanged(kHelper, 12);
        QCOMPARE(currentClass(), QStringLiteral("arc_1"));
        QCOMPARE(currentPort(), QStringLiteral("p1"));

        // a line of one class only leads to that class, wherever the person was
        Q_EMIT source.cursorLineChanged(QStringLiteral("src/shared/src/beta.cpp"), 20);
        QCOMPARE(currentClass(), QStringLiteral("arc_2"));
        QCOMPARE(currentPort(), QStringLiteral("s1"));
    }
};

QTEST_MAIN(TestHelperTrace)
#include "tst_helpertrace.moc"
