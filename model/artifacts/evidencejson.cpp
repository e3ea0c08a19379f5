#include "artifacts/evidencejson.h"

namespace rosarch::EvidenceJson {

nlohmann::ordered_json toJson(const Evidence &e)
{
    nlohmann::ordered_json j;
    j["file"] = e.file.toStdString();
    j["line"] = e.line;
    j["column"] = e.column;
    j["end_line"] = e.endLine;
    j["end_column"] = e.endColumn;
    return j;
}

Evidence fromJson(const nlohmann::ordered_json &j)
{
    Evidence e;
    if (!j.is_object())
        return e;
    if (j.contains("file") && j["file"].is_string())
        e.file = QString::fromStdString(j["file"].get<std::string>());
    e.line = j.value("line", 0);
    e.column = j.value("column", 0);
    e.endLine = j.value("end_line", 0);
    e.endColumn = j.value("end_column", 0);
    return e;
}

} // namespace rosarch::EvidenceJson
