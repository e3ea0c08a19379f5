#include "artifacts/nodlwriter.h"

#include "artifacts/jsonsupport.h"
#include "core/qos.h"
#include "core/visibletext.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSaveFile>
#include <QSet>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace rosarch {

using Json = nlohmann::ordered_json;
using JsonSupport::utf8;

namespace {

QRegularExpression anchored(const QString &pattern)
{
    return QRegularExpression(QRegularExpression::anchoredPattern(pattern));
}

// The `rosName` and `rosType` patterns of nodl.schema.yaml: what NoDL takes as a name and a type.
bool isNodlName(const QString &name)
{
    static const QRegularExpression re =
        anchored(QStringLiteral("[A-Za-z]|[/~A-Za-z][A-Za-z0-9_/]*[A-Za-z0-9_]"));
    return re.match(name).hasMatch();
}

bool isNodlType(const QString &type)
{
    static const QRegularExpression re =
        anchored(QStringLiteral("[a-zA-Z][a-zA-Z0-9_]*(/(msg|srv|action))?/[A-Z][a-zA-Z0-9]*"));
    return re.match(type).hasMatch();
}

/// generate_parameter_library's name of a ROS parameter type, which NoDL uses ("int",
/// "int_array"); "none" when the declaration leaves the type open, as `ros2 nodl describe`
/// writes an unset one.
QString nodlParameterType(const QString &type)
{
    if (type.isEmpty())
        return QStringLiteral("none");
    QString t = type;
    if (t.startsWith(QLatin1String("integer")))
        t.replace(0, 7, QStringLiteral("int"));
    return t;
}

/// `text` (a value as the model writes it) as a JSON value of the scalar type `scalar` ("bool",
/// "integer", "double", "string", or "byte" for a byte_array's item); false when it is not a
/// literal of that type, e.g. an expression left as written.
bool scalarValue(const QString &scalar, const QString &text, Json *out)
{
    const QString t = text.trimmed();
    if (scalar == QLatin1String("bool")) {
        if (t == QLatin1String("true") || t == QLatin1String("True"))
            *out = true;
        else if (t == QLatin1String("false") || t == QLatin1String("False"))
            *out = false;
        else
            return false;
        return true;
    }
    if (scalar == QLatin1String("integer") || scalar == QLatin1String("byte")) {
        static const QRegularExpression integer =
            anchored(QStringLiteral("([-+]?)(0[xX][0-9a-fA-F]+|[0-9]+)[uUlL]*"));
        const QRegularExpressionMatch m = integer.match(t);
        if (!m.hasMatch())
            return false;
        const QString digits = m.captured(2);
        bool ok = false;
        qint64 v = digits.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                       ? digits.mid(2).toLongLong(&ok, 16)
                       : digits.toLongLong(&ok, 10);
        if (!ok)
            return false;
        if (m.captured(1) == QLatin1String("-"))
            v = -v;
        if (scalar == QLatin1String("byte") && (v < 0 || v > 255))
            return false;
        *out = v;
        return true;
    }
    if (scalar == QLatin1String("double")) {
        QString d = t;
        if (d.size() > 1 && (d.endsWith(u'f') || d.endsWith(u'F')) &&
            (d.at(d.size() - 2).isDigit() || d.at(d.size() - 2) == u'.'))
            d.chop(1); // a C++ float literal, 0.5f
        bool ok = false;
        const double v = d.toDouble(&ok);
        if (!ok || !std::isfinite(v)) // JSON has no NaN or infinity
            return false;
        *out = v;
        return true;
    }
    if (scalar == QLatin1String("string")) {
        *out = utf8(text);
        return true;
    }
    return false;
}

/// The items of a list as the model writes it ("[a, b]", or Python's "['a', 'b']" with the
/// quotes taken off); false when `text` is not a list.
bool listItems(const QString &text, QStringList *items)
{
    const QString t = text.trimmed();
    if (!t.startsWith(u'[') || !t.endsWith(u']'))
        return false;
    const QString inner = t.mid(1, t.size() - 2);
    if (inner.trimmed().isEmpty())
        return true;
    QString bare, quotedText;
    QChar quote;
    bool quoted = false;
    auto push = [&] {
        items->append(quoted ? quotedText : bare.trimmed());
        bare.clear();
        quotedText.clear();
        quoted = false;
    };
    for (const QChar c : inner) {
        if (!quote.isNull()) {
            if (c == quote)
                quote = QChar();
            else
                quotedText += c;
        } else if (c == u'\'' || c == u'"') {
            quote = c;
            quoted = true;
        } else if (c == u',') {
            push();
        } else {
            bare += c;
        }
    }
    if (!quote.isNull())
        return false;
    if (quoted || !bare.trimmed().isEmpty())
        push(); // not after a trailing comma
    return true;
}

/// `text` as a JSON value of the ROS parameter type `type`; false when it is not a literal of it.
bool parameterValue(const QString &type, const QString &text, Json *out)
{
    if (!type.endsWith(QLatin1String("_array")))
        return scalarValue(type, text, out);
    const QString item =
        type == QLatin1String("byte_array") ? QStringLiteral("byte") : type.chopped(6);
    QStringList items;
    if (!listItems(text, &items))
        return false;
    Json a = Json::array();
    for (const QString &i : std::as_const(items)) {
        Json v;
        if (!scalarValue(item, i, &v))
            return false;
        a.push_back(v);
    }
    *out = a;
    return true;
}

/// generate_parameter_library's validation of a range as the model writes it: "[from, to]"
/// becomes `bounds` (as `ros2 nodl describe` writes a descriptor's range), "one of [a, b]"
/// becomes `one_of`. The library has no validator for a step: `stepDropped` says it was there.
/// False when the range's values are not literals of the parameter's type.
bool validation(const QString &type, const QString &range, Json *out, bool *stepDropped)
{
    static const QRegularExpression bounds =
        anchored(QStringLiteral(R"(\[([^,\]]+),([^,\]]+)\](?:\s+step\s+(.+))?)"));
    if (type.endsWith(QLatin1String("_array")) || type.isEmpty())
        return false; // the library bounds an array's items with other validators
    const QString oneOf = QStringLiteral("one of ");
    if (range.startsWith(oneOf)) {
        Json values;
        if (!parameterValue(type + QStringLiteral("_array"), range.mid(oneOf.size()), &values) ||
            values.empty())
            return false;
        *out = {{"one_of", Json::array({values})}};
        return true;
    }
    const QRegularExpressionMatch m = bounds.match(range.trimmed());
    Json from, to;
    if (!m.hasMatch() || (type != QLatin1String("integer") && type != QLatin1String("double")) ||
        !scalarValue(type, m.captured(1), &from) || !scalarValue(type, m.captured(2), &to))
        return false;
    *stepDropped = m.hasCaptured(3);
    *out = {{"bounds", Json::array({from, to})}};
    return true;
}

/// A note that an item is declared under a condition, for the item's description.
QString guardNote(const QString &what, const QString &guard)
{
    return guard.isEmpty() ? QString()
                           : QStringLiteral("%1 only when `%2`.").arg(what, guard.simplified());
}

QString joined(const QString &a, const QString &b)
{
    return a.isEmpty() ? b : b.isEmpty() ? a : a + u' ' + b;
}

Json parametersJson(const QList<ParameterDeclaration> &declared, QStringList *notes)
{
    QList<const ParameterDeclaration *> kept;
    QSet<QString> seen;
    for (const ParameterDeclaration &p : declared) {
        // ROS's own parameters are every node's, as `ros2 nodl describe` leaves them out.
        if (p.name.isEmpty() || isBuiltinParameter(p.name) || seen.contains(p.name))
            continue;
        if (p.name.contains(u'{')) {
            // NoDL keys a parameter by the name a node has at run time; a name that depends
            // on the instance or on code is none, and a placeholder would be taken for one.
            *notes << QStringLiteral("parameter %1: name decided at run time").arg(p.name);
            continue;
        }
        seen.insert(p.name);
        kept.append(&p);
    }
    std::stable_sort(kept.begin(), kept.end(),
                     [](const auto *a, const auto *b) { return a->name < b->name; });
    Json out = Json::object();
    for (const ParameterDeclaration *p : std::as_const(kept)) {
        const QString label = QStringLiteral("parameter ") + p->name;
        Json j;
        j["type"] = utf8(nodlParameterType(p->type));
        if (p->hasDefault) {
            Json value;
            if (!p->type.isEmpty() && parameterValue(p->type, p->defaultValue, &value))
                j["default_value"] = value;
            else
                *notes << QStringLiteral("%1: default `%2` is not a literal of its type; left out")
                              .arg(label, p->defaultValue);
        }
        const QString description =
            joined(p->description, guardNote(QStringLiteral("Declared"), p->guard));
        if (!description.isEmpty())
            j["description"] = utf8(description);
        if (p->readOnly)
            j["read_only"] = true;
        if (!p->range.isEmpty()) {
            Json v;
            bool stepDropped = false;
            if (validation(p->type, p->range, &v, &stepDropped))
                j["validation"] = v;
            else
                *notes << QStringLiteral("%1: range `%2` left out").arg(label, p->range);
            if (stepDropped)
                *notes
                    << QStringLiteral("%1: the step of range `%2` left out").arg(label, p->range);
        }
        if (p->dynamicTyping)
            *notes << label + QStringLiteral(": takes a value of any type (dynamic_typing)");
        out[utf8(p->name)] = j;
    }
    return out;
}

/// The history and depth a QoS argument as written settles: a depth (`10`), `QoS(10)`,
/// `KeepLast(5)`, `depth=5`, keep-all, or a ROS profile by its name; "" when it does not.
QString historyOf(const QString &written, int *depth)
{
    const QString t = QString(written).remove(u' ');
    static const QRegularExpression keepAll(QStringLiteral("keep_?all"),
                                            QRegularExpression::CaseInsensitiveOption);
    if (keepAll.match(t).hasMatch())
        return QStringLiteral("KEEP_ALL");
    static const QRegularExpression depthOnly = anchored(QStringLiteral("([0-9]+)[uUlL]*"));
    static const QRegularExpression explicitDepth(
        QStringLiteral(R"((?:QoS[({]|KeepLast[({]|keep_last\(|depth=)([0-9]+)[uUlL]*[)},])"));
    QRegularExpressionMatch m = depthOnly.match(t);
    if (!m.hasMatch())
        m = explicitDepth.match(t);
    if (m.hasMatch() && m.captured(1).toInt() >= 1) {
        *depth = m.captured(1).toInt();
        return QStringLiteral("KEEP_LAST");
    }
    // ROS's profiles by the names rclcpp and rclpy give them (whole identifiers, so that a
    // variable named after one is not taken for it)
    static const QRegularExpression identifier(QStringLiteral("[A-Za-z_][A-Za-z_0-9]*"));
    static const QList<std::pair<QStringList, int>> profiles{
        {{QStringLiteral("SensorDataQoS"), QStringLiteral("qos_profile_sensor_data"),
          QStringLiteral("rmw_qos_profile_sensor_data")},
         5},
        {{QStringLiteral("ServicesQoS"), QStringLiteral("qos_profile_services_default"),
          QStringLiteral("rmw_qos_profile_services_default"),
          QStringLiteral("rmw_qos_profile_default")},
         10},
        {{QStringLiteral("ParametersQoS"), QStringLiteral("ParameterEventsQoS"),
          QStringLiteral("qos_profile_parameters"), QStringLiteral("qos_profile_parameter_events")},
         1000},
        {{QStringLiteral("SystemDefaultsQoS"), QStringLiteral("qos_profile_system_default"),
          QStringLiteral("rmw_qos_profile_system_default")},
         0},
    };
    for (auto it = identifier.globalMatch(t); it.hasNext();) {
        const QString word = it.next().captured();
        for (const auto &[names, d] : profiles) {
            if (!names.contains(word))
                continue;
            *depth = d;
            return d == 0 ? QStringLiteral("SYSTEM_DEFAULT") : QStringLiteral("KEEP_LAST");
        }
    }
    return {};
}

/// NoDL's QoS profile of a QoS argument as written; `settled` says whether the text settles
/// the history and the reliability, which NoDL requires. What it does not settle is written as
/// SYSTEM_DEFAULT, as `ros2 nodl describe` writes a policy it cannot observe.
Json qosJson(const QString &written, bool *settled)
{
    int depth = 0;
    const QString history = historyOf(written, &depth);
    const QosProfile q = QosProfile::fromWritten(written);
    const bool systemDefault = history == QLatin1String("SYSTEM_DEFAULT");
    const bool bestAvailable = written.contains(QLatin1String("BestAvailable")) ||
                               written.contains(QLatin1String("BEST_AVAILABLE"));
    const char *reliability = q.reliability == QosProfile::Reliability::Reliable     ? "RELIABLE"
                              : q.reliability == QosProfile::Reliability::BestEffort ? "BEST_EFFORT"
                              : bestAvailable ? "BEST_AVAILABLE"
                              : systemDefault ? "SYSTEM_DEFAULT"
                                              : nullptr;
    const char *durability = q.durability == QosProfile::Durability::Volatile ? "VOLATILE"
                             : q.durability == QosProfile::Durability::TransientLocal
                                 ? "TRANSIENT_LOCAL"
                             : bestAvailable ? "BEST_AVAILABLE"
                             : systemDefault ? "SYSTEM_DEFAULT"
                                             : nullptr;
    *settled = !history.isEmpty() && reliability;
    Json j;
    j["history"] = history.isEmpty() ? std::string("SYSTEM_DEFAULT") : utf8(history);
    if (history == QLatin1String("KEEP_LAST"))
        j["depth"] = depth;
    j["reliability"] = reliability ? reliability : "SYSTEM_DEFAULT";
    if (durability)
        j["durability"] = durability;
    return j;
}

const char *arrayOf(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return "publishers";
    case PortKind::Subscriber:
        return "subscriptions";
    case PortKind::ServiceServer:
        return "service_servers";
    case PortKind::ServiceClient:
        return "service_clients";
    case PortKind::ActionServer:
        return "action_servers";
    case PortKind::ActionClient:
        return "action_clients";
    }
    return "";
}

