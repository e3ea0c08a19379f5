#pragma once

#include "core/port.h"
#include "nodes/python/pythonresolver.h"

namespace rosarch {

/// Recognizes the rclpy calls that create ports (create_publisher, create_subscription,
/// create_service, create_client, ActionServer, ActionClient, message_filters.Subscriber)
/// and reads their type, name, callback and guard.
class PythonPortReader
{
public:
    explicit PythonPortReader(const PythonResolver &resolver);

    /// True when `call` creates a port; `receiver` is the node handle expression it uses.
    bool recognize(TSNode call, PortKind *kind, TSNode *receiver) const;
    /// The argument that holds the port's interface type (null if absent).
    TSNode typeArgument(TSNode call, PortKind kind) const;
    /// The argument that holds the port's name (null if absent).
    TSNode nameArgument(TSNode call, PortKind kind) const;
    /// The port created by a recognized call (no id, via or inherited yet).
    Port read(TSNode call, PortKind kind) const;

private:
    const PythonResolver &m_resolver;
};

} // namespace rosarch
