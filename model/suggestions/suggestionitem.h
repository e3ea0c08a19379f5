#pragma once

#include "core/evidence.h"
#include "pipeline/recovery.h"

#include <QList>
#include <QString>

namespace rosarch {

/// Something stage 1 or 2 left unresolved that a name-resolution suggestion may target: a port
/// whose name is an expression, or an Unresolved item of a launch-file or node instance.
struct SuggestionItem
{
    QString id;         ///< "arc_2/p1" for a port; "n3#u1" / "lf2#u1" for a launch item
    QString kind;       ///< "port-name", or the Unresolved kind ("condition", "substitution", ...)
    QString elementId;  ///< the ARC or instance it belongs to
    QString expression; ///< as written
    QString guess;      ///< the analysis' best guess
    Evidence evidence;

    /// Every such item of a recovery, in artifact order.
    static QList<SuggestionItem> collect(const Recovery &recovery);
};

} // namespace rosarch
