#pragma once

#include "core/launchdependencies.h"
#include "launch/launchanalyzer.h"

#include <QDialog>
#include <QMap>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace rosarch {

/// Stages → Launch Arguments…: the root launch file stage 2 starts from and the values of
/// the launch arguments the roots declare. Shows what it is given and returns the person's
/// choice as LaunchOptions; storing and re-running is the caller's business.
class LaunchArgumentsDialog : public QDialog
{
    Q_OBJECT
public:
    enum Column
    {
        NameColumn,
        ValueColumn,
        DefaultColumn,
        DescriptionColumn,
        FileColumn,
        ColumnCount
    };

    explicit LaunchArgumentsDialog(QWidget *parent = nullptr);

    /// Every launch file found (workspace-relative) and the arguments the last stage 2 run
    /// listed, which declared them from `analysedRoot` ("" = every top-level launch file).
    void setLaunchDependencies(const LaunchDependencies &launch, const QString &analysedRoot);
    /// Preselects the root and fills in the values.
    void setOptions(const LaunchOptions &options);
    /// The person's choice: the root and every non-empty value shown in the table.
    LaunchOptions options() const;

    QComboBox *rootCombo() const { return m_root; }
    QTableWidget *table() const { return m_table; }
    QLabel *hintLabel() const { return m_hint; }

private:
    void rebuildTable();
    void storeValues();
    void addArgument();
    void removeArgument();
    void resetValues();
    QString selectedRoot() const;

    QList<LaunchArgument> m_arguments;
    QString m_analysedRoot;
    QMap<QString, QString> m_values; ///< name → value the person typed, kept across roots
    QStringList m_tableNames;        ///< the names the table showed when last read
    QComboBox *m_root;
    QList<ExpectedExternal> m_externals; ///< the project's, handed back unchanged
    QTableWidget *m_table;
    QLabel *m_hint;
    QPushButton *m_removeButton;
    bool m_rebuilding = false;
};

} // namespace rosarch
