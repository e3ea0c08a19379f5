#pragma once

#include <QString>

namespace rosarch {

/// An element the views show, by the id of the corrected model ("arc_3", "arc_3/p1", "n3",
/// "lf2", "topic:/scan"); a connection is an instance id and its port ("arc_2/p1").
struct CorrectionElement
{
    enum class Kind
    {
        None,
        Class,
        Port,
        Instance,
        LaunchFile,
        Channel,
        Connection
    };
    Kind kind = Kind::None;
    QString id;
    QString port;   ///< Connection: the class port ("arc_2/p1")
    QString rootId; ///< Instance from the diagram: the root launch-file instance shown
    bool operator==(const CorrectionElement &) const = default;
};

} // namespace rosarch
