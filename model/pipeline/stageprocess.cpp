#include "pipeline/stageprocess.h"
#include "core/helperprogram.h"
#include "pipeline/stagesession.h"

namespace rosarch {

QString StageProcess::helperPath(const QString &configured)
{
    return findHelperProgram(configured, "ROSARCH_STAGES", QStringLiteral("rosarch-stages"));
}

Diagnostic StageProcess::missingWorker()
{
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("worker-missing");
    d.message = QStringLiteral("The analysis worker rosarch-stages was not found next to the "
                               "application, so the stages ran without crash isolation and "
                               "without per-file budgets.");
    return d;
}

namespace {

StageProcess::Options oneShot(StageProcess::Options options)
{
    options.oneShot = true;
    return options;
}

} // namespace

StageProcess::Result StageProcess::recover(const QString &root, const LaunchOptions &options,
                                           const StageControl &control, const Options &process)
{
    StageSession once(oneShot(process), false);
    Result r = once.recover(root, options, control);
    once.releaseWorker(); // it writes its cache after it replied: nobody needs to wait for that
    return r;
}

StageProcess::Result StageProcess::launch(const QString &root, const AtomicNodeList &nodes,
                                          const LaunchOptions &options, const StageControl &control,
                                          const Options &process)
{
    StageSession once(oneShot(process), false);
    Result r = once.launch(root, nodes, options, control);
    once.releaseWorker();
    return r;
}

} // namespace rosarch
