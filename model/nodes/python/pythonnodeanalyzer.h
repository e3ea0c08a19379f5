#pragma once

#include "languageanalysis.h"
#include "stagecontrol.h"
#include "workspace.h"

namespace rosarch {

/// Recovers rclpy node classes, procedural nodes and their ports from Python files.
class PythonNodeAnalyzer
{
public:
    explicit PythonNodeAnalyzer(const Workspace &workspace);

    /// Analyses every Python file of the workspace.
    LanguageAnalysis analyze(const StageControl &control = {}) const;

private:
    const Workspace &m_workspace;
};

} // namespace rosarch
