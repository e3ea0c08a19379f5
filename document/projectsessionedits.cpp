// ProjectSession: a person's edits kept in the project: corrections (blueprint §5) and the
// marks of findings a person hid or accepted.
#include "document/correctioncommand.h"
#include "document/document.h"
#include "document/findingmarkcommand.h"
#include "document/projectsession.h"

#include <QCoreApplication>

#include <pwd.h>
#include <unistd.h>

namespace rosarch {

QString ProjectSession::author()
{
    const QString configured = qEnvironmentVariable("ROSARCH_AUTHOR");
    if (!configured.isEmpty())
        return configured;
    const QString user = qEnvironmentVariable("USER", qEnvironmentVariable("USERNAME"));
    if (!user.isEmpty())
        return user;
    // A session without USER (a desktop launcher, a service): the account's own name.
    if (const passwd *account = ::getpwuid(::getuid()); account && account->pw_name)
        return QString::fromLocal8Bit(account->pw_name);
    return QStringLiteral("unknown");
}

bool ProjectSession::prepare(Correction *correction, int offset) const
{
    if (correction->target.isEmpty() || StableKeys::family(correction->target).isEmpty())
        return false;
    if (correction->id.isEmpty()) {
        Project p;
        p.corrections = m_project.corrections;
        QString id = p.nextCorrectionId();
        id = QStringLiteral("c%1").arg(id.mid(1).toInt() + offset);
        correction->id = id;
    }
    if (correction->author.isEmpty())
        correction->author = author();
    if (!correction->time.isValid())
        correction->time = QDateTime::currentDateTimeUtc();
    correction->time = correction->time.toUTC();
    correction->time.setTime(QTime(correction->time.time().hour(), correction->time.time().minute(),
                                   correction->time.time().second())); // ISO 8601 seconds
    return true;
}

QString ProjectSession::addCorrection(Correction correction)
{
    if (!prepare(&correction, 0))
        return {};
    const QString id = correction.id;
    m_document->undoStack()->push(new CorrectionCommand(
        this, CorrectionCommand::Action::Add, correction, int(m_project.corrections.size())));
    return id;
}

QStringList ProjectSession::addCorrections(const QList<Correction> &corrections,
                                           const QString &text)
{
    QStringList ids;
    auto *macro = new QUndoCommand(text);
    int index = int(m_project.corrections.size());
    for (Correction c : corrections) {
        if (!prepare(&c, int(ids.size())))
            continue;
        ids << c.id;
        new CorrectionCommand(this, CorrectionCommand::Action::Add, c, index++, macro);
    }
    if (ids.isEmpty()) {
        delete macro;
        return ids;
    }
    m_document->undoStack()->push(macro);
    return ids;
}

bool ProjectSession::removeCorrection(const QString &id)
{
    for (int i = 0; i < m_project.corrections.size(); ++i)
        if (m_project.corrections.at(i).id == id) {
            m_document->undoStack()->push(new CorrectionCommand(
                this, CorrectionCommand::Action::Remove, m_project.corrections.at(i), i));
            return true;
        }
    return false;
}

void ProjectSession::setNodeDescription(const QString &nodeId, const QString &description)
{
    const AtomicNode *node = m_document->atomicNodes().node(nodeId);
    if (!node || node->description == description)
        return;
    // a correction like any other: kept in the project by key, so a re-run keeps it
    Correction c;
    c.kind = Correction::Kind::Describe;
    c.target = keyOf(nodeId);
    c.oldValue = node->description;
    c.newValue = description;
    addCorrection(c);
}

const QList<Orphan> &ProjectSession::orphans() const
{
    return m_document->corrected().orphans;
}

void ProjectSession::insertCorrection(int index, const Correction &correction)
{
    m_project.corrections.insert(std::clamp(index, 0, int(m_project.corrections.size())),
                                 correction);
    m_document->dropAccepted();
    markChanged();
    const QStringList described = refreshDescriptions(); // before the views read them
    announce(DocumentChange::Corrections, correction.id);
    for (const QString &id : described)
        announce(DocumentChange::Node, id);
}

void ProjectSession::takeCorrection(const QString &id)
{
    m_project.corrections.removeIf([&](const Correction &c) { return c.id == id; });
    m_document->dropAccepted();
    markChanged();
    const QStringList described = refreshDescriptions(); // before the views read them
    announce(DocumentChange::Corrections, id);
    for (const QString &node : described)
        announce(DocumentChange::Node, node);
}

int ProjectSession::markFindings(const QStringList &keys, FindingMark::Status status,
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
    m_document->undoStack()->push(new FindingMarkCommand(this, before, after, text));
    return int(after.size());
}

int ProjectSession::unmarkFindings(const QStringList &keys)
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
    m_document->undoStack()->push(new FindingMarkCommand(
        this, before, after,
        QCoreApplication::translate("rosarch::Document", "Restore Findings (%1)")
            .arg(after.size())));
    return int(after.size());
}

void ProjectSession::replaceFindingMarks(
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
    markChanged();
    announce(DocumentChange::Findings);
}

} // namespace rosarch
