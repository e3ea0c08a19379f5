#include "app/aboutdialog.h"
#include "widgets/icons.h"

#include <Qsci/qsciglobal.h>
#include <tree_sitter/api.h>

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace rosarch {

AboutDialog::AboutDialog(QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("About rosarch"));

    auto *icon = new QLabel(this);
    icon->setPixmap(Icons::application().pixmap(64, 64));
    icon->setAlignment(Qt::AlignTop);

    auto *text = new QLabel(this);
    text->setTextFormat(Qt::RichText);
    text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    text->setWordWrap(true);
    text->setText(QStringLiteral("<h2>rosarch %1</h2><p>%2</p><p><b>%3</b></p>%4")
                      .arg(QStringLiteral(ROSARCH_VERSION),
                           tr("Recovers the architecture of a ROS 2 workspace from its "
                              "source code, build files and launch files, without building "
                              "or running it."),
                           tr("Built with"), versionsHtml()));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);

    auto *row = new QHBoxLayout;
    row->addWidget(icon);
    row->addSpacing(12);
    row->addWidget(text, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(row);
    layout->addWidget(buttons);
    setMinimumWidth(440);
}

QString AboutDialog::versionsHtml()
{
    const QString row = QStringLiteral("<tr><td>%1</td><td>&nbsp;&nbsp;%2</td></tr>");
    QString rows;
    rows += row.arg(tr("rosarch"), QStringLiteral(ROSARCH_VERSION));
    rows += row.arg(tr("Qt"),
                    tr("%1 (built with %2)")
                        .arg(QString::fromLatin1(qVersion()), QStringLiteral(QT_VERSION_STR)));
    rows += row.arg(tr("tree-sitter language ABI"), QString::number(TREE_SITTER_LANGUAGE_VERSION));
    rows += row.arg(tr("QScintilla"), QStringLiteral(QSCINTILLA_VERSION_STR));
    return QStringLiteral("<table>%1</table>").arg(rows);
}

} // namespace rosarch
