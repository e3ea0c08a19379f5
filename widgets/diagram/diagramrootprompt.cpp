#include "widgets/diagram/diagramrootprompt.h"
#include "core/visibletext.h"
#include "widgets/diagram/diagramrootpicker.h"

#include <QDir>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

namespace rosarch {

DiagramRootPrompt::DiagramRootPrompt(QWidget *parent)
    : QFrame(parent), m_list(new QListWidget(this))
{
    setObjectName(QStringLiteral("diagramRootPrompt"));
    auto *question = new QLabel(
        tr("<b>Which system do you want to see?</b><br>This workspace has several root launch "
           "files and none is named like a bringup. Choose one; the header's list switches "
           "later, and the choice is remembered."),
        this);
    question->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(16, 16, 16, 16);
    layout->addWidget(question);
    layout->addWidget(m_list, 1);
    const auto choose = [this](QListWidgetItem *item) {
        if (item)
            Q_EMIT rootChosen(item->data(Qt::UserRole).toString());
    };
    connect(m_list, &QListWidget::itemActivated, this, choose);
    connect(m_list, &QListWidget::itemClicked, this, choose);
}

void DiagramRootPrompt::setRoots(const QList<LaunchRoot> &roots)
{
    m_list->clear();
    for (const LaunchRoot &r : roots) {
        auto *item = new QListWidgetItem(tr("%1    %2")
                                             .arg(DiagramRootPicker::entryText(r),
                                                  visibleText(QDir::toNativeSeparators(r.file))),
                                         m_list);
        item->setData(Qt::UserRole, r.instanceId);
    }
}

} // namespace rosarch
