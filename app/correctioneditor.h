#pragma once

#include "app/correctionelement.h"
#include "project/correction.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>

class QWidget;

namespace rosarch {

class CorrectionDialog;
class CorrectionTargets;
class Document;

/// Asks in a CorrectionDialog what a correction needs and hands it to the Document (undoable).
class CorrectionEditor : public QObject
{
    Q_OBJECT
public:
    /// Its dialogs are modal on `window`.
    CorrectionEditor(Document *document, CorrectionTargets *targets, QWidget *window,
                     QObject *parent);

    /// Replaces the modal dialog (tests): called with the dialog filled in as a person would
    /// see it; returning true accepts it.
    void setDialogHandler(std::function<bool(CorrectionDialog &)> handler);

    // Each asks through a dialog and pushes one undoable correction; false when cancelled or
    // not applicable.
    bool rename(const CorrectionElement &element);
    bool setType(const CorrectionElement &element);
    bool remove(const CorrectionElement &element);
    bool addPort(const CorrectionElement &classElement);
    bool addPart(const CorrectionElement &launchFile);
    bool addConnection(const CorrectionElement &instance);
    /// Marks reviewed at once (no dialog); again on a reviewed element removes the mark.
    bool toggleReviewed(const CorrectionElement &element);
    /// Groups node instances (ids) of one root launch-file instance into a named subsystem.
    bool group(const QStringList &instanceIds, const QString &rootId);
    /// Reverts the correction that removed `element`.
    bool restore(const CorrectionElement &element);
    /// Replaces an orphaned correction by one naming another element of its family.
    bool retarget(const QString &correctionId);
    /// Reverts the corrections `ids`, as one step to undo.
    void removeCorrections(const QStringList &ids);

Q_SIGNALS:
    void statusMessage(const QString &text, int timeout);

private:
    bool ask(CorrectionDialog &dialog);
    bool push(Correction c);
    /// The other unresolved ports of a port's class whose name is written as its is.
    QStringList twinPorts(const QString &portId);
    QStringList knownTypes();

    Document *m_document;
    CorrectionTargets *m_targets;
    QPointer<QWidget> m_window;
    std::function<bool(CorrectionDialog &)> m_dialogHandler;
};

} // namespace rosarch
