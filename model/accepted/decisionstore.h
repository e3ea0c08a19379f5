#pragma once

#include "accepted/suggestiondecision.h"

#include <QMap>
#include <QString>

namespace rosarch {

/// The decisions of one workspace on disk: <AppDataLocation>/projects/<sha1 of the absolute
/// workspace path>/decisions.json. Holds kinds, ids, proposals and times; never a secret.
namespace DecisionStore {
/// The file for `workspaceRoot` ("" when the root is empty).
QString path(const QString &workspaceRoot);
/// The decisions in `file`, by SuggestionDecision::key (empty when there is none; entries
/// that cannot be read are skipped and counted in `skipped`).
QMap<QString, SuggestionDecision> load(const QString &file, int *skipped = nullptr);
/// Writes atomically (QSaveFile), sorted by key; false with a message on failure.
bool save(const QString &file, const QString &workspaceRoot,
          const QMap<QString, SuggestionDecision> &decisions, QString *error);
} // namespace DecisionStore

} // namespace rosarch
