#pragma once

#include "core/launchaction.h"

#include <QByteArray>
#include <QString>

namespace rosarch {

/// Reads a Yaml launch file into LaunchActions, statically (nothing is executed).
class YamlLaunchReader
{
public:
    /// True when the content is a launch description (decided by content, not by name).
    static bool isLaunchFile(const QByteArray &content);
    /// Reads the launch description; problems become diagnostics, never exceptions.
    static LaunchFileDescription read(const QByteArray &content, const QString &file);
};

} // namespace rosarch
