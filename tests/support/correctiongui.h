#pragma once
// The views and the controller of the main window on one Document, for the GUI tests of
// corrections (tst_corrections, tst_correctionpanels).
#include "app/correctioncontroller.h"
#include "app/correctioneditor.h"
#include "app/inspectorpresenter.h"
#include "app/traceability.h"
#include "diagram/diagramlayouter.h"
#include "document/document.h"
#include "pipeline/recovery.h"
#include "support/acceptedwait.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/correctiondialog.h"
#include "widgets/correctionmodel.h"
#include "widgets/correctionpanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/inspectorpanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QDirIterator>
#include <QMenu>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTreeView>
#include <QUndoStack>
#include <QtTest>

#include <functional>
#include <memory>

namespace rosarch::test {

/// The views and the controller of the main window, on one Document.
struct Gui
{
    Document document;
    AtomicNodeModel nodeModel{&document};
    LaunchTreeModel launchModel{&document};
    CorrectionModel correctionModel{&document};
    AtomicNodePanel nodePanel;
    LaunchTreePanel launchPanel;
    DiagramLayouter layouter;
    DiagramPanel diagramPanel{&layouter};
    SourceView sourceView;
    InspectorPanel inspector;
    CorrectionPanel correctionPanel;
    std::unique_ptr<Traceability> traceability;
    QWidget window;
    std::unique_ptr<CorrectionController> controller;
    std::function<bool(CorrectionDialog &)> answer; ///< the person at the dialog
    QStringList asked;                              ///< the dialogs' titles, in order

    Gui()
    {
        nodePanel.setModel(&nodeModel);
        launchPanel.setModel(&launchModel);
        correctionPanel.setModel(&correctionModel);
        traceability = std::make_unique<Traceability>(&nodeModel, &nodePanel, &launchModel,
                                                      &launchPanel, &sourceView);
        controller = std::make_unique<CorrectionController>(&document, &nodePanel, &launchPanel,
                                                            &diagramPanel, traceability.get(),
                                                            &inspector, &correctionPanel, &window);
        controller->editor()->setDialogHandler([this](CorrectionDialog &d) {
            asked.append(d.windowTitle());
            return answer ? answer(d) : false;
        });
        QObject::connect(&document, &Document::changed, &diagramPanel, [this] {
            diagramPanel.setArchitecture(document.accepted().architecture);
        });
    }
    ~Gui() { controller.reset(); }

    QString classId(const QString &className) const
    {
        for (const AtomicNode &n : document.atomicNodes().nodes)
            if (n.className == className)
                return n.id;
        return {};
    }
    QString portId(const QString &className, const QString &name) const
    {
        acceptedSettled(document); // what the views show follows it
        for (const AtomicNode &n : document.accepted().nodes.nodes)
            if (n.className == className)
                for (const Port &p : n.ports)
                    if (p.name == name || p.nameExpression == name)
                        return n.id + u'/' + p.id;
        return {};
    }
    const NodeInstance *instance(const QString &name) const
    {
        acceptedSettled(document); // what the views show follows it
        for (const NodeInstance &n : document.accepted().launch.nodes)
            if (n.nodeName == name)
                return &n;
        return nullptr;
    }
    QString instanceId(const QString &name) const
    {
        const NodeInstance *n = instance(name);
        return n ? n->id : QString();
    }
    QString launchFileId(const QString &fileName) const
    {
        acceptedSettled(document); // what the views show follows it
        for (const LaunchFileInstance &lf : document.accepted().launch.instances)
            if (lf.file.endsWith(fileName))
                return lf.id;
        return {};
    }
    /// What the node list shows in the name column of a port row.
    QString portRow(const QString &id) const
    {
        acceptedSettled(document); // what the views show follows it
        return nodeModel.portIndex(id.section(u'/', 0, 0), id.section(u'/', 1)).data().toString();
    }
    QString portType(const QString &id) const
    {
        acceptedSettled(document); // what the views show follows it
        return nodeModel
            .portIndex(id.section(u'/', 0, 0), id.section(u'/', 1), AtomicNodeModel::TypeColumn)
            .data()
            .toString();
    }
    QStringList portNames(const QString &className) const
    {
        acceptedSettled(document); // what the views show follows it
        QStringList names;
        const QModelIndex node = nodeModel.nodeIndex(classId(className));
        for (int r = 0; r < nodeModel.rowCount(node); ++r)
            names.append(nodeModel.index(r, 0, node).data().toString());
        return names;
    }
    /// The names of the launch tree's node rows under every launch file, in order.
    QStringList launchNodes() const
    {
        acceptedSettled(document); // what the views show follows it
        QStringList names;
        std::function<void(const QModelIndex &)> walk = [&](const QModelIndex &parent) {
            for (int r = 0; r < launchModel.rowCount(parent); ++r) {
                const QModelIndex i = launchModel.index(r, 0, parent);
                if (launchModel.kind(i) == LaunchTreeModel::ItemKind::Node)
                    names.append(i.data().toString());
                if (launchModel.kind(i) != LaunchTreeModel::ItemKind::Parameters)
                    walk(i);
            }
        };
        walk({});
        return names;
    }
};

inline bool copyFixture(const QString &from, const QString &to)
{
    QDirIterator it(from, QDir::Files | QDir::NoDotAndDotDot, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString target = QDir(to).filePath(QDir(from).relativeFilePath(file));
        if (!QDir().mkpath(QFileInfo(target).path()) || !QFile::copy(file, target))
            return false;
    }
    return true;
}

inline Recovery recover(const QString &root)
{
    LaunchOptions options;
    options.rootFile = QStringLiteral("src/cart_base/launch/cart.launch.py");
    return recoverWorkspace(root, options);
}

/// What each correction test starts from: the fixture workspace copied and recovered once
/// (in each test's initTestCase), and a fresh Gui per test.
class CorrectionTestBase : public QObject
{
protected:
    QTemporaryDir m_dir;
    QString m_ws;
    Recovery m_recovery;

    /// initTestCase() of a test: the project_corrections fixture copied and recovered once.
    void setUpFixture()
    {
        QStandardPaths::setTestModeEnabled(true);
        qputenv("ROSARCH_AUTHOR", "tester");
        QVERIFY(m_dir.isValid());
        m_ws = m_dir.filePath(QStringLiteral("ws"));
        QVERIFY(copyFixture(QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/ws"), m_ws));
        m_recovery = recover(m_ws);
        QVERIFY(!m_recovery.nodes.nodes.isEmpty());
        QVERIFY(!m_recovery.launch.nodes.isEmpty());
    }

    /// init() of a test: every test starts without a project (the autosave of the last one is
    /// not read).
    static void forgetProjects()
    {
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
    }

    std::unique_ptr<Gui> open()
    {
        auto gui = std::make_unique<Gui>();
        gui->document.setRecovery(m_recovery);
        return gui;
    }

    /// Undo and redo the last step; `check(true)` holds after redo, `check(false)` after undo.
    static void roundTrip(Gui &gui, const std::function<void(bool)> &check)
    {
        const Recovery done = acceptedNow(gui.document); // the views follow it
        check(true);
        gui.document.undoStack()->undo();
        QVERIFY(acceptedSettled(gui.document));
        check(false);
        gui.document.undoStack()->redo();
        QVERIFY(acceptedSettled(gui.document));
        check(true);
        QCOMPARE(gui.document.accepted(), done);
    }
};

} // namespace rosarch::test
