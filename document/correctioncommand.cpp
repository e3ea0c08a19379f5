#include "document/correctioncommand.h"
#include "document/projectsession.h"

#include <QCoreApplication>

namespace rosarch {

namespace {

QString describe(const Correction &c)
{
    switch (c.kind) {
    case Correction::Kind::Rename:
        return QCoreApplication::translate("rosarch::Document", "Rename to %1").arg(c.newValue);
    case Correction::Kind::SetName:
        return QCoreApplication::translate("rosarch::Document", "Set name %1").arg(c.newValue);
    case Correction::Kind::SetType:
        return QCoreApplication::translate("rosarch::Document", "Set type %1").arg(c.newValue);
    case Correction::Kind::Remove:
        return QCoreApplication::translate("rosarch::Document", "Remove %1").arg(c.oldValue);
    case Correction::Kind::AddPort:
        return QCoreApplication::translate("rosarch::Document", "Add port %1").arg(c.newValue);
    case Correction::Kind::AddPart:
        return QCoreApplication::translate("rosarch::Document", "Add part %1").arg(c.newValue);
    case Correction::Kind::AddConnection:
        return QCoreApplication::translate("rosarch::Document", "Add connection to %1")
            .arg(c.newValue);
    case Correction::Kind::Group:
        return QCoreApplication::translate("rosarch::Document", "Group as %1").arg(c.newValue);
    case Correction::Kind::Review:
        return QCoreApplication::translate("rosarch::Document", "Mark reviewed");
    case Correction::Kind::Describe:
        return QCoreApplication::translate("rosarch::Document", "Edit description");
    }
    return {};
}

} // namespace

CorrectionCommand::CorrectionCommand(ProjectSession *session, Action action, Correction correction,
                                     int index, QUndoCommand *parent)
    : QUndoCommand(parent), m_session(session), m_action(action),
      m_correction(std::move(correction)), m_index(index)
{
    setText(action == Action::Add ? describe(m_correction)
                                  : QCoreApplication::translate("rosarch::Document", "Revert: %1")
                                        .arg(describe(m_correction)));
}

void CorrectionCommand::undo()
{
    if (m_action == Action::Add)
        m_session->takeCorrection(m_correction.id);
    else
        m_session->insertCorrection(m_index, m_correction);
}

void CorrectionCommand::redo()
{
    if (m_action == Action::Add)
        m_session->insertCorrection(m_index, m_correction);
    else
        m_session->takeCorrection(m_correction.id);
}

} // namespace rosarch
