#include "cppnodeanalyzer.h"

namespace rosarch {

CppNodeAnalyzer::CppNodeAnalyzer(const Workspace &workspace) : m_workspace(workspace) {}

LanguageAnalysis CppNodeAnalyzer::analyze(const StageControl &control) const
{
    Q_UNUSED(control);
    return {};
}

} // namespace rosarch
