#include "artifacts/checkreport.h"
#include "artifacts/diagnosticsjson.h"
#include "artifacts/jsonsupport.h"
#include "core/diagnostickind.h"
#include "core/visibletext.h"

#include <QDir>
#include <QUrl>
#include <QXmlStreamWriter>

#include <algorithm>

namespace rosarch {

using JsonSupport::Json;
using JsonSupport::utf8;

namespace {

int rank(Diagnostic::Severity s)
{
    return s == Diagnostic::Severity::Error ? 2 : s == Diagnostic::Severity::Warning ? 1 : 0;
}

QString sarifLevel(Diagnostic::Severity s)
{
    return s == Diagnostic::Severity::Error     ? QStringLiteral("error")
           : s == Diagnostic::Severity::Warning ? QStringLiteral("warning")
                                                : QStringLiteral("note");
}

QString place(const Evidence &e)
{
    if (e.file.isEmpty())
        return {};
    QString out = visibleText(e.file);
    if (e.line > 0) {
        out += QLatin1Char(':') + QString::number(e.line);
        if (e.column > 0)
            out += QLatin1Char(':') + QString::number(e.column);
    }
    return out;
}

/// A SARIF physicalLocation for a workspace-relative evidence (none without a file).
Json physicalLocation(const Evidence &e)
{
    Json artifact;
    artifact["uri"] = QUrl::toPercentEncoding(e.file, "/").toStdString();
    artifact["uriBaseId"] = "%SRCROOT%";
    Json location;
    location["artifactLocation"] = artifact;
    if (e.line > 0) {
        Json region;
        region["startLine"] = e.line;
        if (e.column > 0)
            region["startColumn"] = e.column;
        if (e.endLine >= e.line) {
            region["endLine"] = e.endLine;
            if (e.endColumn > 0 && (e.endLine > e.line || e.endColumn > e.column))
                region["endColumn"] = e.endColumn;
        }
        location["region"] = region;
    }
    return location;
}

} // namespace

CheckReport::CheckReport(const QList<Diagnostic> &diagnostics, const QSet<QString> &baseline,
                         Diagnostic::Severity failOn, bool failNever)
{
    QSet<QString> seen;
    for (const Diagnostic &d : diagnostics) {
        CheckFinding f;
        f.diagnostic = d;
        f.key = d.key();
        // One finding reached twice (a file included from two roots) is one finding.
        if (seen.contains(f.key + place(d.evidence)))
            continue;
        seen.insert(f.key + place(d.evidence));
        f.baselined = d.isIn(baseline);
        f.failing = !failNever && !f.baselined && rank(d.severity) >= rank(failOn);
        m_findings.append(f);
    }
}

int CheckReport::failing() const
{
    return int(std::count_if(m_findings.begin(), m_findings.end(),
                             [](const CheckFinding &f) { return f.failing; }));
}

int CheckReport::baselined() const
{
    return int(std::count_if(m_findings.begin(), m_findings.end(),
                             [](const CheckFinding &f) { return f.baselined; }));
}

int CheckReport::count(Diagnostic::Severity severity) const
{
    return int(std::count_if(m_findings.begin(), m_findings.end(), [&](const CheckFinding &f) {
        return f.diagnostic.severity == severity;
    }));
}

QString CheckReport::text() const
{
    QString out;
    for (const CheckFinding &f : m_findings) {
        const Diagnostic &d = f.diagnostic;
        const QString where = place(d.evidence);
        out += (where.isEmpty() ? QString() : where + QStringLiteral(": ")) +
               Diagnostic::severityName(d.severity) + QStringLiteral(": ") +
               visibleText(d.message) + QStringLiteral(" [") + d.code +
               (f.baselined ? QStringLiteral(", baseline]\n") : QStringLiteral("]\n"));
        for (const Diagnostic::Related &r : d.related)
            out +=
                QStringLiteral("  %1: note: %2\n").arg(place(r.evidence), visibleText(r.message));
        if (d.contexts.size() > 1)
            out += QStringLiteral("  seen in %1 systems: %2\n")
                       .arg(d.contexts.size())
                       .arg(visibleText(d.contexts.join(QStringLiteral(", "))));
    }
    out += QStringLiteral("%1 findings (%2 errors, %3 warnings, %4 notes); %5 in the baseline; "
                          "%6 fail the check.\n")
               .arg(m_findings.size())
               .arg(count(Diagnostic::Severity::Error))
               .arg(count(Diagnostic::Severity::Warning))
               .arg(count(Diagnostic::Severity::Info))
               .arg(baselined())
               .arg(failing());
    return out;
}

QByteArray CheckReport::json(const QString &toolVersion) const
{
    Json findings = Json::array();
    for (const CheckFinding &f : m_findings) {
        Json j = {{"key", utf8(f.key)}};
        j.update(DiagnosticsJson::toJson(f.diagnostic));
        if (!j.contains("related")) // the report has it always, empty or not
            j["related"] = Json::array();
        j["baselined"] = f.baselined;
        j["failing"] = f.failing;
        findings.push_back(j);
    }
    Json root;
    root["version"] = 1;
    root["tool"] = {{"name", "rosarch"}, {"version", utf8(toolVersion)}};
    root["summary"] = {{"findings", m_findings.size()},
                       {"errors", count(Diagnostic::Severity::Error)},
                       {"warnings", count(Diagnostic::Severity::Warning)},
                       {"notes", count(Diagnostic::Severity::Info)},
                       {"baselined", baselined()},
                       {"failing", failing()}};
    root["findings"] = findings;
    return visibleJson(root.dump(2)) + '\n';
}

QByteArray CheckReport::sarif(const QString &workspace, const QString &toolVersion) const
{
    // Rules: every kind a finding has, in the catalogue's order, then unknown ones.
    QStringList codes;
    for (const DiagnosticKind &k : DiagnosticKind::all())
        for (const CheckFinding &f : m_findings)
            if (f.diagnostic.code == k.code) {
                codes << k.code;
                break;
            }
    for (const CheckFinding &f : m_findings)
        if (!codes.contains(f.diagnostic.code))
            codes << f.diagnostic.code;
    Json rules = Json::array();
    for (const QString &code : std::as_const(codes)) {
        const DiagnosticKind k = DiagnosticKind::of(code);
        Json rule;
        rule["id"] = utf8(k.code);
        // SARIF's rule name is an identifier: "TopicUnpublished".
        QString name;
        for (const QString &word : k.code.split(QLatin1Char('-'), Qt::SkipEmptyParts))
            name += word.left(1).toUpper() + word.mid(1);
        rule["name"] = utf8(name);
        rule["shortDescription"] = {{"text", utf8(k.title)}};
        rule["fullDescription"] = {{"text", utf8(k.help)}};
        rule["help"] = {{"text", utf8(k.help)},
                        {"markdown", utf8(QStringLiteral("**%1**\n\n%2").arg(k.title, k.help))}};
        rule["defaultConfiguration"] = {{"level", utf8(k.defaultLevel)}};
        rules.push_back(rule);
    }
    Json results = Json::array();
    for (const CheckFinding &f : m_findings) {
        const Diagnostic &d = f.diagnostic;
        Json r;
        r["ruleId"] = utf8(d.code);
        r["ruleIndex"] = codes.indexOf(d.code);
        r["level"] = utf8(sarifLevel(d.severity));
        r["message"] = {{"text", utf8(d.message)}};
        Json locations = Json::array();
        if (!d.evidence.file.isEmpty())
            locations.push_back({{"physicalLocation", physicalLocation(d.evidence)}});
        r["locations"] = locations;
        Json related = Json::array();
        int id = 0;
        for (const Diagnostic::Related &rel : d.related) {
            if (rel.evidence.file.isEmpty())
                continue;
            related.push_back({{"id", id++},
                               {"physicalLocation", physicalLocation(rel.evidence)},
                               {"message", {{"text", utf8(rel.message)}}}});
        }
        if (!related.empty())
            r["relatedLocations"] = related;
        r["partialFingerprints"] = {{"rosarchKey/v1", utf8(f.key)}};
        // The systems (root launch files) a merged finding was reached through, in SARIF's
        // property bag, so that code scanning shows one result with its contexts.
        if (!d.contexts.isEmpty()) {
            Json contexts = Json::array();
            for (const QString &c : d.contexts)
                contexts.push_back(utf8(c));
            r["properties"] = {{"contexts", contexts}};
        }
        if (f.baselined)
            r["suppressions"] = Json::array(
                {{{"kind", "external"}, {"justification", "in the rosarch check baseline"}}});
        results.push_back(r);
    }
    Json driver;
    driver["name"] = "rosarch";
    driver["version"] = utf8(toolVersion);
    driver["semanticVersion"] = utf8(toolVersion);
    driver["rules"] = rules;
    Json run;
    run["tool"] = {{"driver", driver}};
    QString root = QUrl::fromLocalFile(QDir(workspace).absolutePath()).toString();
    if (!root.endsWith(QLatin1Char('/')))
        root += QLatin1Char('/');
    run["originalUriBaseIds"] = {{"%SRCROOT%", {{"uri", utf8(root)}}}};
    run["columnKind"] = "unicodeCodePoints";
    run["results"] = results;
    Json log;
    log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
    log["version"] = "2.1.0";
    log["runs"] = Json::array({run});
    return visibleJson(log.dump(2)) + '\n';
}

QByteArray CheckReport::junit() const
{
    QByteArray out;
    QXmlStreamWriter xml(&out);
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("testsuites"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("rosarch check"));
    xml.writeAttribute(QStringLiteral("tests"), QString::number(qMax(1, int(m_findings.size()))));
    xml.writeAttribute(QStringLiteral("failures"), QString::number(failing()));
    // One suite per kind, in order of first appearance; an empty check is one passing case.
    QStringList codes;
    for (const CheckFinding &f : m_findings)
        if (!codes.contains(f.diagnostic.code))
            codes << f.diagnostic.code;
    if (codes.isEmpty()) {
        xml.writeStartElement(QStringLiteral("testsuite"));
        xml.writeAttribute(QStringLiteral("name"), QStringLiteral("rosarch"));
        xml.writeAttribute(QStringLiteral("tests"), QStringLiteral("1"));
        xml.writeAttribute(QStringLiteral("failures"), QStringLiteral("0"));
        xml.writeStartElement(QStringLiteral("testcase"));
        xml.writeAttribute(QStringLiteral("classname"), QStringLiteral("rosarch"));
        xml.writeAttribute(QStringLiteral("name"), QStringLiteral("architecture checks"));
        xml.writeEndElement();
        xml.writeEndElement();
    }
    for (const QString &code : std::as_const(codes)) {
        QList<const CheckFinding *> of;
        for (const CheckFinding &f : m_findings)
            if (f.diagnostic.code == code)
                of << &f;
        const int failures = int(
            std::count_if(of.begin(), of.end(), [](const CheckFinding *f) { return f->failing; }));
        const int skipped = int(std::count_if(of.begin(), of.end(),
                                              [](const CheckFinding *f) { return f->baselined; }));
        xml.writeStartElement(QStringLiteral("testsuite"));
        xml.writeAttribute(QStringLiteral("name"), QStringLiteral("rosarch.") + code);
        xml.writeAttribute(QStringLiteral("tests"), QString::number(of.size()));
        xml.writeAttribute(QStringLiteral("failures"), QString::number(failures));
        xml.writeAttribute(QStringLiteral("skipped"), QString::number(skipped));
        for (const CheckFinding *f : std::as_const(of)) {
            const Diagnostic &d = f->diagnostic;
            xml.writeStartElement(QStringLiteral("testcase"));
            xml.writeAttribute(QStringLiteral("classname"), QStringLiteral("rosarch.") + code);
            const QString where = place(d.evidence);
            xml.writeAttribute(QStringLiteral("name"),
                               where.isEmpty() ? visibleText(d.message)
                                               : where + QStringLiteral(" ") + visibleText(f->key));
            if (!d.evidence.file.isEmpty())
                xml.writeAttribute(QStringLiteral("file"), visibleText(d.evidence.file));
            if (d.evidence.line > 0)
                xml.writeAttribute(QStringLiteral("line"), QString::number(d.evidence.line));
            if (f->baselined) {
                xml.writeStartElement(QStringLiteral("skipped"));
                xml.writeAttribute(QStringLiteral("message"), QStringLiteral("in the baseline"));
                xml.writeEndElement();
            } else if (f->failing) {
                xml.writeStartElement(QStringLiteral("failure"));
                xml.writeAttribute(QStringLiteral("message"), visibleText(d.message));
                xml.writeAttribute(QStringLiteral("type"), code);
                QString body = Diagnostic::severityName(d.severity) + QStringLiteral(": ") +
                               visibleText(d.message) + QLatin1Char('\n');
                for (const Diagnostic::Related &r : d.related)
                    body +=
                        QStringLiteral("%1: %2\n").arg(place(r.evidence), visibleText(r.message));
                xml.writeCharacters(body);
                xml.writeEndElement();
            } else {
                xml.writeTextElement(QStringLiteral("system-out"),
                                     Diagnostic::severityName(d.severity) + QStringLiteral(": ") +
                                         visibleText(d.message));
            }
            xml.writeEndElement();
        }
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEndDocument();
    return out;
}

bool CheckReport::readBaseline(const QByteArray &data, QSet<QString> *keys, QString *error)
{
    keys->clear();
    const QByteArray trimmed = data.trimmed();
    if (trimmed.startsWith('{')) {
        const Json root = Json::parse(trimmed.toStdString(), nullptr, false);
        if (root.is_discarded() || !root.contains("findings") || !root["findings"].is_array()) {
            if (error)
                *error = QStringLiteral("not a rosarch check JSON report (no \"findings\" list)");
            return false;
        }
        for (const Json &f : root["findings"]) {
            const QString key = JsonSupport::string(f, "key");
            if (!key.isEmpty())
                keys->insert(key);
        }
        return true;
    }
    for (const QByteArray &raw : trimmed.split('\n')) {
        const QString line = QString::fromUtf8(raw).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        if (line.contains(QLatin1Char(' ')) || !line.contains(QLatin1Char(':'))) {
            if (error)
                *error = QStringLiteral("'%1' is not a finding key (code:hash)").arg(line);
            return false;
        }
        keys->insert(line);
    }
    return true;
}

} // namespace rosarch
