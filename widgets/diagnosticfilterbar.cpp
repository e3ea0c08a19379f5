#include "widgets/diagnosticfilterbar.h"
#include "core/diagnostickind.h"
#include "widgets/flowlayout.h"
#include "widgets/icons.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>
#include <QTimer>
#include <QToolButton>

namespace rosarch {

DiagnosticFilterBar::DiagnosticFilterBar(DiagnosticModel *model, QWidget *parent)
    : QWidget(parent), m_model(model), m_errors(new QToolButton(this)),
      m_warnings(new QToolButton(this)), m_infos(new QToolButton(this)),
      m_kind(new QComboBox(this)), m_package(new QComboBox(this)), m_search(new QLineEdit(this)),
      m_hidden(new QCheckBox(tr("Hidden"), this)), m_accepted(new QCheckBox(tr("Accepted"), this)),
      m_grouping(new QComboBox(this))
{
    // Wraps into rows when the dock is narrow: the bar must not set the window's width.
    auto *layout = new FlowLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    // what belongs together stays on one row
    const auto group = [this] {
        auto *box = new QWidget(this);
        auto *row = new QHBoxLayout(box);
        row->setContentsMargins(0, 0, 0, 0);
        return std::make_pair(box, row);
    };
    const auto [severityBox, severityRow] = group();
    const std::pair<QToolButton *, Diagnostic::Severity> severities[] = {
        {m_errors, Diagnostic::Severity::Error},
        {m_warnings, Diagnostic::Severity::Warning},
        {m_infos, Diagnostic::Severity::Info}};
    for (const auto &[button, severity] : severities) {
        button->setCheckable(true);
        button->setChecked(true);
        button->setAutoRaise(true);
        button->setIcon(Icons::severity(severity));
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setToolTip(tr("Show or hide findings of this severity"));
        connect(button, &QToolButton::toggled, this, &DiagnosticFilterBar::apply);
        severityRow->addWidget(button);
    }
    layout->addWidget(severityBox);
    m_kind->setToolTip(tr("Show only findings of one kind"));
    m_kind->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_kind->setMinimumContentsLength(8);
    m_package->setToolTip(tr("Show only findings in one package"));
    m_package->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_package->setMinimumContentsLength(6);
    m_search->setPlaceholderText(tr("Search findings"));
    m_search->setClearButtonEnabled(true);
    m_search->setMinimumWidth(90);
    m_search->setToolTip(tr("Show findings whose message, file, kind or package contains this"));
    m_hidden->setToolTip(tr("Also show findings you hid (drawn grey)"));
    m_accepted->setToolTip(tr("Also show findings you accepted (drawn grey)"));
    m_grouping->addItem(tr("None"), int(DiagnosticModel::Grouping::None));
    m_grouping->addItem(tr("Kind"), int(DiagnosticModel::Grouping::Kind));
    m_grouping->addItem(tr("Package"), int(DiagnosticModel::Grouping::Package));
    m_grouping->setToolTip(tr("Group the findings by kind or by package"));
    layout->addWidget(m_kind);
    layout->addWidget(m_package);
    layout->addWidget(m_search);
    layout->setStretchWidget(m_search);
    const auto [showBox, showRow] = group();
    showRow->addWidget(m_hidden);
    showRow->addWidget(m_accepted);
    layout->addWidget(showBox);
    const auto [groupingBox, groupingRow] = group();
    groupingRow->addWidget(new QLabel(tr("Group by:"), groupingBox));
    groupingRow->addWidget(m_grouping);
    layout->addWidget(groupingBox);

    // Typing filters after a short pause, not on every key, with thousands of findings.
    auto *typing = new QTimer(this);
    typing->setSingleShot(true);
    typing->setInterval(150);
    connect(typing, &QTimer::timeout, this, &DiagnosticFilterBar::apply);
    connect(m_search, &QLineEdit::textChanged, typing, qOverload<>(&QTimer::start));
    connect(m_search, &QLineEdit::returnPressed, this, &DiagnosticFilterBar::apply);
    for (QComboBox *combo : {m_kind, m_package})
        connect(combo, &QComboBox::currentIndexChanged, this, &DiagnosticFilterBar::apply);
    for (QCheckBox *box : {m_hidden, m_accepted})
        connect(box, &QCheckBox::toggled, this, &DiagnosticFilterBar::apply);
    connect(m_grouping, &QComboBox::currentIndexChanged, this, [this] {
        m_model->setGrouping(DiagnosticModel::Grouping(m_grouping->currentData().toInt()));
    });
    connect(m_model, &DiagnosticModel::findingsChanged, this, &DiagnosticFilterBar::refreshCounts);
    refreshCounts();
}

QToolButton *DiagnosticFilterBar::severityButton(Diagnostic::Severity severity) const
{
    return severity == Diagnostic::Severity::Error     ? m_errors
           : severity == Diagnostic::Severity::Warning ? m_warnings
                                                       : m_infos;
}

void DiagnosticFilterBar::apply()
{
    DiagnosticModel::Filter f;
    f.errors = m_errors->isChecked();
    f.warnings = m_warnings->isChecked();
    f.infos = m_infos->isChecked();
    f.code = m_kind->currentData().toString();
    f.package = m_package->currentData().toString();
    f.text = m_search->text().trimmed();
    f.showHidden = m_hidden->isChecked();
    f.showAccepted = m_accepted->isChecked();
    m_model->setFilter(f);
}

QVariantMap DiagnosticFilterBar::state() const
{
    return {{QStringLiteral("errors"), m_errors->isChecked()},
            {QStringLiteral("warnings"), m_warnings->isChecked()},
            {QStringLiteral("infos"), m_infos->isChecked()},
            {QStringLiteral("kind"), m_kind->currentData().toString()},
            {QStringLiteral("package"), m_package->currentData().toString()},
            {QStringLiteral("text"), m_search->text()},
            {QStringLiteral("hidden"), m_hidden->isChecked()},
            {QStringLiteral("accepted"), m_accepted->isChecked()},
            {QStringLiteral("grouping"), m_grouping->currentData().toInt()}};
}

void DiagnosticFilterBar::restoreState(const QVariantMap &state)
{
    if (state.isEmpty())
        return;
    {
        const QSignalBlocker b1(m_errors), b2(m_warnings), b3(m_infos), b4(m_kind), b5(m_package),
            b6(m_search), b7(m_hidden), b8(m_accepted), b9(m_grouping);
        m_errors->setChecked(state.value(QStringLiteral("errors"), true).toBool());
        m_warnings->setChecked(state.value(QStringLiteral("warnings"), true).toBool());
        m_infos->setChecked(state.value(QStringLiteral("infos"), true).toBool());
        // a kind or package with no findings (yet) stays chosen: refreshCounts offers it with 0
        for (const auto &[combo, key] : {std::pair{m_kind, QStringLiteral("kind")},
                                         std::pair{m_package, QStringLiteral("package")}}) {
            const QString value = state.value(key).toString();
            if (!value.isEmpty() && combo->findData(value) < 0)
                combo->addItem(value, value);
            combo->setCurrentIndex(std::max(combo->findData(value), 0));
        }
        m_search->setText(state.value(QStringLiteral("text")).toString());
        m_hidden->setChecked(state.value(QStringLiteral("hidden")).toBool());
        m_accepted->setChecked(state.value(QStringLiteral("accepted")).toBool());
        m_grouping->setCurrentIndex(
            std::max(m_grouping->findData(state.value(QStringLiteral("grouping")).toInt()), 0));
    }
    m_model->setGrouping(DiagnosticModel::Grouping(m_grouping->currentData().toInt()));
    apply();
    refreshCounts();
}

void DiagnosticFilterBar::refreshCounts()
{
    const QLocale locale;
    m_errors->setText(
        tr("Errors %1").arg(locale.toString(m_model->severityCount(Diagnostic::Severity::Error))));
    m_warnings->setText(
        tr("Warnings %1")
            .arg(locale.toString(m_model->severityCount(Diagnostic::Severity::Warning))));
    m_infos->setText(
        tr("Info %1").arg(locale.toString(m_model->severityCount(Diagnostic::Severity::Info))));

    const auto fill = [&](QComboBox *combo, QMap<QString, int> counts, const QString &all,
                          bool kinds) {
        const QSignalBlocker block(combo);
        const QString current = combo->currentData().toString();
        int total = 0;
        for (int n : std::as_const(counts))
            total += n;
        // The kind or package chosen stays offered (with 0) while nothing of it is left.
        if (!current.isEmpty() && !counts.contains(current))
            counts.insert(current, 0);
        combo->clear();
        combo->addItem(QStringLiteral("%1 (%2)").arg(all, locale.toString(total)), QString());
        for (const auto &[key, count] : counts.asKeyValueRange()) {
            const QString label =
                kinds ? QStringLiteral("%1 — %2").arg(key, DiagnosticKind::of(key).title)
                : key.isEmpty() ? tr("(no package)")
                                : key;
            combo->addItem(QStringLiteral("%1 (%2)").arg(label, locale.toString(count)), key);
            if (kinds)
                combo->setItemData(combo->count() - 1, DiagnosticKind::of(key).help,
                                   Qt::ToolTipRole);
        }
        combo->setCurrentIndex(std::max(combo->findData(current), 0));
    };
    fill(m_kind, m_model->codeCounts(), tr("All kinds"), true);
    fill(m_package, m_model->packageCounts(), tr("All packages"), false);
}

} // namespace rosarch
