#include "app/siteexportdialog.h"
#include "app/appsettings.h"
#include "site/sitesource.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace rosarch {

namespace {
const QString kFolder = QStringLiteral("folder");
const QString kTitle = QStringLiteral("title");
const QString kSourceUrl = QStringLiteral("sourceUrl");
const QString kCommit = QStringLiteral("commit");
} // namespace

SiteExportDialog::SiteExportDialog(const QString &workspace, QWidget *parent)
    : QDialog(parent), m_workspace(workspace)
{
    setWindowTitle(tr("Export Architecture Site"));
    const QVariantMap stored = AppSettings().siteExport(workspace);

    m_folder = new QLineEdit(this);
    m_folder->setObjectName(QStringLiteral("siteFolder"));
    m_folder->setText(
        stored.value(kFolder, QDir(QFileInfo(workspace).path()).filePath(QStringLiteral("site")))
            .toString());
    auto *browse = new QToolButton(this);
    browse->setText(tr("Browse…"));
    browse->setToolTip(tr("Choose the folder for the site"));
    connect(browse, &QToolButton::clicked, this, &SiteExportDialog::chooseFolder);
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);

    m_title = new QLineEdit(this);
    m_title->setObjectName(QStringLiteral("siteTitle"));
    m_title->setPlaceholderText(QDir(workspace).dirName());
    m_title->setText(stored.value(kTitle).toString());

    m_sourceUrl = new QLineEdit(this);
    m_sourceUrl->setObjectName(QStringLiteral("siteSourceUrl"));
    m_sourceUrl->setPlaceholderText(
        QStringLiteral("https://github.com/org/repo/blob/{commit}/{path}#L{line}"));
    m_sourceUrl->setToolTip(
        tr("Link source lines to hosted source: {path} is the file's path in the git "
           "repository, {line} its line, {commit} the commit. Empty: relative links to the "
           "workspace's files."));
    m_sourceUrl->setText(stored.value(kSourceUrl).toString());

    m_commit = new QLineEdit(this);
    m_commit->setObjectName(QStringLiteral("siteCommit"));
    m_commit->setPlaceholderText(tr("the repository's HEAD"));
    m_commit->setToolTip(tr("A commit, tag or branch for {commit}; needed when the workspace "
                            "is not in a git repository."));
    m_commit->setText(stored.value(kCommit).toString());

    auto *form = new QFormLayout;
    // A row of a layout takes no buddy by itself: the label names the line edit for its key.
    auto *folderLabel = new QLabel(tr("&Folder:"), this);
    folderLabel->setBuddy(m_folder);
    form->addRow(folderLabel, folderRow);
    form->addRow(tr("&Title:"), m_title);
    form->addRow(tr("&Source URL:"), m_sourceUrl);
    form->addRow(tr("&Commit:"), m_commit);

    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("siteProblem"));
    m_problem->setWordWrap(true);
    m_problem->setTextFormat(Qt::PlainText);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &SiteExportDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("Writes the accepted model as a static HTML site: a page per "
                                "system, node, topic and launch file, the findings and a "
                                "search. The folder must be empty, new, or a site written "
                                "before."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(m_buttons);
    setMinimumWidth(560);

    for (QLineEdit *edit : {m_folder, m_sourceUrl, m_commit})
        connect(edit, &QLineEdit::textChanged, this, &SiteExportDialog::updateProblem);
    updateProblem();
}

QString SiteExportDialog::problem() const
{
    if (m_folder->text().trimmed().isEmpty())
        return tr("Choose a folder for the site.");
    const QString pattern = m_sourceUrl->text().trimmed();
    if (!pattern.isEmpty() && !pattern.contains(QLatin1String("{path}")))
        return tr("The source URL needs {path} in its pattern, where the file's path goes, "
                  "e.g. https://github.com/org/repo/blob/{commit}/{path}#L{line}.");
    return {};
}

void SiteExportDialog::updateProblem()
{
    const QString text = problem();
    m_problem->setText(text);
    m_problem->setVisible(!text.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(text.isEmpty());
}

void SiteExportDialog::chooseFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Export Architecture Site To"),
        m_folder->text().isEmpty() ? QFileInfo(m_workspace).path() : m_folder->text());
    if (!folder.isEmpty())
        m_folder->setText(QDir::toNativeSeparators(folder));
}

void SiteExportDialog::accept()
{
    if (!problem().isEmpty())
        return;
    SiteOptions options;
    options.workspace = m_workspace;
    options.siteFolder = QDir::fromNativeSeparators(m_folder->text().trimmed());
    options.title = m_title->text().trimmed().isEmpty() ? QDir(m_workspace).dirName()
                                                        : m_title->text().trimmed();
    options.sourceUrl = m_sourceUrl->text().trimmed();
    if (!options.sourceUrl.isEmpty()) {
        // As `rosarch site` does: {path} is relative to the repository's root, {commit} is its
        // HEAD unless a commit is given.
        QString head;
        QString prefix;
        SiteSource::gitInfo(m_workspace, &head, &prefix);
        options.repositoryPrefix = prefix;
        options.commit = m_commit->text().trimmed().isEmpty() ? head : m_commit->text().trimmed();
        if (SiteSource::needsCommit(options.sourceUrl) && options.commit.isEmpty()) {
            m_problem->setText(tr("The source URL has {commit}, but %1 is not in a git "
                                  "repository: give the commit, tag or branch to link to.")
                                   .arg(QDir::toNativeSeparators(m_workspace)));
            m_problem->setVisible(true);
            m_commit->setFocus();
            return;
        }
    }
    m_options = options;
    AppSettings().setSiteExport(m_workspace, {{kFolder, m_folder->text().trimmed()},
                                              {kTitle, m_title->text().trimmed()},
                                              {kSourceUrl, options.sourceUrl},
                                              {kCommit, m_commit->text().trimmed()}});
    QDialog::accept();
}

} // namespace rosarch
