#include "widgets/launchargumentsdialog.h"
#include "widgets/icons.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPalette>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rosarch {

namespace {

constexpr int kUserAddedRole = Qt::UserRole + 1; ///< a row the person added (name editable)

QTableWidgetItem *readOnlyItem(const QString &text)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

} // namespace

LaunchArgumentsDialog::LaunchArgumentsDialog(QWidget *parent)
    : QDialog(parent), m_root(new QComboBox(this)), m_table(new QTableWidget(0, ColumnCount, this)),
      m_hint(new QLabel(this)), m_removeButton(new QPushButton(tr("&Remove"), this))
{
    setWindowTitle(tr("Launch Arguments"));
    setWindowIcon(Icons::launchArguments());

    auto *intro = new QLabel(
        tr("Stage 2 reads the launch files as <code>ros2 launch</code> would run them: choose "
           "the launch file to start from and give values to its arguments. Empty values use "
           "the default."),
        this);
    intro->setWordWrap(true);

    m_root->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_root->setToolTip(tr("The launch file stage 2 starts from"));
    connect(m_root, &QComboBox::currentIndexChanged, this, [this] {
        storeValues();
        rebuildTable();
    });
    auto *form = new QFormLayout;
    form->addRow(tr("&Root launch file:"), m_root);

    m_table->setHorizontalHeaderLabels(
        {tr("Argument"), tr("Value"), tr("Default"), tr("Description"), tr("Declared in")});
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 10);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::AllEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->horizontalHeader()->setSectionResizeMode(DescriptionColumn, QHeaderView::Stretch);
    m_table->setColumnWidth(NameColumn, 170);
    m_table->setColumnWidth(ValueColumn, 160);
    m_table->setColumnWidth(DefaultColumn, 120);
    m_table->setColumnWidth(FileColumn, 160);
    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        if (!m_rebuilding)
            storeValues();
    });
    connect(m_table, &QTableWidget::currentCellChanged, this, [this](int row) {
        m_removeButton->setEnabled(row >= 0 && m_table->item(row, NameColumn) &&
                                   m_table->item(row, NameColumn)->data(kUserAddedRole).toBool());
    });

    m_hint->setWordWrap(true);
    m_hint->setForegroundRole(QPalette::PlaceholderText);

    auto *add = new QPushButton(tr("&Add Argument"), this);
    add->setToolTip(tr("Give a value to an argument the list does not show"));
    connect(add, &QPushButton::clicked, this, &LaunchArgumentsDialog::addArgument);
    m_removeButton->setEnabled(false);
    m_removeButton->setToolTip(tr("Remove an argument you added"));
    connect(m_removeButton, &QPushButton::clicked, this, &LaunchArgumentsDialog::removeArgument);
    auto *reset = new QPushButton(tr("Use &Defaults"), this);
    reset->setToolTip(tr("Clear every value so that each argument uses its default"));
    connect(reset, &QPushButton::clicked, this, &LaunchArgumentsDialog::resetValues);
    auto *tableButtons = new QHBoxLayout;
    tableButtons->addWidget(add);
    tableButtons->addWidget(m_removeButton);
    tableButtons->addStretch(1);
    tableButtons->addWidget(reset);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Run Stage &2"));
    buttons->button(QDialogButtonBox::Ok)->setIcon(Icons::runLaunch());
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        storeValues();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_hint);
    layout->addLayout(tableButtons);
    layout->addWidget(buttons);
    resize(860, 440);
    setLaunchDependencies({}, {});
}

void LaunchArgumentsDialog::setLaunchDependencies(const LaunchDependencies &launch,
                                                  const QString &analysedRoot)
{
    m_arguments = launch.arguments;
    m_analysedRoot = analysedRoot;
    const QString root = selectedRoot();
    m_rebuilding = true;
    m_root->clear();
    m_root->addItem(Icons::launchFile(), tr("All top-level launch files"), QString());
    QStringList files = launch.launchFiles;
    if (!analysedRoot.isEmpty() && !files.contains(analysedRoot))
        files << analysedRoot;
    for (const QString &file : std::as_const(files))
        m_root->addItem(Icons::launchFile(), file, file);
    m_root->setCurrentIndex(std::max(0, m_root->findData(root)));
    m_rebuilding = false;
    rebuildTable();
}

void LaunchArgumentsDialog::setOptions(const LaunchOptions &options)
{
    m_values = options.arguments;
    m_externals = options.externals; // not edited here: kept as they were
    m_rebuilding = true;
    int index = m_root->findData(options.rootFile);
    if (index < 0) {
        m_root->addItem(Icons::launchFile(), options.rootFile, options.rootFile);
        index = m_root->count() - 1;
    }
    m_root->setCurrentIndex(index);
    m_rebuilding = false;
    rebuildTable();
}

LaunchOptions LaunchArgumentsDialog::options() const
{
    LaunchOptions options;
    options.rootFile = selectedRoot();
    options.externals = m_externals;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QTableWidgetItem *name = m_table->item(row, NameColumn);
        const QTableWidgetItem *value = m_table->item(row, ValueColumn);
        if (name && value && !name->text().trimmed().isEmpty() && !value->text().isEmpty())
            options.arguments.insert(name->text().trimmed(), value->text());
    }
    return options;
}

QString LaunchArgumentsDialog::selectedRoot() const
{
    return m_root->currentIndex() < 0 ? QString() : m_root->currentData().toString();
}

