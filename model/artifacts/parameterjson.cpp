#include "artifacts/parameterjson.h"

#include "artifacts/evidencejson.h"
#include "artifacts/jsonsupport.h"

namespace rosarch::ParameterJson {

using JsonSupport::utf8;

Json toJson(const ParameterDeclaration &p)
{
    Json j;
    j["name"] = utf8(p.name);
    if (!p.nameExpression.isEmpty())
        j["name_expression"] = utf8(p.nameExpression);
    j["type"] = utf8(p.type);
    j["default"] = p.hasDefault ? Json(utf8(p.defaultValue)) : Json(nullptr);
    j["read_only"] = p.readOnly;
    if (p.dynamicTyping)
        j["dynamic_typing"] = true;
    j["description"] = utf8(p.description);
    if (!p.range.isEmpty())
        j["range"] = utf8(p.range);
    if (!p.guard.isEmpty())
        j["guard"] = utf8(p.guard);
    j["via"] = utf8(p.via);
    if (p.inherited)
        j["inherited"] = true;
    j["evidence"] = EvidenceJson::toJson(p.evidence);
    return j;
}

Json toJson(const QList<ParameterDeclaration> &parameters)
{
    Json a = Json::array();
    for (const ParameterDeclaration &p : parameters)
        a.push_back(toJson(p));
    return a;
}

QList<ParameterDeclaration> fromJson(const Json &array)
{
    QList<ParameterDeclaration> out;
    if (!array.is_array())
        return out;
    for (const Json &j : array) {
        if (!j.is_object())
            continue;
        ParameterDeclaration p;
        p.name = JsonSupport::string(j, "name");
        p.nameExpression = JsonSupport::string(j, "name_expression");
        p.type = JsonSupport::string(j, "type");
        p.hasDefault = j.contains("default") && j["default"].is_string();
        p.defaultValue = JsonSupport::string(j, "default");
        p.readOnly = j.value("read_only", false);
        p.dynamicTyping = j.value("dynamic_typing", false);
        p.description = JsonSupport::string(j, "description");
        p.range = JsonSupport::string(j, "range");
        p.guard = JsonSupport::string(j, "guard");
        p.via = JsonSupport::string(j, "via");
        p.inherited = j.value("inherited", false);
        if (j.contains("evidence"))
            p.evidence = EvidenceJson::fromJson(j["evidence"]);
        out.append(p);
    }
    return out;
}

} // namespace rosarch::ParameterJson