/// The port as a NoDL endpoint, or null when NoDL cannot express it (`notes` says why).
Json endpointJson(const Port &p, QStringList *notes)
{
    const QString label = portKindName(p.kind) + u' ' + p.name;
    // NoDL names what a node has at run time; a name the code computes, or one each instance
    // fills in ({node}, {plugin}), is none, and its placeholder is no ROS name either.
    if (!p.isResolved() || p.name.contains(u'{')) {
        *notes << label + QStringLiteral(": name decided at run time");
        return nullptr;
    }
    if (!isNodlName(p.name)) {
        *notes << label + QStringLiteral(": not a name NoDL accepts");
        return nullptr;
    }
    if (!isNodlType(p.type)) {
        *notes << label + (p.type.isEmpty() ? QStringLiteral(": type unknown")
                                            : QStringLiteral(": type `%1` unknown").arg(p.type));
        return nullptr;
    }
    Json j;
    j["name"] = utf8(p.name);
    j["type"] = utf8(p.type);
    const QString family = portFamilyName(p.kind);
    bool settled = false;
    if (family == QLatin1String("topic")) { // NoDL requires a topic's QoS
        j["qos"] = qosJson(p.qos, &settled);
        if (!settled)
            *notes << label +
                          (p.qos.isEmpty()
                               ? QStringLiteral(": no QoS argument at the call; SYSTEM_DEFAULT "
                                                "written")
                               : QStringLiteral(": QoS `%1` not settled in the code; "
                                                "SYSTEM_DEFAULT written for what it leaves open")
                                     .arg(p.qos));
    } else if (family == QLatin1String("service") && !p.qos.isEmpty()) {
        const Json qos = qosJson(p.qos, &settled);
        if (settled)
            j["qos"] = qos;
        else
            *notes << label +
                          QStringLiteral(": QoS `%1` not settled in the code; left out").arg(p.qos);
    }
    QString description;
    if (p.nameOrigin == NameOrigin::Parameter && !p.parameter.isEmpty())
        description =
            QStringLiteral("Named by parameter `%1` (its default here).").arg(p.parameter);
    description = joined(description, guardNote(QStringLiteral("Exists"), p.guard));
    if (!description.isEmpty())
        j["description"] = utf8(description);
    return j;
}

