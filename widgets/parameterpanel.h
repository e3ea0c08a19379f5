#pragma once

#include "core/parameterview.h"

#include <QWidget>

class QLabel;
class QLineEdit;
class QSortFilterProxyModel;
class QTableView;

namespace rosarch {

class ParameterTableModel;

/// "Parameters": the parameters of the node instance selected in the launch tree (declared
/// ones joined with the value in effect and where it is set) or those a node class declares,
/// as a table whose columns sort, with a filter. Activating a row asks to show where its value
/// is set (else its declaration).
class ParameterPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterPanel(QWidget *parent = nullptr);

    /// Shows `parameters` under `title` ("/controller_server (ControllerServer)").
    void showParameters(const QString &title, const QList<InstanceParameter> &parameters,
                        bool instance);
    /// A message instead of a table (nothing selected, no parameters).
    void setMessage(const QString &message);

    QTableView *table() const { return m_table; }
    ParameterTableModel *model() const { return m_model; }
    QSortFilterProxyModel *proxy() const { return m_proxy; }
    QLineEdit *filter() const { return m_filter; }
    QString summary() const;

Q_SIGNALS:
    /// A row was activated: show where its value is set, else its declaration.
    void evidenceRequested(const QString &file, int line);

private:
    QLabel *m_summary;
    QLineEdit *m_filter;
    QTableView *m_table;
    ParameterTableModel *m_model;
    QSortFilterProxyModel *m_proxy;
};

} // namespace rosarch
