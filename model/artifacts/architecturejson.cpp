#include "artifacts/architecturejson.h"
#include "artifacts/evidencejson.h"
#include "artifacts/jsonsupport.h"
#include "core/parameterview.h"
#include "core/visibletext.h"

namespace rosarch {

using Json = nlohmann::ordered_json;
using JsonSupport::utf8;

namespace {

Json portJson(const PartPort &p)
{
    Json j;
    j["id"] = utf8(p.id);
    j["kind"] = utf8(portKindName(p.kind));
    j["name"] = utf8(p.name);
    if (!p.nameAsWritten.isEmpty())
        j["name_as_written"] = utf8(p.nameAsWritten);
    j["type"] = utf8(p.type);
    if (!p.type.isEmpty() && !isCanonicalInterfaceType(p.type))
        j["type_resolved"] = false;
    if (!p.resolved || p.guessed)
        j["unresolved"] = true;
    if (p.parameterDerived)
        j["parameter_derived"] = true;
    if (p.remapped)
        j["remapped"] = true;
    if (!p.model.isEmpty())
        j["interface_model"] = utf8(p.model);
    if (!p.guard.isEmpty()) {
        j["guard"] = utf8(p.guard);
        j["active"] = p.active;
    }
    if (p.evidence.isValid())
        j["evidence"] = EvidenceJson::toJson(p.evidence);
    JsonSupport::putMarks(j, p.marks);
    return j;
}

// One entry per parameter, kept small: a navigation stack gives its instances a hundred
// thousand of them. The source says where the value in effect is set: "launch" (the launch
// file), "file:line" (a parameter file), "default" (the declaration), "" (nothing sets it).
Json parametersJson(const QList<InstanceParameter> &parameters)
{
    Json a = Json::array();
    for (const InstanceParameter &p : parameters) {
        Json j;
        j["name"] = utf8(p.name);
        if (!p.plugin.isEmpty())
            j["plugin"] = utf8(p.plugin);
        if (!p.declared)
            j["declared"] = false; // ROS 2 ignores the value
        j["type"] = utf8(p.type);
        j["default"] = p.hasDefault ? Json(utf8(p.defaultValue)) : Json(nullptr);
        j["value"] = p.source.isEmpty() ? Json(nullptr) : Json(utf8(p.value));
        j["source"] =
            p.source == QLatin1String("file")
                ? utf8(QStringLiteral("%1:%2").arg(p.valueEvidence.file).arg(p.valueEvidence.line))
                : utf8(p.source);
        if (!p.description.isEmpty())
            j["description"] = utf8(p.description);
        a.push_back(j);
    }
    return a;
}

Json partJson(const RosNodePart &part, const QList<InstanceParameter> *parameters)
{
    Json j;
    j["id"] = utf8(part.id);
    j["kind"] = part.kind == RosNodePart::Kind::Node ? "node" : "launch";
    j["instance"] = utf8(part.instanceId);
    if (!part.name.isEmpty())
        j["name"] = utf8(part.name);
    j["type"] = utf8(part.typeName);
    j["type_id"] = utf8(part.typeId);
    j["namespace"] = utf8(part.nameSpace);
    j["active"] = part.active;
    if (part.external)
        j["external"] = true;
    if (!part.typed)
        j["typed"] = false;
    if (!part.subsystem.isEmpty())
        j["subsystem"] = utf8(part.subsystem);
    Json ports = Json::array();
    for (const PartPort &p : part.ports)
        ports.push_back(portJson(p));
    j["ports"] = ports;
    if (parameters)
        j["parameters"] = parametersJson(*parameters);
    if (part.evidence.isValid())
        j["evidence"] = EvidenceJson::toJson(part.evidence);
    JsonSupport::putMarks(j, part.marks);
    return j;
}

Json compositeJson(const Composite &c, const QString &ccd,
                   const QHash<QString, QList<InstanceParameter>> &parameters)
{
    Json j;
    j["id"] = utf8(c.instanceId);
    j["launch_file"] = utf8(c.file);
    j["stem"] = utf8(c.stem);
    if (!c.executable.isEmpty())
        j["executable"] = utf8(c.executable);
    j["package"] = utf8(c.package);
    j["parent"] = utf8(c.parentId);
    if (!ccd.isEmpty())
        j["ccd"] = utf8(ccd);
    Json parts = Json::array();
    for (const RosNodePart &p : c.parts) {
        const auto it = p.kind == RosNodePart::Kind::Node ? parameters.constFind(p.instanceId)
                                                          : parameters.constEnd();
        parts.push_back(partJson(p, it == parameters.constEnd() ? nullptr : &*it));
    }
    j["parts"] = parts;
    Json channels = Json::array();
    for (const Channel &ch : c.channels) {
        Json cj = {{"id", utf8(ch.id)},
                   {"kind", utf8(channelKindName(ch.kind))},
                   {"name", utf8(ch.name)},
                   {"type", utf8(ch.type)}};
        JsonSupport::putMarks(cj, ch.marks);
        channels.push_back(cj);
    }
    j["channels"] = channels;
    Json boundary = Json::array();
    for (const BoundaryPort &b : c.boundary) {
        Json bj = {{"id", utf8(b.id)},
                   {"direction", b.isInput() ? "in" : "out"},
                   {"kind", utf8(portKindName(b.kind))},
                   {"name", utf8(b.name)},
                   {"type", utf8(b.type)}};
        if (b.guessed)
            bj["unresolved"] = true;
        boundary.push_back(bj);
    }
    j["boundary_ports"] = boundary;
    Json connections = Json::array();
    for (const Connection &k : c.connections)
        connections.push_back({{"kind", utf8(connectionKindName(k.kind))},
                               {"part", utf8(k.partId)},
                               {"port", utf8(k.portId)},
                               {"target", utf8(k.targetId)}});
    j["connections"] = connections;
    return j;
}

} // namespace

QByteArray ArchitectureJson::write(const Architecture &arch, const QMap<QString, QString> &ccdStems,
                                   const AtomicNodeList *nodes, const LaunchDependencies *launch)
{
    QHash<QString, QList<InstanceParameter>> parameters; // by node instance id
    if (nodes && launch) {
        const ParameterView view(*nodes);
        // the systems as launched; a launch file's own diagram shows the same nodes again
        for (const NodeInstance &n : launch->nodes)
            parameters.insert(n.id, view.of(n));
    }
    Json root;
    Json list = Json::array();
    for (const Composite &c : arch.composites) {
        const QString stem = ccdStems.value(c.instanceId);
        list.push_back(compositeJson(
            c, stem.isEmpty() ? QString() : QStringLiteral("ccd/%1.puml").arg(stem), parameters));
    }
    root["list_composed_ros_node_classifiers"] = list;
    return visibleJson(root.dump(2)) + '\n';
}

} // namespace rosarch
