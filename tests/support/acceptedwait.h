#pragma once

// The model as accepted is made again on a background job after each change of the recovery or
// the project (Document::isAcceptedPending): tests that read it after a change wait for it, as
// the views do for DocumentChange::Accepted.
#include "document/document.h"

#include <QTest>

namespace rosarch::test {

/// Waits until the document's model as accepted includes every change made so far; false when
/// it did not within `timeoutMs`.
inline bool acceptedSettled(const Document &doc, int timeoutMs = 30000)
{
    return QTest::qWaitFor([&doc] { return !doc.isAcceptedPending(); }, timeoutMs);
}

/// The document's model as accepted, once it includes every change made so far.
inline const Recovery &acceptedNow(const Document &doc)
{
    acceptedSettled(doc);
    return doc.accepted();
}

} // namespace rosarch::test
