#include "widgets/diagram/diagramrootpicker.h"
#include "core/visibletext.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QDir>
#include <QLineEdit>

#include <algorithm>

namespace rosarch {

namespace {

/// Up to this many entries the lists are fitted at once; more wait until a list opens.
constexpr int kMeasuredAtOnce = 40;

} // namespace

DiagramRootPicker::DiagramRootPicker(QWidget *parent) : QComboBox(parent)
{
    setObjectName(QStringLiteral("diagramRootPicker"));
    setEditable(true);
    setInsertPolicy(QComboBox::NoInsert);
    // Long launch-file names (autoware's) would push the breadcrumbs away: the list is wider.
    setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    setMinimumContentsLength(22);
    view()->setTextElideMode(Qt::ElideNone);
    setMaxVisibleItems(20);
    completer()->setFilterMode(Qt::MatchContains);
    completer()->setCompletionMode(QCompleter::PopupCompletion);
    completer()->setCaseSensitivity(Qt::CaseInsensitive);
    lineEdit()->setPlaceholderText(tr("Root launch file"));
    connect(this, &QComboBox::currentIndexChanged, this, &DiagramRootPicker::updateToolTip);
    updateToolTip();
    // Typing opens the completer's list: it is fitted then, as the combo box's own when shown.
    connect(lineEdit(), &QLineEdit::textEdited, this, [this] { fitListWidth(Fit::Now); });
    connect(this, &QComboBox::activated, this, [this](int index) {
        const QString id = itemData(index).toString();
        if (!id.isEmpty())
            Q_EMIT rootChosen(id);
    });
}

QString DiagramRootPicker::entryText(const LaunchRoot &root)
{
    const QString stem = visibleText(root.stem); // from a file name: no control characters
    if (root.executable)                         // its main builds the nodes: it includes nothing
        return root.nodes == 1 ? tr("%1 — executable, 1 node").arg(stem)
                               : tr("%1 — executable, %2 nodes").arg(stem).arg(root.nodes);
    return root.includes == 1 ? tr("%1 — 1 include").arg(stem)
                              : tr("%1 — %2 includes").arg(stem).arg(root.includes);
}

void DiagramRootPicker::setRoots(const QList<LaunchRoot> &roots)
{
    if (roots == m_roots)
        return;
    const QString current = currentRoot();
    const QSignalBlocker blocker(this);
    m_roots = roots;
    clear();
    // By name, as a person looks a name up (the analysis lists them by path, which put
    // autoware's roots in no order the list shows).
    QList<const LaunchRoot *> byName;
    for (const LaunchRoot &r : roots)
        byName << &r;
    std::stable_sort(byName.begin(), byName.end(), [](const LaunchRoot *a, const LaunchRoot *b) {
        return QString::compare(a->stem, b->stem, Qt::CaseInsensitive) < 0;
    });
    for (const LaunchRoot *root : std::as_const(byName)) {
        const LaunchRoot &r = *root;
        addItem(entryText(r), r.instanceId);
        setItemData(
            count() - 1,
            tr("%1\n%2 launch files included, %3 nodes started, %4 unresolved")
                .arg(visibleText(QDir::toNativeSeparators(r.file.isEmpty() ? r.stem : r.file)))
                .arg(r.includes)
                .arg(r.nodes)
                .arg(r.unresolved),
            Qt::ToolTipRole);
    }
    setEnabled(!roots.isEmpty());
    m_widthFitted = false; // measuring hundreds of entries is left for when a list opens
    fitListWidth(Fit::IfCheap);
    setCurrentRoot(current);
}

void DiagramRootPicker::fitListWidth(Fit when)
{
    if (m_widthFitted)
        return;
    if (when == Fit::IfCheap && count() > kMeasuredAtOnce && !view()->isVisible() &&
        !completer()->popup()->isVisible())
        return; // fitted when a list opens (showPopup, or typing)
    m_widthFitted = true;
    view()->setMinimumWidth(view()->sizeHintForColumn(0) + 24);
    completer()->popup()->setMinimumWidth(view()->minimumWidth());
}

void DiagramRootPicker::showPopup()
{
    fitListWidth(Fit::Now);
    QComboBox::showPopup();
}

void DiagramRootPicker::setCurrentRoot(const QString &instanceId)
{
    const QSignalBlocker blocker(this);
    const int index = findData(instanceId);
    setCurrentIndex(index);
    updateToolTip(); // the signal is blocked
    if (index < 0)
        lineEdit()->clear();
    lineEdit()->setCursorPosition(0); // the name's start, not its end, when it is cut
}

void DiagramRootPicker::updateToolTip()
{
    // the whole entry, when a narrow header cuts it
    const QString hint =
        tr("The root launch file whose system the diagram shows; type to find one");
    const int index = currentIndex();
    setToolTip(index < 0 ? hint : itemText(index) + QLatin1Char('\n') + hint);
}

QString DiagramRootPicker::currentRoot() const
{
    return currentData().toString();
}

void DiagramRootPicker::focusOutEvent(QFocusEvent *event)
{
    QComboBox::focusOutEvent(event);
    // A search typed and left: show the root again rather than a half-typed name.
    if (currentIndex() >= 0 && lineEdit()->text() != itemText(currentIndex())) {
        lineEdit()->setText(itemText(currentIndex()));
        lineEdit()->setCursorPosition(0);
    }
}

} // namespace rosarch
