#include "evaluation/evaluationjson.h"
#include "artifacts/jsonsupport.h"
#include "core/visibletext.h"

#include <cmath>

namespace rosarch {

namespace {

using JsonSupport::Json;
using JsonSupport::utf8;

/// Ratios rounded to 4 decimals, so the JSON is stable and readable.
double rounded(double v)
{
    return std::round(v * 10000.0) / 10000.0;
}

Json score(const EvaluationScore &s)
{
    Json j = Json::object();
    j["tp"] = s.tp;
    j["fp"] = s.fp;
    j["fn"] = s.fn;
    j["precision"] = rounded(s.precision);
    j["recall"] = rounded(s.recall);
    j["f1"] = rounded(s.f1);
    return j;
}

Json elements(const QList<UmlElement> &list)
{
    Json a = Json::array();
    for (const UmlElement &e : list)
        a.push_back(Json{{"value", utf8(e.value)}, {"line", e.line}});
    return a;
}

Json diagram(const DiagramEvaluation &d)
{
    Json j = Json::object();
    j["name"] = utf8(d.name);
    j["reference_file"] = utf8(d.referenceFile);
    j["recovered_file"] = d.missing ? Json(nullptr) : Json(utf8(d.recoveredFile));
    j["missing"] = d.missing;
    j["total"] = score(d.total);
    Json kinds = Json::array();
    for (const KindEvaluation &k : d.kinds) {
        Json jk = score(k.score);
        jk["kind"] = utf8(k.kind);
        jk["false_positives"] = elements(k.falsePositives);
        jk["false_negatives"] = elements(k.falseNegatives);
        kinds.push_back(jk);
    }
    j["kinds"] = kinds;
    return j;
}

Json level(const LevelEvaluation &l)
{
    Json j = Json::object();
    j["level"] = utf8(umlLevelName(l.level));
    Json kinds = Json::array();
    for (const KindSummary &k : l.kinds)
        kinds.push_back(Json{{"kind", utf8(k.kind)},
                             {"label", utf8(umlKindLabel(k.kind))},
                             {"micro", score(k.micro)},
                             {"macro", score(k.macro)}});
    j["kinds"] = kinds;
    j["micro"] = score(l.micro);
    j["macro"] = score(l.macro);
    Json diagrams = Json::array();
    for (const DiagramEvaluation &d : l.diagrams)
        diagrams.push_back(diagram(d));
    j["diagrams"] = diagrams;
    Json extra = Json::array();
    for (const UmlDiagram &d : l.extra)
        extra.push_back(Json{{"name", utf8(d.name)}, {"file", utf8(d.file)}});
    j["extra_diagrams"] = extra;
    return j;
}

Json input(const UmlModel &m)
{
    Json j = Json::object();
    j["path"] = utf8(m.path);
    Json diagrams = Json::array();
    for (const UmlDiagram &d : m.diagrams) {
        Json jd = Json::object();
        jd["file"] = utf8(d.file);
        jd["name"] = utf8(d.name);
        jd["level"] = utf8(umlLevelName(d.level));
        jd["elements"] = int(d.elements.size());
        jd["notes"] = JsonSupport::strings(d.notes);
        jd["warnings"] = JsonSupport::strings(d.warnings);
        diagrams.push_back(jd);
    }
    j["diagrams"] = diagrams;
    j["errors"] = JsonSupport::strings(m.errors);
    return j;
}

} // namespace

QByteArray EvaluationJson::write(const Evaluation &evaluation, const UmlModel &reference,
                                 const UmlModel &recovered)
{
    Json root = Json::object();
    Json levels = Json::array();
    for (const LevelEvaluation &l : evaluation.levels)
        levels.push_back(level(l));
    root["levels"] = levels;
    root["reference"] = input(reference);
    root["recovered"] = input(recovered);
    return visibleJson(root.dump(2)) + '\n';
}

} // namespace rosarch