/// The class's identity, which a NoDL document has no field for (the file's place gives it):
/// kept under NoDL's tool-defined `codegen` metadata, keyed by the tool, for traceability.
Json identityJson(const AtomicNode &n)
{
    Json j;
    j["class"] = utf8(n.qualifiedName.isEmpty() ? n.className : n.qualifiedName);
    if (!n.nodeName.isEmpty())
        j["node_name"] = utf8(n.nodeName);
    if (!n.executables.isEmpty())
        j["executables"] = JsonSupport::strings(n.executables);
    if (!n.plugins.isEmpty())
        j["plugins"] = JsonSupport::strings(n.plugins);
    if (n.lifecycle)
        j["lifecycle"] = true;
    if (n.acceptsUndeclared)
        j["accepts_undeclared_parameters"] = true;
    if (n.evidence.isValid())
        j["source"] = utf8(QStringLiteral("%1:%2").arg(n.evidence.file).arg(n.evidence.line));
    return j;
}

QByteArray document(const AtomicNode &n, QStringList *notes)
{
    Json doc;
    doc["nodl_version"] = 2;
    if (!n.description.isEmpty())
        doc["description"] = utf8(n.description);
    doc["codegen"] = {{"rosarch", identityJson(n)}};
    const Json parameters = parametersJson(n.parameters, notes);
    if (!parameters.empty())
        doc["parameters"] = parameters;
    QMap<QString, QList<std::pair<std::string, Json>>> arrays;
    for (const Port &p : n.ports) {
        Json e = endpointJson(p, notes);
        if (e.is_null())
            continue;
        const std::string key =
            e["name"].get<std::string>() + '\n' + e["type"].get<std::string>() + '\n' + e.dump();
        arrays[QString::fromLatin1(arrayOf(p.kind))].append({key, std::move(e)});
    }
    for (PortKind kind :
         {PortKind::Publisher, PortKind::Subscriber, PortKind::ServiceServer,
          PortKind::ServiceClient, PortKind::ActionServer, PortKind::ActionClient}) {
        auto entries = arrays.value(QString::fromLatin1(arrayOf(kind)));
        if (entries.isEmpty())
            continue; // NoDL leaves an empty collection out
        std::sort(entries.begin(), entries.end(),
                  [](const auto &a, const auto &b) { return a.first < b.first; });
        Json a = Json::array();
        for (qsizetype i = 0; i < entries.size(); ++i)
            if (i == 0 || entries.at(i).first != entries.at(i - 1).first) // the same one once
                a.push_back(entries.at(i).second);
        doc[arrayOf(kind)] = a;
    }
    return visibleJson(doc.dump(2)) + '\n';
}

