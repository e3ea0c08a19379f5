#include "suggestions/suggestionsjson.h"
#include "artifacts/evidencejson.h"
#include "artifacts/jsonsupport.h"
#include "core/visibletext.h"

namespace rosarch {

using JsonSupport::Json;
using JsonSupport::strings;
using JsonSupport::utf8;

namespace {

const char *targetElement(Suggestion::Kind kind)
{
    switch (kind) {
    case Suggestion::Kind::NodeDescription:
        return "atomic-node";
    case Suggestion::Kind::SubsystemGrouping:
        return "launch-file";
    case Suggestion::Kind::NameResolution:
        return "unresolved-item";
    }
    return "";
}

Json suggestionJson(const Suggestion &s)
{
    Json j;
    j["id"] = utf8(s.id);
    j["kind"] = utf8(Suggestion::kindName(s.kind));
    Json target;
    target["element"] = targetElement(s.kind);
    target["id"] = utf8(s.targetId);
    if (s.kind == Suggestion::Kind::SubsystemGrouping)
        target["node_instance_ids"] = strings(s.memberIds);
    j["target"] = target;
    Json proposal;
    switch (s.kind) {
    case Suggestion::Kind::NodeDescription:
        proposal["description"] = utf8(s.value);
        break;
    case Suggestion::Kind::SubsystemGrouping:
        proposal["group_name"] = utf8(s.value);
        proposal["member_ids"] = strings(s.memberIds);
        break;
    case Suggestion::Kind::NameResolution:
        proposal["value"] = utf8(s.value);
        break;
    }
    if (s.quoted)
        proposal["quoted_from_code"] = true;
    j["proposal"] = proposal;
    j["rationale"] = utf8(s.rationale);
    Json evidence = Json::array();
    for (const Suggestion::Citation &c : s.evidence) {
        Json e = EvidenceJson::toJson(c.evidence);
        e["quote"] = utf8(c.quote);
        evidence.push_back(e);
    }
    j["evidence"] = evidence;
    Json origin;
    origin["provider"] = utf8(s.origin.provider);
    origin["prompt"] = utf8(s.origin.prompt);
    origin["timestamp"] = utf8(s.origin.timestamp.toUTC().toString(Qt::ISODateWithMs));
    j["origin"] = origin;
    j["status"] = utf8(Suggestion::statusName(s.status));
    return j;
}

} // namespace

QByteArray SuggestionsJson::write(const SuggestionReport &report)
{
    Json root;
    Json list = Json::array();
    for (const Suggestion &s : report.suggestions)
        list.push_back(suggestionJson(s));
    root["suggestions"] = list;
    Json discarded;
    discarded["total"] = report.discardedTotal();
    Json reasons = Json::object();
    for (auto it = report.discarded.begin(); it != report.discarded.end(); ++it)
        reasons[utf8(it.key())] = it.value();
    discarded["reasons"] = reasons;
    discarded["details"] = strings(report.discardedDetails);
    root["discarded"] = discarded;
    Json prompts;
    prompts["token_estimate"] = "characters / 4";
    qint64 total = 0;
    Json plist = Json::array();
    for (const SuggestionReport::PromptUsage &p : report.prompts) {
        Json j;
        j["prompt"] = utf8(p.prompt);
        j["scope"] = utf8(p.scope);
        j["chars"] = p.chars;
        j["estimated_tokens"] = p.estimatedTokens;
        j["sent"] = p.sent;
        j["requests"] = p.requests;
        j["outcome"] = utf8(p.outcome);
        plist.push_back(j);
        total += p.estimatedTokens;
    }
    prompts["total_estimated_tokens"] = total;
    prompts["list"] = plist;
    root["prompts"] = prompts;
    root["errors"] = strings(report.errors);
    Json llm;
    llm["used"] = report.llmUsed;
    llm["model"] = utf8(report.llmModel);
    root["llm"] = llm;
    return visibleJson(root.dump(2)) + '\n';
}

bool SuggestionsJson::read(const QByteArray &json, SuggestionReport *report, QString *error)
{
    const Json root = Json::parse(json.constBegin(), json.constEnd(), nullptr, false);
    if (root.is_discarded() || !root.is_object() || !root.contains("suggestions") ||
        !root["suggestions"].is_array()) {
        *error = QStringLiteral("not a suggestions.json object");
        return false;
    }
    SuggestionReport out;
    for (const Json &j : root["suggestions"]) {
        Suggestion s;
        s.id = JsonSupport::string(j, "id");
        if (!Suggestion::kindFromName(JsonSupport::string(j, "kind"), &s.kind)) {
            *error = QStringLiteral("suggestion %1 has an unknown kind '%2'")
                         .arg(s.id, JsonSupport::string(j, "kind"));
            return false;
        }
        const Json target = j.value("target", Json::object());
        s.targetId = JsonSupport::string(target, "id");
        s.memberIds = JsonSupport::stringList(target, "node_instance_ids");
        const Json proposal = j.value("proposal", Json::object());
        s.value = s.kind == Suggestion::Kind::NodeDescription
                      ? JsonSupport::string(proposal, "description")
                  : s.kind == Suggestion::Kind::SubsystemGrouping
                      ? JsonSupport::string(proposal, "group_name")
                      : JsonSupport::string(proposal, "value");
        s.quoted = proposal.value("quoted_from_code", false);
        s.rationale = JsonSupport::string(j, "rationale");
        if (j.contains("evidence") && j["evidence"].is_array())
            for (const Json &e : j["evidence"])
                s.evidence.append({EvidenceJson::fromJson(e), JsonSupport::string(e, "quote")});
        const Json origin = j.value("origin", Json::object());
        s.origin.provider = JsonSupport::string(origin, "provider");
        s.origin.prompt = JsonSupport::string(origin, "prompt");
        s.origin.timestamp =
            QDateTime::fromString(JsonSupport::string(origin, "timestamp"), Qt::ISODate);
        if (!Suggestion::statusFromName(JsonSupport::string(j, "status"), &s.status))
            s.status = Suggestion::Status::Pending;
        out.suggestions.append(s);
    }
    if (root.contains("discarded")) {
        const Json &d = root["discarded"];
        if (d.contains("reasons") && d["reasons"].is_object())
            for (auto it = d["reasons"].begin(); it != d["reasons"].end(); ++it)
                if (it.value().is_number_integer())
                    out.discarded.insert(QString::fromStdString(it.key()), it.value().get<int>());
        out.discardedDetails = JsonSupport::stringList(d, "details");
    }
    if (root.contains("prompts") && root["prompts"].contains("list"))
        for (const Json &p : root["prompts"]["list"]) {
            SuggestionReport::PromptUsage u;
            u.prompt = JsonSupport::string(p, "prompt");
            u.scope = JsonSupport::string(p, "scope");
            u.chars = p.value("chars", qint64(0));
            u.estimatedTokens = p.value("estimated_tokens", qint64(0));
            u.sent = p.value("sent", false);
            u.requests = p.value("requests", 0);
            u.outcome = JsonSupport::string(p, "outcome");
            out.prompts.append(u);
        }
    out.errors = JsonSupport::stringList(root, "errors");
    if (root.contains("llm")) {
        out.llmUsed = root["llm"].value("used", false);
        out.llmModel = JsonSupport::string(root["llm"], "model");
    }
    *report = std::move(out);
    return true;
}

} // namespace rosarch
