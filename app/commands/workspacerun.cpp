#include "workspacerun.h"
#include "decisionstore.h"
#include "stageprocess.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

namespace rosarch {

void WorkspaceRun::addOptions(QCommandLineParser &parser) const
{
    parser.addOption(m_argOption);
    parser.addOption(m_rootOption);
    parser.addOption(m_noDecisionsOption);
    parser.addOption(m_projectOption);
    parser.addOption(m_inProcessOption);
}

bool WorkspaceRun::read(const QCommandLineParser &parser, const QString &command, QString *error)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2) {
        *error =
            QCoreApplication::translate("rosarch::CommandLine", "%1 needs one workspace folder.")
                .arg(command);
        return false;
    }
    m_workspace = positional.at(1);
    if (!QFileInfo(m_workspace).isDir()) {
        *error = QCoreApplication::translate("rosarch::CommandLine", "Not a folder: %1")
                     .arg(m_workspace);
        return false;
    }
    m_inProcess = parser.isSet(m_inProcessOption);
    m_launch = {};
    m_launch.rootFile = parser.value(m_rootOption);
    for (const QString &arg : parser.values(m_argOption)) {
        const qsizetype sep = arg.indexOf(QLatin1String(":="));
        if (sep <= 0) {
            *error = QCoreApplication::translate("rosarch::CommandLine",
                                                 "--launch-arg expects name:=value, got '%1'.")
                         .arg(arg);
            return false;
        }
        m_launch.arguments.insert(arg.left(sep), arg.mid(sep + 2));
    }
    if (parser.isSet(m_noDecisionsOption) && parser.isSet(m_projectOption)) {
        *error = QCoreApplication::translate("rosarch::CommandLine",
                                             "--no-decisions and --project exclude each other.");
        return false;
    }
    m_decisions = parser.isSet(m_noDecisionsOption) ? QString()
                  : parser.isSet(m_projectOption)   ? parser.value(m_projectOption)
                                                    : DecisionStore::path(m_workspace);
    if (parser.isSet(m_projectOption) && !QFileInfo(m_decisions).isFile()) {
        *error = QCoreApplication::translate("rosarch::CommandLine", "No such file: %1")
                     .arg(m_decisions);
        return false;
    }
    return true;
}

Recovery WorkspaceRun::recover(int *applied, QString *failure) const
{
    Recovery recovered;
    if (!m_inProcess && !StageProcess::helperPath().isEmpty()) {
        StageProcess::Result r =
            StageProcess::recover(m_workspace, m_launch, StageControl(), StageProcess::Options());
        if (!r.error.isEmpty()) {
            if (failure)
                *failure = r.error;
            return {};
        }
        recovered = std::move(r.recovery);
    } else {
        recovered = recoverWorkspace(m_workspace, m_launch);
        if (!m_inProcess)
            recovered.nodes.diagnostics.append(StageProcess::missingWorker());
    }
    // The model as accepted, exactly as the GUI exports it for the same decisions.
    const AcceptedDecisions accepted =
        m_decisions.isEmpty() ? AcceptedDecisions{}
                              : AcceptedModel::select(DecisionStore::load(m_decisions), recovered);
    if (applied)
        *applied =
            int(accepted.groupings.size() + accepted.names.size() + accepted.descriptions.size());
    return AcceptedModel::apply(recovered, accepted);
}

} // namespace rosarch
