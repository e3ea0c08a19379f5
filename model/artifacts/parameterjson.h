#pragma once

#include "core/parameter.h"

#include <QList>

#include <nlohmann/json.hpp>

namespace rosarch::ParameterJson {

using Json = nlohmann::ordered_json;

/// A class's declared parameter as the List of Atomic ROS Nodes writes it (blueprint §2).
Json toJson(const ParameterDeclaration &p);
/// The array of `parameters`.
Json toJson(const QList<ParameterDeclaration> &parameters);
/// What toJson wrote; entries that are not objects are skipped.
QList<ParameterDeclaration> fromJson(const Json &array);

} // namespace rosarch::ParameterJson
