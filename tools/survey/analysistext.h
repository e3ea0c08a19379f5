#pragma once

#include "core/languageanalysis.h"
#include "core/launchaction.h"
#include "core/port.h"

#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// What the analyzers recover, as plain text with every field visible: for reading their
/// output on real code (rosarch-survey) and for comparisons in the analyzer tests.
namespace AnalysisText {

/// A port on one line: "publisher chatter std_msgs/msg/String cb= origin=literal ... @file:line".
QString port(const Port &port);
/// Every node class with its ports, then entry points, registrations and diagnostics.
QString analysis(const LanguageAnalysis &analysis);
/// Like Substitution::describe(), but every kind is visible: join[..] for PathJoin, cat[..]
/// for Concat, ?{..} for Unknown, |default for configurations and environment variables.
QString substitution(const Substitution &substitution);
/// A short name of an action kind ("Node", "Include", "PushNs", ...).
QString actionKind(LaunchAction::Kind kind);
/// One line per action, children indented by two spaces; BAD-EVIDENCE marks an action whose
/// remaps or parameters do not carry the action's evidence.
QStringList actions(const QList<LaunchAction> &actions);
/// Counts action kinds, and what stayed unresolved by the name of the call or construct.
void tally(const QList<LaunchAction> &actions, QMap<QString, int> *kinds,
           QMap<QString, int> *unresolved);

} // namespace AnalysisText

} // namespace rosarch
