#pragma once

#include "core/evidence.h"

#include <nlohmann/json.hpp>

namespace rosarch::EvidenceJson {

/// {"file", "line", "column", "end_line", "end_column"} per the blueprint.
nlohmann::ordered_json toJson(const Evidence &e);
Evidence fromJson(const nlohmann::ordered_json &j);

} // namespace rosarch::EvidenceJson
