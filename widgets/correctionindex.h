#pragma once

#include "project/correction.h"
#include "project/stablekeys.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

class Document;

/// Which corrections touch which element, for the views: an element is named by the id the
/// views use ("arc_3", "arc_3/p1", "n3", "lf2", "topic:/scan"), in the corrected model or, for
/// an element a correction removed, in the model as recovered. Built once per change of the
/// Document (the keys of both models); cheap when there are no corrections.
class CorrectionIndex
{
public:
    CorrectionIndex() = default;
    explicit CorrectionIndex(const Document &document);

    bool isEmpty() const { return m_corrections.isEmpty(); }
    /// The corrections that changed, added, removed or reviewed the element, in the order
    /// they were made.
    QList<Correction> of(const QString &id) const;
    /// The correction that removed the element ("" when it was not removed).
    QString removedBy(const QString &id) const;
    /// "Corrected by c3: Rename /scan → /laser (reason)" lines, one per correction ("" none).
    QString summary(const QString &id) const;
    /// The key of the element as it is now (in the corrected model), else as recovered.
    QString keyOf(const QString &id) const;
    /// The element a key names now, else the one it named as recovered ("" when none).
    QString idOf(const QString &key) const;
    const StableKeys &correctedKeys() const { return m_corrected; }
    const StableKeys &recoveredKeys() const { return m_recovered; }

private:
    QList<Correction> m_corrections;
    QHash<QString, QList<int>> m_byTarget; ///< target key → indexes into m_corrections
    StableKeys m_corrected;
    StableKeys m_recovered;
    QHash<QString, QString> m_portNames; ///< added port id ("arc_3/s2") → "kind|name"
};

} // namespace rosarch
