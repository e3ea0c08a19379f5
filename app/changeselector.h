#pragma once

#include "diff/architecturediff.h"

#include <QObject>

namespace rosarch {

class ArchitectureDiffView;
class DiagramPanel;
class Document;
class Traceability;

/// Selects what a row of *Architecture changes* is about in the other views: a node class or
/// port in the node list, a launch file or part in the launch tree (and the diagram), a topic,
/// service, action or connection in the composite of its launch file. A removed element is not
/// in the model shown: its class or launch file is selected and the status bar says so.
class ChangeSelector : public QObject
{
    Q_OBJECT
public:
    ChangeSelector(Document *document, ArchitectureDiffView *view, Traceability *traceability,
                   DiagramPanel *diagram, QObject *parent = nullptr);

    /// Selects the element of `change`; false when nothing of it is in the model shown.
    bool select(const ArchitectureChange &change);

Q_SIGNALS:
    void statusMessage(const QString &text, int timeout);

private:
    bool selectClass(const QString &key);
    bool selectPort(const QString &className, const QString &portText);
    bool selectLaunchFile(const QString &file);
    /// In the composite of `file`: the part, name or connection that `text` describes.
    bool selectInComposite(const ArchitectureChange &change, const QString &text);
    /// Selects a diagram element once the composite shown is laid out.
    void selectWhenLaidOut(const QString &diagramKey);

    Document *m_document;
    Traceability *m_traceability;
    DiagramPanel *m_diagram;
    QMetaObject::Connection m_pending;
};

} // namespace rosarch
