#pragma once

#include "widgets/diagram/diagrampanel.h"

#include <QSignalSpy>

namespace rosarch::test {

/// Runs `trigger` and waits until the panel has drawn (or failed to draw) its result.
template <typename F> bool laidOut(DiagramPanel &panel, F &&trigger)
{
    QSignalSpy spy(&panel, &DiagramPanel::layoutFinished);
    trigger();
    while (spy.isEmpty() || panel.isLayingOut())
        if (!spy.wait(30000))
            return false;
    return true;
}

} // namespace rosarch::test
