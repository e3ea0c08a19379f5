#include "widgets/parameterpanel.h"

#include "widgets/parametertablemodel.h"

#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

namespace rosarch {

ParameterPanel::ParameterPanel(QWidget *parent)
    : QWidget(parent), m_summary(new QLabel(this)), m_filter(new QLineEdit(this)),
      m_table(new QTableView(this)), m_model(new ParameterTableModel(this)),
      m_proxy(new QSortFilterProxyModel(this))
{
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_filter->setPlaceholderText(tr("Filter parameters"));
    m_filter->setClearButtonEnabled(true);
    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterKeyColumn(-1); // any column
    m_proxy->setSortCaseSensitivity(Qt::CaseInsensitive);
    m_table->setModel(m_proxy);
    m_table->setSortingEnabled(true);
    m_table->sortByColumn(ParameterTableModel::NameColumn, Qt::AscendingOrder);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->setAccessibleName(tr("Parameters"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_summary);
    layout->addWidget(m_filter);
    layout->addWidget(m_table, 1);
    connect(m_filter, &QLineEdit::textChanged, m_proxy,
            &QSortFilterProxyModel::setFilterFixedString);
    connect(m_table, &QTableView::activated, this, [this](const QModelIndex &index) {
        const QModelIndex source = m_proxy->mapToSource(index);
        const QString file =
            m_model->data(source, ParameterTableModel::EvidenceFileRole).toString();
        if (!file.isEmpty())
            emit evidenceRequested(
                file, m_model->data(source, ParameterTableModel::EvidenceLineRole).toInt());
    });
    setMessage(tr("Select a node instance in the launch tree, or a node class, to see its "
                  "parameters."));
}

void ParameterPanel::showParameters(const QString &title,
                                    const QList<InstanceParameter> &parameters, bool instance)
{
    m_model->setParameters(parameters);
    int declared = 0;
    int undeclared = 0;
    for (const InstanceParameter &p : parameters)
        (p.declared ? declared : undeclared) += 1;
    QString text = instance ? tr("%1: %n parameters declared", nullptr, declared).arg(title)
                            : tr("%1 declares %n parameters", nullptr, declared).arg(title);
    if (undeclared > 0)
        text += tr(", %n given but not declared", nullptr, undeclared);
    if (parameters.isEmpty())
        text = instance ? tr("%1 has no parameters the analysis could find.").arg(title)
                        : tr("%1 declares no parameters the analysis could find.").arg(title);
    m_summary->setText(text);
    m_table->setVisible(!parameters.isEmpty());
    m_filter->setVisible(!parameters.isEmpty());
    m_table->resizeColumnsToContents();
    for (int c = 0; c < ParameterTableModel::DescriptionColumn; ++c)
        m_table->setColumnWidth(c, std::min(m_table->columnWidth(c), 260));
}

void ParameterPanel::setMessage(const QString &message)
{
    m_model->setParameters({});
    m_summary->setText(message);
    m_table->hide();
    m_filter->hide();
}

QString ParameterPanel::summary() const
{
    return m_summary->text();
}

} // namespace rosarch
