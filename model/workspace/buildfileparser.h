#pragma once

#include "core/diagnostic.h"
#include "core/rospackage.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace rosarch {

/// Reads the build files of one package: package.xml, setup.py, setup.cfg, CMakeLists.txt.
/// Paths given and returned are relative to the workspace root.
namespace BuildFileParser {

/// Fills name, version, buildType and evidence from package.xml; a malformed file gives a
/// diagnostic and the folder name as the package name.
void readPackageXml(const QByteArray &content, const QString &file, RosPackage *package,
                    QList<Diagnostic> *diagnostics);

/// console_scripts entry points of a setup.py (literals, concatenation, f-strings and module
/// level string variables such as `package_name`).
QList<Executable> readSetupPy(const QByteArray &content, const QString &file,
                              QList<Diagnostic> *diagnostics);

/// console_scripts of a setup.cfg [options.entry_points] section.
QList<Executable> readSetupCfg(const QByteArray &content, const QString &file);

} // namespace BuildFileParser

} // namespace rosarch
