#pragma once

#include "core/atomicnodelist.h"

#include <QByteArray>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// The node classes of the List of Atomic ROS Nodes as NoDL documents (Node Definition
/// Language v2, ros-tooling/nodl): the parameters, topics, services and actions each class
/// declares, for NoDL's tools (drift checks against a running node, documentation).
namespace NodlWriter {

struct Documents
{
    /// "<package>/<executable>.nodl.json" → the document, one per node class. NoDL keeps a
    /// node's identity out of the document (the package and the file name give it, as
    /// `ament_nodl_register(<executable> FILE ...)` registers it), and reads JSON as well as
    /// YAML.
    QMap<QString, QByteArray> files;
    /// What NoDL cannot express and was left out or written as NoDL's "unknown", one line
    /// each ("drive_py/battery_watch: subscription {topic}: name decided at run time").
    QStringList omitted;
};

/// Deterministic: documents by path, parameters and endpoints sorted by name.
Documents write(const AtomicNodeList &list);

/// Writes the documents under `dir` (each atomically); false with a message at the first
/// that cannot be written.
bool writeTo(const Documents &documents, const QString &dir, QString *error);

} // namespace NodlWriter

} // namespace rosarch
