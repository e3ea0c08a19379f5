#pragma once

#include "core/diagnostic.h"
#include "core/rospackage.h"

#include <QList>
#include <QString>

namespace rosarch {

/// A source file the analyzers may read.
struct SourceFile
{
    enum class Language
    {
        Python,
        Cpp,
        CMake,
        SetupPy,
        SetupCfg,
        PackageXml,
        Xml,
        Yaml,
        Other
    };

    QString path;    ///< relative to the workspace root, '/' separated
    QString package; ///< name of the package that contains it ("" outside any package)
    Language language = Language::Other;
    qint64 size = 0;

    bool operator==(const SourceFile &) const = default;
};

/// The result of scanning a workspace folder: its packages and the files worth reading.
struct Workspace
{
    QString root; ///< absolute, canonical
    QList<RosPackage> packages;
    QList<SourceFile> files; ///< sorted by path
    QList<Diagnostic> diagnostics;

    QString absolutePath(const QString &relativePath) const;
    const RosPackage *package(const QString &name) const;
};

} // namespace rosarch
