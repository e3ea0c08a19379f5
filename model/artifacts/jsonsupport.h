#pragma once

#include "core/provenance.h"

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

/// The string at `key`, or "" when it is missing or not a string.
inline QString string(const Json &j, const char *key)
{
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? QString::fromStdString(it->get<std::string>())
                                            : QString();
}

/// The strings of the array at `key` (other values skipped); empty when missing.
inline QStringList stringList(const Json &j, const char *key)
{
    QStringList out;
    const auto it = j.find(key);
    if (it != j.end() && it->is_array())
        for (const Json &v : *it)
            if (v.is_string())
                out.append(QString::fromStdString(v.get<std::string>()));
    return out;
}

/// Writes `provenance` and `reviewed` when they are not the defaults (blueprint §5).
inline void putMarks(Json &j, const Marks &marks)
{
    if (marks.provenance != Provenance::Recovered)
        j["provenance"] = utf8(provenanceName(marks.provenance));
    if (marks.reviewed)
        j["reviewed"] = true;
}

/// Reads what putMarks wrote.
inline Marks marks(const Json &j)
{
    Marks m;
    const QString p = string(j, "provenance");
    for (Provenance v : {Provenance::Suggested, Provenance::Corrected})
        if (p == provenanceName(v))
            m.provenance = v;
    const auto it = j.find("reviewed");
    m.reviewed = it != j.end() && it->is_boolean() && it->get<bool>();
    return m;
}

} // namespace rosarch::JsonSupport
