#pragma once

#include "core/evidence.h"

#include <QModelIndex>
#include <QObject>
#include <QPointer>

class QMenu;

namespace rosarch {

class AtomicNodeModel;
class AtomicNodePanel;
class LaunchTreeModel;
class LaunchTreePanel;
class SourceView;

/// Keeps the atomic node tree, the launch tree and the source view on the same element:
/// selecting a row shows its evidence; a node instance also selects its class; moving the
/// cursor in the source selects the innermost element of that line. Selections made to
/// follow another view never echo back.
class Traceability : public QObject
{
    Q_OBJECT
public:
    Traceability(AtomicNodeModel *nodeModel, AtomicNodePanel *nodePanel,
                 LaunchTreeModel *launchModel, LaunchTreePanel *launchPanel, SourceView *sourceView,
                 QObject *parent = nullptr);

    /// Selects a node (or one of its ports) in the atomic tree, showing its evidence.
    void selectNode(const QString &nodeId, const QString &portId = {});
    /// Selects a launch-file or node instance in the launch tree, showing its evidence.
    void selectLaunchItem(const QString &instanceId);
    /// Selects the class in the atomic tree and shows its definition (Go to Class).
    void goToClass(const QString &classId);

    void showEvidence(const Evidence &evidence);

    /// The current rows, as ids ("" for none): for remembering them across runs.
    QString currentNodeId() const;
    QString currentPortId() const;
    QString currentLaunchId() const;

Q_SIGNALS:
    /// The source view could not show `evidence` (the file is missing or unreadable).
    void evidenceUnavailable(const rosarch::Evidence &evidence);
    /// The user chose a port of a class in the atomic tree (not a row that followed another
    /// view or that selectNode() chose).
    void portSelected(const QString &nodeId, const QString &portId);

private:
    void onNodeSelected(const QModelIndex &sourceIndex);
    void onLaunchItemSelected(const QModelIndex &sourceIndex);
    void onSourceLineChanged(const QString &file, int line);
    /// The innermost element of file:line in each class that has one as narrow as any other
    /// class's (several for a helper's line that makes a port of each class), sorted by
    /// "package/Class".
    QModelIndexList usersOfLine(const QString &file, int line) const;
    /// A menu at the source's cursor naming the classes of `users`; the one picked is selected.
    void offerClassChoice(const QModelIndexList &users);
    /// Selects the class of a node instance in the atomic tree without moving the source.
    void followClass(const QModelIndex &launchIndex);

    AtomicNodeModel *m_nodeModel;
    AtomicNodePanel *m_nodePanel;
    LaunchTreeModel *m_launchModel;
    LaunchTreePanel *m_launchPanel;
    SourceView *m_sourceView;
    bool m_syncing = false;   ///< a view follows another; do not echo back
    bool m_selecting = false; ///< selectNode() chose the row, not the user
    QPointer<QMenu> m_choice; ///< the open choice of a class for a shared line
};

} // namespace rosarch
