#pragma once

#include "core/evidence.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// How a launch file can start code: an executable or a component plugin.
struct Executable
{
    enum class Kind
    {
        ConsoleScript,
        CMakeExecutable,
        ComponentPlugin
    };

    Kind kind = Kind::CMakeExecutable;
    QString name;        ///< executable name, or the plugin class for a plugin-only registration
    QString target;      ///< python "module.path:function"; cmake target name; plugin class
    QString plugin;      ///< plugin class ("ns::Class") for component registrations
    QStringList sources; ///< source files relative to the workspace root (CMake targets)
    Evidence evidence;

    bool operator==(const Executable &) const = default;
};

/// A ROS 2 package found by its package.xml.
struct RosPackage
{
    QString name;
    QString buildType; ///< ament_python, ament_cmake, ...
    QString path;      ///< folder relative to the workspace root ("" for the root itself)
    QString version;   ///< package.xml's <version>, as written
    Evidence evidence; ///< the <name> element of package.xml
    QList<Executable> executables;

    bool operator==(const RosPackage &) const = default;
};

} // namespace rosarch
