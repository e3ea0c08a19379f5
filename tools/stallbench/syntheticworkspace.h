#pragma once

#include <QString>

namespace rosarch {

/// A generated ROS 2 workspace of any size, for the large-workspace test and the stall
/// benchmark: package i holds a C++ node (even i) or a Python node (odd i) publishing topic_i
/// and subscribing to topic_{i-1}, and a launch file starting it; every `group`-th package's
/// launch file also includes the next packages' launch files, and package 0 has
/// all.launch.xml including the groups.
namespace SyntheticWorkspace {
/// Writes `packages` packages under `root`/src; false (and `error`) when a file cannot be
/// written.
bool generate(const QString &root, int packages, int group, QString *error);
/// One Python package under `root`/src whose `files` launch files (alternately Python, XML and
/// YAML) each start its node once: a workspace of many small launch files.
bool generateLaunchFiles(const QString &root, int files, QString *error);
} // namespace SyntheticWorkspace

} // namespace rosarch
