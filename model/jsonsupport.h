#pragma once

#include <QString>
#include <QStringList>

#include <nlohmann/json.hpp>

namespace rosarch::JsonSupport {

using Json = nlohmann::ordered_json;

/// A QString as the UTF-8 std::string nlohmann::json stores.
inline std::string utf8(const QString &text)
{
    return text.toStdString();
}

/// A list of strings as a JSON array, in order.
inline Json strings(const QStringList &list)
{
    Json a = Json::array();
    for (const QString &v : list)
        a.push_back(utf8(v));
    return a;
}

} // namespace rosarch::JsonSupport
