#pragma once

#include <QByteArray>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;

namespace rosarch {

/// View → Focus Diagram (Ctrl+Shift+D): the composed diagram takes the whole window, every
/// other panel and the toolbar hidden; the command again puts the window back as it was.
class DiagramFocus : public QObject
{
    Q_OBJECT
public:
    DiagramFocus(QMainWindow *window, QDockWidget *diagramDock);

    QAction *action() const { return m_action; }
    bool isFocused() const { return !m_saved.isEmpty(); }
    void setFocused(bool focused);

private:
    QMainWindow *m_window;
    QDockWidget *m_diagramDock;
    QAction *m_action;
    QByteArray m_saved; ///< the window's docks and toolbars before the focus
};

} // namespace rosarch
