#pragma once

#include "core/launchaction.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace rosarch {

/// Reads a Python launch file into LaunchActions, statically (nothing is executed).
class PythonLaunchReader
{
public:
    /// True when the content is a launch description (decided by content, not by name).
    static bool isLaunchFile(const QByteArray &content);
    /// Reads the launch description; problems become diagnostics, never exceptions.
    static LaunchFileDescription read(const QByteArray &content, const QString &file);
    /// read() when isLaunchFile(), from one parse of the content (a launch file is parsed once).
    static std::optional<LaunchFileDescription> readIfLaunchFile(const QByteArray &content,
                                                                 const QString &file);
};

} // namespace rosarch