void LaunchArgumentsDialog::storeValues()
{
    if (m_rebuilding)
        return;
    // The table is the truth for the names it shows (a renamed row drops its old name).
    for (const QString &name : std::as_const(m_tableNames))
        m_values.remove(name);
    m_tableNames.clear();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QTableWidgetItem *name = m_table->item(row, NameColumn);
        const QTableWidgetItem *value = m_table->item(row, ValueColumn);
        if (!name || !value || name->text().trimmed().isEmpty())
            continue;
        m_tableNames << name->text().trimmed();
        if (!value->text().isEmpty())
            m_values.insert(name->text().trimmed(), value->text());
    }
}

void LaunchArgumentsDialog::rebuildTable()
{
    if (m_rebuilding)
        return;
    m_rebuilding = true;
    const QString root = selectedRoot();
    // One row per name: a name two roots declare takes one value.
    QMap<QString, QList<const LaunchArgument *>> declared;
    QStringList order;
    for (const LaunchArgument &a : std::as_const(m_arguments)) {
        if (!root.isEmpty() && a.launchFile != root)
            continue;
        if (!declared.contains(a.name))
            order << a.name;
        declared[a.name] << &a;
    }
    for (auto it = m_values.cbegin(); it != m_values.cend(); ++it)
        if (!declared.contains(it.key()))
            order << it.key();

    m_table->setRowCount(0);
    m_table->setRowCount(int(order.size()));
    const QBrush dim = QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
    for (int row = 0; row < order.size(); ++row) {
        const QString &name = order[row];
        const QList<const LaunchArgument *> decl = declared.value(name);
        auto *nameItem = readOnlyItem(name);
        auto *valueItem = new QTableWidgetItem(m_values.value(name));
        valueItem->setToolTip(
            tr("The value stage 2 gives %1; leave empty for the default").arg(name));
        QStringList files;
        for (const LaunchArgument *a : decl)
            if (!files.contains(a->launchFile))
                files << a->launchFile;
        if (decl.isEmpty()) {
            nameItem->setData(kUserAddedRole, true);
            nameItem->setFlags(nameItem->flags() | Qt::ItemIsEditable);
            m_table->setItem(row, DefaultColumn, readOnlyItem(QString()));
            auto *description =
                readOnlyItem(root.isEmpty() ? tr("Not declared by a top-level launch file")
                                            : tr("Not declared by this launch file"));
            description->setForeground(dim);
            m_table->setItem(row, DescriptionColumn, description);
            m_table->setItem(row, FileColumn, readOnlyItem(QString()));
        } else {
            const LaunchArgument &a = *decl.first();
            auto *defaultItem = readOnlyItem(a.hasDefault ? a.defaultValue : tr("(none)"));
            if (!a.hasDefault) {
                defaultItem->setForeground(dim);
                nameItem->setIcon(Icons::severity(Diagnostic::Severity::Warning));
                nameItem->setToolTip(tr("%1 has no default: without a value the analysis "
                                        "continues with a guess.")
                                         .arg(name));
            } else {
                nameItem->setToolTip(a.description.isEmpty() ? name : a.description);
            }
            m_table->setItem(row, DefaultColumn, defaultItem);
            auto *description = readOnlyItem(a.description);
            description->setToolTip(a.description);
            m_table->setItem(row, DescriptionColumn, description);
            QStringList names;
            for (const QString &f : std::as_const(files))
                names << f.section(QLatin1Char('/'), -1);
            auto *file = readOnlyItem(names.join(QStringLiteral(", ")));
            file->setToolTip(a.evidence.isValid()
                                 ? QStringLiteral("%1:%2").arg(a.evidence.file).arg(a.evidence.line)
                                 : files.join(QLatin1Char('\n')));
            m_table->setItem(row, FileColumn, file);
        }
        m_table->setItem(row, NameColumn, nameItem);
        m_table->setItem(row, ValueColumn, valueItem);
    }

    m_tableNames = order;
    const bool knowsRoot = root == m_analysedRoot || !declared.isEmpty();
    if (!knowsRoot)
        m_hint->setText(tr("The arguments %1 declares are listed once stage 2 has run with it "
                           "as the root: run it, then open this dialog again. Values you add "
                           "here are used.")
                            .arg(root.section(QLatin1Char('/'), -1)));
    else if (order.isEmpty())
        m_hint->setText(tr("No launch arguments are declared. Add one to give it a value."));
    else
        m_hint->clear();
    m_hint->setVisible(!m_hint->text().isEmpty());
    m_rebuilding = false;
}

void LaunchArgumentsDialog::addArgument()
{
    const int row = m_table->rowCount();
    m_rebuilding = true;
    m_table->insertRow(row);
    auto *name = new QTableWidgetItem;
    name->setData(kUserAddedRole, true);
    m_table->setItem(row, NameColumn, name);
    m_table->setItem(row, ValueColumn, new QTableWidgetItem);
    for (int c : {DefaultColumn, DescriptionColumn, FileColumn})
        m_table->setItem(row, c, readOnlyItem(QString()));
    m_rebuilding = false;
    m_table->setCurrentCell(row, NameColumn);
    m_table->editItem(name);
}

void LaunchArgumentsDialog::removeArgument()
{
    const int row = m_table->currentRow();
    const QTableWidgetItem *name = row >= 0 ? m_table->item(row, NameColumn) : nullptr;
    if (!name || !name->data(kUserAddedRole).toBool())
        return;
    m_values.remove(name->text().trimmed());
    m_tableNames.removeAll(name->text().trimmed());
    m_table->removeRow(row);
}

void LaunchArgumentsDialog::resetValues()
{
    m_values.clear();
    m_rebuilding = true;
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (QTableWidgetItem *value = m_table->item(row, ValueColumn))
            value->setText(QString());
    m_rebuilding = false;
}

} // namespace rosarch
