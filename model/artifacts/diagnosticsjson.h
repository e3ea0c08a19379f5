#pragma once

#include "core/diagnostic.h"

#include <QByteArray>
#include <QList>

#include <nlohmann/json.hpp>

/// The diagnostics of a run as JSON (diagnostics.json, schemas/diagnostics.schema.json).
namespace rosarch::DiagnosticsJson {

/// One diagnostic: severity, code, message, evidence, then related and contexts when it has any.
nlohmann::ordered_json toJson(const Diagnostic &d);
/// The whole file: deterministic and pretty-printed, in the order of the list.
QByteArray write(const QList<Diagnostic> &diagnostics);

} // namespace rosarch::DiagnosticsJson
