#pragma once

#include "core/stagecontrol.h"
#include "syntax/cpppreprocessor.h"
#include "workspace/sourcereader.h"
#include "workspace/workspace.h"

#include <QHash>
#include <QSet>
#include <QString>
#include <QStringList>

namespace rosarch {

/// What the workspace tells the preprocessor: the compile definitions of each package's
/// CMakeLists.txt (add_compile_definitions, add_definitions(-D...), target_compile_definitions)
/// and the macros each workspace header exports (its `#define`s and those of the workspace
/// headers it includes, without its include guard). Built once before the files are analysed;
/// read-only afterwards, so the parallel phase can share it.
class CppMacroIndex
{
public:
    /// A header includes others at most this deep when its exports are collected.
    static constexpr int kMaxIncludeDepth = 16;

    CppMacroIndex() = default;
    CppMacroIndex(const Workspace &workspace, const SourceReader &reader,
                  const StageControl &control = {});
    /// The index with the headers' exports given, as exports() gave them for the same headers
    /// (the analysis cache's memo): no header is read.
    CppMacroIndex(const Workspace &workspace, const SourceReader &reader,
                  QHash<QString, CppMacros> exports);

    /// The macros each workspace header exports.
    const QHash<QString, CppMacros> &exports() const { return m_exports; }

    /// The macros a file of `package` starts with: a few the compiler predefines
    /// (`__cplusplus`, `__linux__`, `__GNUC__`) and the package's compile definitions.
    CppMacros initialMacros(const QString &package) const;

    /// Resolves `#include`s of `file` to the exports of workspace headers.
    CppPreprocessor::IncludeLookup lookup(const QString &file) const;

    /// The workspace header an `#include` of `file` names ("" when none).
    QString resolve(const QString &file, const QString &written, bool angled) const;

    /// The compile definitions a CMakeLists.txt makes (exposed for tests).
    static CppMacros compileDefinitions(const QByteArray &cmakeLists);

private:
    void indexFiles(const Workspace &workspace, const SourceReader &reader);
    const CppMacros *exportsOf(const QString &header, int depth);

    const Workspace *m_workspace = nullptr;
    const SourceReader *m_reader = nullptr;
    const StageControl *m_control = nullptr;
    QHash<QString, CppMacros> m_packageDefinitions;
    QHash<QString, QStringList> m_byIncludePath; ///< "pkg/x.hpp" -> workspace paths
    QHash<QString, QString> m_packageOf;         ///< workspace path -> package
    QHash<QString, CppMacros> m_exports;         ///< header path -> its exports
    QSet<QString> m_visiting;
};

} // namespace rosarch
