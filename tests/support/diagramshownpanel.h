#pragma once

#include "diagram/diagramlayouter.h"
#include "support/diagramarchitecture.h"
#include "support/diagramwait.h"
#include "widgets/diagram/diagrampanel.h"

#include <QtTest>

namespace rosarch::test {

/// A panel on screen showing the hand-made architecture's root: every element, inactive ones
/// too, unless `asFirstShown` (then as a person first sees it: inactive ones hidden).
struct ShownPanel
{
    DiagramLayouter layouter;
    DiagramPanel panel{&layouter};
    bool ok = false;
    explicit ShownPanel(bool asFirstShown = false)
    {
        if (!asFirstShown) {
            DiagramOptions options = panel.options();
            options.showInactive = true;
            panel.setOptions(options);
        }
        panel.resize(1100, 720);
        panel.show();
        if (!QTest::qWaitForWindowExposed(&panel))
            return;
        ok = test::laidOut(panel, [this] { panel.setArchitecture(test::diagram::architecture()); });
    }
};

} // namespace rosarch::test
