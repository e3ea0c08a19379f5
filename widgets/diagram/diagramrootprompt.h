#pragma once

#include "diagram/rootchoice.h"

#include <QFrame>

class QListWidget;

namespace rosarch {

/// Asks, without blocking the window, which root launch file to show first when the
/// workspace has several and nothing says which one matters: a short question and the list.
class DiagramRootPrompt : public QFrame
{
    Q_OBJECT
public:
    explicit DiagramRootPrompt(QWidget *parent = nullptr);

    void setRoots(const QList<LaunchRoot> &roots);
    QListWidget *list() const { return m_list; }

Q_SIGNALS:
    void rootChosen(const QString &instanceId);

private:
    QListWidget *m_list;
};

} // namespace rosarch
