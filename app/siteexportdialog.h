#pragma once

#include "site/sitegenerator.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace rosarch {

/// File → Export Architecture Site…: where the site goes and what `rosarch site` offers on the
/// command line (title, source-URL pattern, commit), remembered per workspace. It accepts only
/// options the generator can use: a pattern without {path}, or one with {commit} outside git
/// and without a commit, is refused with a sentence that says what to write.
class SiteExportDialog : public QDialog
{
    Q_OBJECT
public:
    explicit SiteExportDialog(const QString &workspace, QWidget *parent = nullptr);

    /// The options the site is written with (commit and repository prefix from git when the
    /// pattern needs them); valid after the dialog was accepted.
    SiteOptions options() const { return m_options; }
    /// Why the options cannot be used as they are ("" when they can).
    QString problem() const;

    void accept() override;

private:
    void chooseFolder();
    void updateProblem();

    QString m_workspace;
    QLineEdit *m_folder = nullptr;
    QLineEdit *m_title = nullptr;
    QLineEdit *m_sourceUrl = nullptr;
    QLineEdit *m_commit = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    SiteOptions m_options;
};

} // namespace rosarch
