#pragma once

#include "core/atomicnodelist.h"

#include <QByteArray>
#include <QString>

namespace rosarch {

/// The List of Atomic ROS Nodes as JSON (blueprint §2, with ports and evidence added).
namespace AtomicNodesJson {
/// Deterministic, pretty-printed, sorted as the list is.
QByteArray write(const AtomicNodeList &list);
/// Reads what write() produced; returns false with a message on malformed input.
bool read(const QByteArray &json, AtomicNodeList *list, QString *error);
} // namespace AtomicNodesJson

} // namespace rosarch
