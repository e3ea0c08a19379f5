// From the source to the model on a helper several classes share: a line of the helper that
// makes a port of each class leads to the class the person came from, not to whichever class
// comes first; coming from no class, or from one that does not use the line, the person picks
// the class in a menu that names exactly the classes using it.
#include "app/traceability.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"

#include <QMenu>
#include <Qsci/qsciscintilla.h>
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
    // Listed out of name order: the choice sorts them. Gamma uses the helper at another line.
    list.nodes = {node(QStringLiteral("arc_2"), QStringLiteral("Beta"),
                       QStringLiteral("src/shared/src/beta.cpp")),
                  node(QStringLiteral("arc_1"), QStringLiteral("Alpha"),
                       QStringLiteral("src/shared/src/alpha.cpp")),
                  node(QStringLiteral("arc_3"), QStringLiteral("Gamma"),
                       QStringLiteral("src/shared/src/gamma.cpp"))};
    list.nodes[2].ports[0].evidence = at(kHelper, 30);
    return list;
}

} // namespace

/// The node list, the launch tree and the source pane of one document, traced together.
struct Views
{
    Document document;
    AtomicNodeModel nodeModel{&document};
    AtomicNodePanel nodePanel;
    LaunchTreeModel launchModel{&document};
    LaunchTreePanel launchPanel;
    SourceView source;
    Traceability trace{&nodeModel, &nodePanel, &launchModel, &launchPanel, &source};

    Views()
    {
        document.setAtomicNodes(sharedHelper());
        nodePanel.setModel(&nodeModel);
        launchPanel.setModel(&launchModel);
    }
    QString currentClass() const
    {
        const AtomicNode *n = nodeModel.node(nodePanel.currentSourceIndex());
        return n ? n->id : QString();
    }
    QString currentPort() const
    {
        const Port *p = nodeModel.port(nodePanel.currentSourceIndex());
        return p ? p->id : QString();
    }
    /// The open choice of a class, or null.
    QMenu *choice() const
    {
        auto *menu = source.findChild<QMenu *>(QStringLiteral("classChoiceMenu"));
        return menu && menu->isVisible() ? menu : nullptr;
    }
    /// The classes the choice offers, as shown.
    static QStringList offered(const QMenu *menu)
    {
        QStringList names;
        for (const QAction *a : menu->actions())
            if (!a->isSeparator())
                names << a->text();
        return names;
    }
    static QAction *entry(const QMenu *menu, const QString &name)
    {
        for (QAction *a : menu->actions())
            if (!a->isSeparator() && a->text() == name)
                return a;
        return nullptr;
    }
};

class TestHelperTrace : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void aSharedHelperLineKeepsTheClassThePersonCameFrom()
    {
        Views views;
        AtomicNodeModel &nodeModel = views.nodeModel;
        AtomicNodePanel &nodePanel = views.nodePanel;
        SourceView &source = views.source;
        const auto currentClass = [&] { return views.currentClass(); };
        const auto currentPort = [&] { return views.currentPort(); };

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
        QVERIFY(!views.choice()); // the current class decided each time: nothing to choose
    }

    void withoutADecidingClassThePersonChoosesAmongTheUsers_data()
    {
        QTest::addColumn<QString>("from"); // the class current before, "" for none
        QTest::addColumn<QString>("pick");
        QTest::addColumn<QString>("expected");
        QTest::newRow("no class, Beta")
            << QString() << QStringLiteral("shared/Beta") << QStringLiteral("arc_2");
        QTest::newRow("no class, Alpha")
            << QString() << QStringLiteral("shared/Alpha") << QStringLiteral("arc_1");
        QTest::newRow("from Gamma, Alpha")
            << QStringLiteral("arc_3") << QStringLiteral("shared/Alpha") << QStringLiteral("arc_1");
    }

    void withoutADecidingClassThePersonChoosesAmongTheUsers()
    {
        QFETCH(QString, from);
        QFETCH(QString, pick);
        QFETCH(QString, expected);
        Views views;
        views.nodePanel.show(); // where the person works
        views.source.show();
        if (!from.isEmpty())
            views.nodePanel.selectSourceIndex(views.nodeModel.nodeIndex(from));
        QCOMPARE(views.currentClass(), from);

        Q_EMIT views.source.cursorLineChanged(kHelper, 12);
        QMenu *menu = views.choice();
        QVERIFY2(menu, "the person is asked which class");
        // exactly the classes whose port the line makes, sorted, not Gamma (another line)
        QCOMPARE(Views::offered(menu),
                 (QStringList{QStringLiteral("shared/Alpha"), QStringLiteral("shared/Beta")}));
        QCOMPARE(views.currentClass(), from); // nothing chosen for the person meanwhile

        QAction *entry = Views::entry(menu, pick);
        QVERIFY(entry);
        entry->trigger();
        QCOMPARE(views.currentClass(), expected);
        QCOMPARE(views.currentPort(), QStringLiteral("p1"));
        QTRY_VERIFY(!views.choice());
    }

    void readingWithTheArrowKeysIsNotInterrupted()
    {
        Views views;
        views.source.show();
        QVERIFY(QTest::qWaitForWindowExposed(&views.source));
        // a key in the editor: the move that follows is the person reading on
        QTest::keyClick(views.source.editor()->viewport(), Qt::Key_Down);
        QVERIFY(views.source.movedByKey());
        Q_EMIT views.source.cursorLineChanged(kHelper, 12);
        QVERIFY(!views.choice());
        QCOMPARE(views.currentClass(), QString()); // nothing chosen for the person either
        // a click on the same line asks
        QTest::mouseClick(views.source.editor()->viewport(), Qt::LeftButton, {}, QPoint(20, 5));
        QVERIFY(!views.source.movedByKey());
        Q_EMIT views.source.cursorLineChanged(kHelper, 12);
        QVERIFY(views.choice());
    }

    void aLineOfOneUserGoesThereWithoutAsking()
    {
        Views views;
        views.nodePanel.selectSourceIndex(views.nodeModel.nodeIndex(QStringLiteral("arc_1")));
        Q_EMIT views.source.cursorLineChanged(kHelper, 30); // Gamma's publisher only
        QVERIFY(!views.choice());
        QCOMPARE(views.currentClass(), QStringLiteral("arc_3"));
        QCOMPARE(views.currentPort(), QStringLiteral("p1"));
    }
};

QTEST_MAIN(TestHelperTrace)
#include "tst_helpertrace.moc"
