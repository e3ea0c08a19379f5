#pragma once

#include "suggestions/suggestionreport.h"

#include <QByteArray>
#include <QString>

namespace rosarch {

/// suggestions.json: the checked suggestions (kind, target, proposal, rationale, evidence,
/// origin, status), the discarded count with reasons, the prompt sizes and the LLM errors.
namespace SuggestionsJson {
/// Pretty-printed, in the report's order.
QByteArray write(const SuggestionReport &report);
/// Reads what write() produced; false with a message on malformed input.
bool read(const QByteArray &json, SuggestionReport *report, QString *error);
} // namespace SuggestionsJson

} // namespace rosarch
