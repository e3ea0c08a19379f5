#pragma once

#include <QColor>
#include <QFont>

class QPalette;

namespace rosarch {

/// Colours and fonts of the composed diagram, for light or dark paper. Edge colours follow the
/// blueprint: publish green, subscribe blue, client red, server purple, delegation grey.
struct DiagramStyle
{
    bool dark = false;
    QColor paper;
    QColor text;
    QColor mutedText;
    QColor frame;
    QColor frameFill;
    QColor partFill;
    QColor launchFill;
    QColor partBorder;
    QColor clusterFill;
    QColor clusterBorder;
    QColor topicFill;
    QColor serviceFill;
    QColor actionFill;
    QColor boundaryFill;
    QColor portFill;
    QColor selection;
    QColor match;
    QColor extra;
    QColor corrected; ///< the dashed border of what a person corrected, and the review ✓
    QFont titleFont;
    QFont textFont;
    QFont smallFont;

    /// The colour of an edge of a Connection::Kind (as the layout graph's category).
    QColor edgeColor(int category) const;
    /// Light paper (the export style), or dark paper.
    static DiagramStyle make(bool dark);
    /// The style matching a widget palette (dark when the window colour is dark).
    static DiagramStyle fromPalette(const QPalette &palette);
};

} // namespace rosarch
