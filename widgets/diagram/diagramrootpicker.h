#pragma once

#include "diagram/rootchoice.h"

#include <QComboBox>

namespace rosarch {

/// The root launch files in the diagram's header, with how many launch files each includes;
/// type to filter (any part of the name). Choosing one reports it; the panel shows it.
class DiagramRootPicker : public QComboBox
{
    Q_OBJECT
public:
    explicit DiagramRootPicker(QWidget *parent = nullptr);

    void setRoots(const QList<LaunchRoot> &roots);
    QList<LaunchRoot> roots() const { return m_roots; }
    /// Shows `instanceId` as the current root without reporting it ("" = none).
    void setCurrentRoot(const QString &instanceId);
    QString currentRoot() const;
    /// The text of a root's entry: "bringup — 12 includes".
    static QString entryText(const LaunchRoot &root);
    /// Fits the list's width to the entries first.
    void showPopup() override;

Q_SIGNALS:
    /// A person chose a root (by the list, or by typing and Enter).
    void rootChosen(const QString &instanceId);

protected:
    void focusOutEvent(QFocusEvent *event) override;

private:
    /// The current entry, whole, above what the picker is for.
    void updateToolTip();
    enum class Fit
    {
        Now,
        IfCheap ///< only when few entries or a list is open
    };
    /// Makes the lists as wide as their widest entry.
    void fitListWidth(Fit when);

    QList<LaunchRoot> m_roots;
    bool m_widthFitted = false; ///< the list's width fits the entries (done when it opens)
};

} // namespace rosarch
