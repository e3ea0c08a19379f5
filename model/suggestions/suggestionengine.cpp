#include "suggestions/suggestionengine.h"
#include "suggestions/deterministicprovider.h"
#include "suggestions/llm/llmclient.h"
#include "suggestions/llm/prompttemplate.h"
#include "suggestions/subsystemgrouper.h"
#include "suggestions/suggestionchecker.h"
#include "suggestions/suggestionitem.h"
#include "suggestions/suggestionsource.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

namespace rosarch {

namespace {

QString compact(const QJsonArray &a)
{
    return QString::fromUtf8(QJsonDocument(a).toJson(QJsonDocument::Compact));
}

QList<Suggestion::Citation> citations(const QJsonValue &evidence)
{
    QList<Suggestion::Citation> out;
    for (const QJsonValue &v : evidence.toArray()) {
        const QJsonObject o = v.toObject();
        Evidence e;
        e.file = o.value(QLatin1String("file")).toString();
        e.line = o.value(QLatin1String("line")).toInt();
        e.column = 1;
        e.endLine = o.value(QLatin1String("end_line")).toInt();
        out.append({e, o.value(QLatin1String("quote")).toString()});
    }
    return out;
}

/// The root launch-file instances and the node instances of each, in artifact order.
QList<QPair<const LaunchFileInstance *, QStringList>> roots(const LaunchDependencies &launch)
{
    QList<QPair<const LaunchFileInstance *, QStringList>> out;
    for (const LaunchFileInstance &root : launch.instances) {
        if (!root.parentId.isEmpty())
            continue;
        QSet<QString> scope{root.id};
        for (const LaunchFileInstance &lf : launch.instances)
            if (scope.contains(lf.parentId))
                scope.insert(lf.id);
        QStringList ids;
        for (const NodeInstance &n : launch.nodes)
            if (scope.contains(n.launchFileId))
                ids << n.id;
        out.append({&root, ids});
    }
    return out;
}

} // namespace

SuggestionEngine::SuggestionEngine(const QString &workspaceRoot, const Recovery &recovery,
                                   const Options &options)
    : m_root(workspaceRoot), m_recovery(recovery), m_options(options)
{
}

LlmRequest SuggestionEngine::prepare(const QString &prompt,
                                     const QMap<QString, QString> &values) const
{
    const PromptTemplate t = PromptTemplate::load(prompt, m_options.promptDir);
    if (!t.isValid() || !t.missingSections().isEmpty()) {
        LlmRequest empty;
        empty.name = prompt;
        return empty;
    }
    LlmRequest r = t.request(values);
    r.repairInstruction = PromptTemplate::load(QStringLiteral("repair_reply"), m_options.promptDir)
                              .section(QStringLiteral("task"));
    return r;
}

QList<SuggestionEngine::PromptJob> SuggestionEngine::describeJobs() const
{
    const SuggestionSource source(m_root);
    QList<PromptJob> jobs;
    QJsonArray batch;
    QStringList ids;
    qsizetype chars = 0;
    auto flush = [&] {
        if (batch.isEmpty())
            return;
        jobs.append({ids.join(QLatin1Char(',')), QString(),
                     prepare(QStringLiteral("describe_nodes"),
                             {{QStringLiteral("nodes"), compact(batch)}})});
        batch = {};
        ids.clear();
        chars = 0;
    };
    for (const AtomicNode &n : m_recovery.nodes.nodes) {
        QJsonArray ports;
        for (const Port &p : n.ports)
            ports.append(QJsonObject{{QLatin1String("kind"), portKindName(p.kind)},
                                     {QLatin1String("name"), p.name},
                                     {QLatin1String("type"), p.type}});
        // The lines above the class hold its comment; the class body shows what it does.
        const QJsonObject node{{QLatin1String("id"), n.id},
                               {QLatin1String("class_name"), n.className},
                               {QLatin1String("node_name"), n.nodeName},
                               {QLatin1String("package"), n.packageName},
                               {QLatin1String("compile_type"), compileTypeName(n.compileType)},
                               {QLatin1String("ports"), ports},
                               {QLatin1String("excerpt"),
                                source.excerpt(n.evidence.file, n.evidence.line - 6,
                                               qMax(n.evidence.line, n.evidence.endLine), 60)}};
        const qsizetype size = QJsonDocument(node).toJson(QJsonDocument::Compact).size();
        if (!batch.isEmpty() &&
            (batch.size() >= m_options.batchSize || chars + size > m_options.maxBatchChars))
            flush();
        batch.append(node);
        ids << n.id;
        chars += size;
    }
    flush();
    return jobs;
}

QList<SuggestionEngine::PromptJob> SuggestionEngine::groupJobs() const
{
    const SuggestionSource source(m_root);
    const SubsystemGrouper grouper(m_recovery);
    QList<PromptJob> jobs;
    for (const auto &[root, ids] : roots(m_recovery.launch)) {
        QJsonArray instances;
        for (const QString &id : ids) {
            const NodeInstance *n = m_recovery.launch.node(id);
            if (!n->active)
                continue;
            instances.append(QJsonObject{
                {QLatin1String("id"), n->id},
                {QLatin1String("node_name"), n->nodeName},
                {QLatin1String("namespace"), n->nameSpace},
                {QLatin1String("class_name"), n->className},
                {QLatin1String("package"), n->package},
                {QLatin1String("executable"), n->execName},
                {QLatin1String("communication"), QJsonArray::fromStringList(grouper.endpoints(*n))},
                {QLatin1String("launch"),
                 source.excerpt(n->evidence.file, n->evidence.line,
                                qMax(n->evidence.line, n->evidence.endLine), 12)}});
        }
        // Two instances form at most one obvious group; there is nothing to ask.
        if (instances.size() < 3)
            continue;
        const int maxGroups = qBound(1, int(instances.size() / 2), 8);
        jobs.append({root->id, root->id,
                     prepare(QStringLiteral("group_subsystems"),
                             {{QStringLiteral("launch_file"),
                               root->file.isEmpty() ? root->type : root->file},
                              {QStringLiteral("launch_id"), root->id},
                              {QStringLiteral("max_groups"), QString::number(maxGroups)},
                              {QStringLiteral("instances"), compact(instances)}})});
    }
    return jobs;
}

QList<SuggestionEngine::PromptJob> SuggestionEngine::resolveJobs() const
{
    const SuggestionSource source(m_root);
    QList<PromptJob> jobs;
    QJsonArray batch;
    QStringList ids;
    auto flush = [&] {
        if (batch.isEmpty())
            return;
        jobs.append({ids.join(QLatin1Char(',')), QString(),
                     prepare(QStringLiteral("resolve_names"),
                             {{QStringLiteral("items"), compact(batch)}})});
        batch = {};
        ids.clear();
    };
    // The same launch file included many times repeats the same unresolved expression; ask
    // once per place in the code (the candidate targets the first occurrence).
    const QList<SuggestionItem> all = SuggestionItem::collect(m_recovery);
    QMap<QString, int> occurrences;
    auto placeKey = [](const SuggestionItem &i) {
        return QStringLiteral("%1|%2|%3|%4")
            .arg(i.kind, i.expression, i.evidence.file)
            .arg(i.evidence.line);
    };
    for (const SuggestionItem &item : all)
        ++occurrences[placeKey(item)];
    QSet<QString> asked;
    for (const SuggestionItem &item : all) {
        if (asked.contains(placeKey(item)))
            continue;
        asked.insert(placeKey(item));
        batch.append(
            QJsonObject{{QLatin1String("occurrences"), occurrences.value(placeKey(item))},
                        {QLatin1String("item_id"), item.id},
                        {QLatin1String("kind"), item.kind},
                        {QLatin1String("element"), item.elementId},
                        {QLatin1String("expression"), item.expression},
                        {QLatin1String("current_guess"), item.guess},
                        {QLatin1String("excerpt"),
                         source.excerpt(item.evidence.file, item.evidence.line - 6,
                                        qMax(item.evidence.line, item.evidence.endLine) + 2, 20)}});
        ids << item.id;
        if (batch.size() >= 10)
            flush();
    }
    flush();
    return jobs;
}

SuggestionReport SuggestionEngine::run() const
{
    SuggestionReport report;
    const SuggestionChecker checker(m_root, m_recovery);
    QSet<QString> seen;
    auto log = [&](const QString &line) {
        if (m_options.logged)
            m_options.logged(line);
    };
    auto offer = [&](Suggestion s) {
        QString reason;
        QString detail;
        const QString who = s.origin.provider;
        if (!checker.check(s, &reason, &detail)) {
            report.discard(reason, QStringLiteral("%1 %2 for %3: %4")
                                       .arg(who, Suggestion::kindName(s.kind), s.targetId, detail));
            return;
        }
        const QString key = s.subjectKey() + QLatin1Char('|') + s.value + QLatin1Char('|') + who;
        if (seen.contains(key)) {
            report.discard(QStringLiteral("duplicate"),
                           QStringLiteral("%1 repeats %2").arg(who, s.subjectKey()));
            return;
        }
        seen.insert(key);
        s.id = QStringLiteral("s%1").arg(report.suggestions.size() + 1);
        report.suggestions.append(s);
    };

    if (m_options.deterministic)
        for (const Suggestion &s : DeterministicProvider(m_root, m_recovery).suggest())
            offer(s);

    const bool useLlm = m_options.llm.isConfigured();
    report.llmUsed = useLlm;
    report.llmModel = useLlm ? m_options.llm.model : QString();
    const LlmClient client(m_options.llm);
    bool stopped = !useLlm;
    struct Task
    {
        Suggestion::Kind kind;
        QList<PromptJob> jobs;
    };
    const QList<Task> tasks{{Suggestion::Kind::NodeDescription, describeJobs()},
                            {Suggestion::Kind::SubsystemGrouping, groupJobs()},
                            {Suggestion::Kind::NameResolution, resolveJobs()}};
    for (const Task &task : tasks) {
        for (PromptJob job : task.jobs) {
            SuggestionReport::PromptUsage usage;
            usage.prompt = job.request.name;
            usage.scope = job.scope;
            usage.chars = job.request.chars();
            usage.estimatedTokens = estimateTokens(usage.chars);
            usage.outcome = stopped ? QStringLiteral("not-sent") : QString();
            if (job.request.messages.isEmpty()) {
                report.errors << QStringLiteral("The prompt template %1 is missing or incomplete.")
                                     .arg(job.request.name);
                usage.outcome = QStringLiteral("template-error");
                report.prompts << usage;
                continue;
            }
            if (stopped || (m_options.cancel && m_options.cancel->load())) {
                report.prompts << usage;
                continue;
            }
            log(QStringLiteral("%1 [%2]: %3 characters, ~%4 tokens")
                    .arg(usage.prompt, usage.scope)
                    .arg(usage.chars)
                    .arg(usage.estimatedTokens));
            job.request.cancel = m_options.cancel;
            if (m_options.progressed) {
                const QString name = usage.prompt;
                job.request.progressed = [this, name](qint64 chars, int) {
                    m_options.progressed(name, chars);
                };
            }
            const LlmResult result = client.complete(job.request);
            usage.sent = true;
            usage.requests = result.requests;
            usage.outcome = result.ok() ? QStringLiteral("ok") : LlmResult::errorName(result.error);
            report.prompts << usage;
            if (!result.ok()) {
                report.errors << result.message;
                if (result.error == LlmResult::Error::NotJson ||
                    result.error == LlmResult::Error::SchemaMismatch) {
                    report.discard(QStringLiteral("reply-") + LlmResult::errorName(result.error),
                                   QStringLiteral("%1 [%2]: %3")
                                       .arg(usage.prompt, usage.scope, result.message));
                } else {
                    stopped = true; // the endpoint is unusable; do not send the remaining prompts
                }
                continue;
            }
            const QString provider = QStringLiteral("llm:") + m_options.llm.model;
            const QDateTime now = QDateTime::currentDateTimeUtc();
            const QJsonObject reply = result.json.toObject();
            const char *listKey = task.kind == Suggestion::Kind::NodeDescription ? "descriptions"
                                  : task.kind == Suggestion::Kind::SubsystemGrouping ? "groups"
                                                                                     : "candidates";
            for (const QJsonValue &v : reply.value(QLatin1String(listKey)).toArray()) {
                const QJsonObject o = v.toObject();
                Suggestion s;
                s.kind = task.kind;
                s.origin = {provider, usage.prompt, now};
                s.rationale = o.value(QLatin1String("rationale")).toString();
                s.evidence = citations(o.value(QLatin1String("evidence")));
                switch (task.kind) {
                case Suggestion::Kind::NodeDescription:
                    s.targetId = o.value(QLatin1String("node_id")).toString();
                    s.value = o.value(QLatin1String("description")).toString().trimmed();
                    break;
                case Suggestion::Kind::SubsystemGrouping:
                    s.targetId = job.launchId;
                    s.value = o.value(QLatin1String("name")).toString().trimmed();
                    for (const QJsonValue &m : o.value(QLatin1String("member_ids")).toArray())
                        s.memberIds << m.toString();
                    break;
                case Suggestion::Kind::NameResolution:
                    s.targetId = o.value(QLatin1String("item_id")).toString();
                    s.value = o.value(QLatin1String("value")).toString().trimmed();
                    break;
                }
                // A reply may only speak about what its prompt asked about.
                if (task.kind != Suggestion::Kind::SubsystemGrouping &&
                    !job.scope.split(QLatin1Char(',')).contains(s.targetId)) {
                    report.discard(
                        QStringLiteral("unknown-target"),
                        QStringLiteral("%1 %2 names '%3', which the prompt did not ask about")
                            .arg(provider, Suggestion::kindName(s.kind), s.targetId));
                    continue;
                }
                offer(s);
            }
        }
    }
    return report;
}

} // namespace rosarch
