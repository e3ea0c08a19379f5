#pragma once

// Reading a Document's change signal in tests: the changes a QSignalSpy on Document::changed
// recorded, filtered by part.
#include "document/documentchange.h"

#include <QSignalSpy>
#include <QStringList>

namespace rosarch::test {

/// The changes recorded by `spy` (a QSignalSpy on Document::changed) that include `part`.
inline QList<DocumentChange> changesOf(const QSignalSpy &spy, DocumentChange::Part part)
{
    QList<DocumentChange> out;
    for (const QList<QVariant> &args : spy) {
        const auto change = args.at(0).value<DocumentChange>();
        if (change.has(part))
            out << change;
    }
    return out;
}

/// The ids of the recorded changes that include `part`, in order.
inline QStringList changedIds(const QSignalSpy &spy, DocumentChange::Part part)
{
    QStringList ids;
    for (const DocumentChange &c : changesOf(spy, part))
        ids << c.id;
    return ids;
}

} // namespace rosarch::test
