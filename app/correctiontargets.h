#pragma once

#include "app/correctionelement.h"
#include "widgets/correctionindex.h"

#include <QObject>

#include <optional>

namespace rosarch {

class Document;

/// What the corrections in effect say about an element: its key, its name, whether it is removed.
class CorrectionTargets : public QObject
{
    Q_OBJECT
public:
    /// Forgets what it worked out whenever `document` changes.
    CorrectionTargets(Document *document, QObject *parent);

    /// The corrections in effect, by element (made on first use after each change).
    const CorrectionIndex &index();
    /// The stable key of element `id` in the corrected model.
    QString keyOf(const QString &id);
    /// True when keyOf(id) answers without waiting for the keys of a large model (made on a
    /// thread of their own after each recovery): the inspector does not wait for them.
    bool keysAtHand(const QString &id);
    /// The name the views show for `element` ("" when it is not in the model).
    QString nameOf(const CorrectionElement &element);
    /// True when a correction removed the class, port or instance `element`.
    bool isRemoved(const CorrectionElement &element);

private:
    Document *m_document;
    std::optional<CorrectionIndex> m_index; ///< until the Document changes
};

} // namespace rosarch
