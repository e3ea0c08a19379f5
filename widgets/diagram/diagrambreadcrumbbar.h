#pragma once

#include <QList>
#include <QWidget>

class QHBoxLayout;
class QToolButton;

namespace rosarch {

/// "root › included › …": one button per composite from the root down to the one shown.
class DiagramBreadcrumbBar : public QWidget
{
    Q_OBJECT
public:
    struct Crumb
    {
        QString id;
        QString label;
        QString toolTip;
    };

    explicit DiagramBreadcrumbBar(QWidget *parent = nullptr);

    /// `note`: a quiet line after the crumbs saying whose view this is ("" for none).
    void setPath(const QList<Crumb> &path, const QString &note = {},
                 const QString &noteToolTip = {});
    QList<Crumb> path() const { return m_path; }
    /// The button of a crumb, for tests and keyboard navigation; null when absent.
    QToolButton *button(const QString &id) const;
    /// The width the whole path and note would take.
    QSize sizeHint() const override;

Q_SIGNALS:
    /// A person clicked a crumb other than the last one.
    void crumbClicked(const QString &id);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    /// Shows what fits of the path: the note only when all of it fits, each name elided in
    /// its middle when the names do not.
    void fitToWidth();

    QHBoxLayout *m_layout;
    int m_fullWidth = 0;
    QList<Crumb> m_path;
    QList<QWidget *> m_widgets;
};

} // namespace rosarch
