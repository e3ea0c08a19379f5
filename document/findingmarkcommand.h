#pragma once

#include "project/findingmark.h"

#include <QList>
#include <QUndoCommand>

#include <optional>
#include <utility>

namespace rosarch {

class ProjectSession;

/// Undoable change of the marks (hidden, accepted) of some findings: what each key had before
/// and has after (none = unmarked).
class FindingMarkCommand : public QUndoCommand
{
public:
    using Marks = QList<std::pair<QString, std::optional<FindingMark>>>;
    FindingMarkCommand(ProjectSession *session, Marks before, Marks after, const QString &text);
    void undo() override;
    void redo() override;

private:
    ProjectSession *m_session;
    Marks m_before;
    Marks m_after;
};

} // namespace rosarch
