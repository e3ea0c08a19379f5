#include "pythonnodeanalyzer.h"

namespace rosarch {

PythonNodeAnalyzer::PythonNodeAnalyzer(const Workspace &workspace) : m_workspace(workspace) {}

LanguageAnalysis PythonNodeAnalyzer::analyze(const StageControl &control) const
{
    Q_UNUSED(control);
    return {};
}

} // namespace rosarch
