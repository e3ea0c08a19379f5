#pragma once

#include "core/languageanalysis.h"
#include "core/stagecontrol.h"
#include "nodes/python/pythonfactscodec.h"
#include "workspace/workspace.h"

namespace rosarch {

/// Recovers rclpy node classes, procedural nodes and their ports from Python files.
class PythonNodeAnalyzer
{
public:
    explicit PythonNodeAnalyzer(const Workspace &workspace);

    /// Analyses every Python file of the workspace.
    LanguageAnalysis analyze(const StageControl &control = {}) const;

    /// Parses one file's `content` and reads its module facts (`module` is its dotted path).
    static PythonFileResult analyzeContent(const QByteArray &content, const QString &file,
                                           const QString &package, const QString &module);

private:
    const Workspace &m_workspace;
};

} // namespace rosarch