/// A package's or an executable's name as one path component.
QString pathComponent(const QString &name)
{
    const QString stem = fileStemOf(name);
    return stem.isEmpty() || stem.startsWith(u'.') ? u'_' + stem : stem;
}

/// The file stems of one package's nodes: the first executable (the name NoDL registers a
/// document under), else the class; nodes that would share one get their class added, then a
/// number.
QList<QString> stemsOf(const QList<const AtomicNode *> &nodes)
{
    QList<QString> first;
    for (const AtomicNode *n : nodes)
        first << pathComponent(n->executables.isEmpty() ? n->className : n->executables.first());
    QList<QString> stems = first;
    for (qsizetype i = 0; i < stems.size(); ++i)
        if (first.count(first.at(i)) > 1 && first.at(i) != pathComponent(nodes.at(i)->className))
            stems[i] += u'_' + pathComponent(nodes.at(i)->className);
    QSet<QString> taken;
    for (QString &stem : stems) {
        const QString base = stem;
        for (int k = 2; taken.contains(stem); ++k)
            stem = QStringLiteral("%1_%2").arg(base).arg(k);
        taken.insert(stem);
    }
    return stems;
}

} // namespace

NodlWriter::Documents NodlWriter::write(const AtomicNodeList &list)
{
    Documents out;
    QMap<QString, QList<const AtomicNode *>> byPackage;
    for (const AtomicNode &n : list.nodes) {
        const QString who = QStringLiteral("%1/%2").arg(n.packageName, n.className);
        if (n.isPlugin())
            out.omitted << who + QStringLiteral(": a pluginlib plugin, not a node");
        else if (n.packageName.isEmpty())
            out.omitted << who + QStringLiteral(": outside any package");
        else
            byPackage[n.packageName].append(&n);
    }
    for (auto it = byPackage.cbegin(); it != byPackage.cend(); ++it) {
        const QString package = pathComponent(it.key());
        const QList<QString> stems = stemsOf(it.value());
        for (qsizetype i = 0; i < stems.size(); ++i) {
            QStringList notes;
            out.files.insert(QStringLiteral("%1/%2.nodl.json").arg(package, stems.at(i)),
                             document(*it.value().at(i), &notes));
            for (const QString &note : std::as_const(notes))
                out.omitted << QStringLiteral("%1/%2: %3").arg(package, stems.at(i), note);
        }
    }
    return out;
}

bool NodlWriter::writeTo(const Documents &documents, const QString &dir, QString *error)
{
    const QDir out(dir);
    for (auto it = documents.files.cbegin(); it != documents.files.cend(); ++it) {
        const QString path = out.filePath(it.key());
        QSaveFile file(path);
        if (!QDir().mkpath(QFileInfo(path).path()) || !file.open(QIODevice::WriteOnly) ||
            file.write(it.value()) != it.value().size() || !file.commit()) {
            *error = QStringLiteral("Cannot write %1: %2")
                         .arg(QDir::toNativeSeparators(path), file.errorString());
            return false;
        }
    }
    return true;
}

} // namespace rosarch
