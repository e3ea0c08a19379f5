#include "app/diagramfocus.h"

#include <QAction>
#include <QDockWidget>
#include <QGraphicsView>
#include <QMainWindow>
#include <QToolBar>

namespace rosarch {

DiagramFocus::DiagramFocus(QMainWindow *window, QDockWidget *diagramDock)
    : QObject(window), m_window(window), m_diagramDock(diagramDock),
      m_action(new QAction(tr("&Focus Diagram"), this))
{
    m_action->setObjectName(QStringLiteral("focusDiagramAction"));
    m_action->setCheckable(true);
    m_action->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D));
    m_action->setToolTip(tr("Give the composed diagram the whole window; again to bring the "
                            "other panels back (Ctrl+Shift+D)"));
    connect(m_action, &QAction::toggled, this, &DiagramFocus::setFocused);
}

void DiagramFocus::setFocused(bool focused)
{
    if (focused == isFocused())
        return;
    if (focused) {
        m_saved = m_window->saveState();
        m_diagramDock->setFloating(false);
        m_diagramDock->show();
        for (QDockWidget *dock : m_window->findChildren<QDockWidget *>())
            if (dock != m_diagramDock && dock->parentWidget() == m_window)
                dock->hide();
        for (QToolBar *bar : m_window->findChildren<QToolBar *>())
            if (bar->parentWidget() == m_window)
                bar->hide();
    } else {
        m_window->restoreState(std::exchange(m_saved, {}));
    }
    // The focus stays in the diagram: left to Qt, it lands in the first panel shown again, and
    // a table given the focus without a current row makes its first row current (the Log's
    // first finding then moved the source pane).
    if (auto *view = m_diagramDock->findChild<QGraphicsView *>())
        view->setFocus(Qt::OtherFocusReason);
    const QSignalBlocker block(m_action);
    m_action->setChecked(focused);
}

} // namespace rosarch
