#pragma once

#include "languageanalysis.h"
#include "stagecontrol.h"
#include "workspace.h"

namespace rosarch {

/// Recovers rclcpp / rclcpp_lifecycle node classes, procedural nodes, component
/// registrations and their ports from C++ files.
class CppNodeAnalyzer
{
public:
    explicit CppNodeAnalyzer(const Workspace &workspace);

    /// Analyses every C++ file of the workspace.
    LanguageAnalysis analyze(const StageControl &control = {}) const;

private:
    const Workspace &m_workspace;
};

} // namespace rosarch
