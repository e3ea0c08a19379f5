#pragma once

#include "widgets/talkersearch.h"

#include <QWidget>

class QLabel;
class QTreeWidget;
class QTreeWidgetItem;

namespace rosarch {

/// "Talkers": who publishes and who subscribes to a topic (serves and calls a service or an
/// action), one group per resolved name counting node instances (the active ones), one row per
/// node instance with its ports under it. Selecting a row
/// asks to go to that instance; the panel keeps its list while the user walks it.
class TalkersPanel : public QWidget
{
    Q_OBJECT
public:
    explicit TalkersPanel(QWidget *parent = nullptr);

    /// Shows `groups` for `subject` ("topic /scan", "port p1 of Camera") inside `scope` (the
    /// composite's launch file stem), with a `note` under the summary.
    void showTalkers(const QString &subject, const QString &scope, const QList<TalkerGroup> &groups,
                     const QString &note = {});
    /// A message instead of talkers (nothing clicked yet, or nothing found).
    void setMessage(const QString &message);

    QTreeWidget *tree() const { return m_tree; }
    QString summary() const;

    /// The rows' data: the node instance id and the port id.
    enum Role
    {
        InstanceIdRole = Qt::UserRole + 1,
        PortIdRole,
    };

Q_SIGNALS:
    /// A talker row became current: go to that instance and port.
    void talkerSelected(const QString &instanceId, const QString &portId);

private:
    void onCurrentItemChanged(QTreeWidgetItem *current);

    QLabel *m_summary;
    QTreeWidget *m_tree;
    bool m_filling = false; ///< rows are being replaced; no row is chosen by the user
};

} // namespace rosarch
