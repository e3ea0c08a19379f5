#pragma once

#include <QStringList>

namespace rosarch {

/// `rosarch suggest <workspace> --out <dir> [--llm-endpoint URL] [--llm-model NAME]
/// [--llm-timeout S]`: stages 1 and 2, then the suggestion tasks, written to suggestions.json.
/// Exit codes: 0 ok, 1 the LLM endpoint failed or the output could not be written (the
/// deterministic suggestions are written anyway), 2 usage. `arguments` includes the program.
int runSuggest(const QStringList &arguments);

} // namespace rosarch
