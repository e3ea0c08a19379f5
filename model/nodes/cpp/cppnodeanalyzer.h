#pragma once

#include "core/languageanalysis.h"
#include "core/stagecontrol.h"
#include "workspace/workspace.h"

#include <QFuture>

#include <memory>

namespace rosarch {

class CppMacroIndex;

/// Recovers rclcpp / rclcpp_lifecycle node classes, procedural nodes, component
/// registrations and their ports from C++ files.
class CppNodeAnalyzer
{
public:
    explicit CppNodeAnalyzer(const Workspace &workspace);
    ~CppNodeAnalyzer();
    CppNodeAnalyzer(const CppNodeAnalyzer &) = delete;
    CppNodeAnalyzer &operator=(const CppNodeAnalyzer &) = delete;

    /// Starts what every file's analysis needs first, the macro index (it reads each workspace
    /// header and CMakeLists.txt, on one thread), on a pool thread, so that it overlaps other
    /// work (stage 1's Python files) instead of leaving a core idle; analyze() waits for it.
    void prepare(const StageControl &control);

    /// Analyses every C++ file of the workspace.
    LanguageAnalysis analyze(const StageControl &control = {}) const;

private:
    const Workspace &m_workspace;
    QFuture<std::shared_ptr<const CppMacroIndex>> m_prepared; ///< valid after prepare()
};

} // namespace rosarch
