#pragma once

#include <QString>
#include <QUndoCommand>

namespace rosarch {

class Document;

/// Undoable edit of an atomic node's description.
class SetNodeDescriptionCommand : public QUndoCommand
{
public:
    SetNodeDescriptionCommand(Document *document, QString nodeId, QString before, QString after);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    QString m_nodeId;
    QString m_before;
    QString m_after;
};

} // namespace rosarch
