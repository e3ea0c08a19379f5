#include "artifacts/diagnosticsjson.h"
#include "artifacts/evidencejson.h"
#include "artifacts/jsonsupport.h"
#include "core/visibletext.h"

namespace rosarch::DiagnosticsJson {

using JsonSupport::Json;
using JsonSupport::utf8;

Json toJson(const Diagnostic &d)
{
    Json j;
    j["severity"] = utf8(Diagnostic::severityName(d.severity));
    j["code"] = utf8(d.code);
    j["message"] = utf8(d.message);
    j["evidence"] = EvidenceJson::toJson(d.evidence);
    if (!d.related.isEmpty()) {
        Json related = Json::array();
        for (const Diagnostic::Related &r : d.related)
            related.push_back(
                {{"message", utf8(r.message)}, {"evidence", EvidenceJson::toJson(r.evidence)}});
        j["related"] = related;
    }
    if (!d.contexts.isEmpty())
        j["contexts"] = JsonSupport::strings(d.contexts);
    return j;
}

QByteArray write(const QList<Diagnostic> &diagnostics)
{
    Json a = Json::array();
    for (const Diagnostic &d : diagnostics)
        a.push_back(toJson(d));
    Json root;
    root["diagnostics"] = a;
    return visibleJson(root.dump(2)) + '\n';
}

} // namespace rosarch::DiagnosticsJson
