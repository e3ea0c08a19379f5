// Document: findings a person hid or accepted, kept in the project by stable key.
#include "document/document.h"
#include "document/findingmarkcommand.h"

#include <QCoreApplication>

namespace rosarch {

int Document::markFindings(const QStringList &keys, FindingMark::Status status,
                           const QString &reason)
{
    FindingMarkCommand::Marks before;
    FindingMarkCommand::Marks after;
    // Whole seconds: what the project file keeps.
    const QDateTime now =
        QDateTime::fromSecsSinceEpoch(QDateTime::currentSecsSinceEpoch(), Qt::UTC);
    for (const QString &key : keys) {
        const FindingMark *old = m_project.finding(key);
        if (key.isEmpty() || (old && old->status == status && old->reason == reason) ||
            std::any_of(after.cbegin(), after.cend(),
                        [&](const auto &m) { return m.first == key; }))
            continue;
        before.append({key, old ? std::optional<FindingMark>(*old) : std::nullopt});
        after.append({key, FindingMark{key, status, reason, author(), now}});
    }
    if (after.isEmpty())
        return 0;
    const QString text =
        status == FindingMark::Status::Accepted
            ? QCoreApplication::translate("rosarch::Document", "Accept Findings (%1)")
                  .arg(after.size())
            : QCoreApplication::translate("rosarch::Document", "Hide Findings (%1)")
                  .arg(after.size());
    m_undoStack.push(new FindingMarkCommand(this, before, after, text));
    return int(after.size());
}

int Document::unmarkFindings(const QStringList &keys)
{
    FindingMarkCommand::Marks before;
    FindingMarkCommand::Marks after;
    for (const QString &key : keys) {
        const FindingMark *old = m_project.finding(key);
        if (!old || std::any_of(after.cbegin(), after.cend(),
                                [&](const auto &m) { return m.first == key; }))
            continue;
        before.append({key, *old});
        after.append({key, std::nullopt});
    }
    if (after.isEmpty())
        return 0;
    m_undoStack.push(new FindingMarkCommand(
        this, before, after,
        QCoreApplication::translate("rosarch::Document", "Restore Findings (%1)")
            .arg(after.size())));
    return int(after.size());
}

void Document::replaceFindingMarks(
    const QList<std::pair<QString, std::optional<FindingMark>>> &marks)
{
    for (const auto &change : marks) {
        const QString &key = change.first;
        m_project.findings.removeIf([&](const FindingMark &m) { return m.key == key; });
        if (change.second)
            m_project.findings.append(*change.second);
    }
    std::sort(m_project.findings.begin(), m_project.findings.end(),
              [](const FindingMark &a, const FindingMark &b) { return a.key < b.key; });
    markDecisionsChanged();
    emitChange(DocumentChange::Findings);
}

} // namespace rosarch
