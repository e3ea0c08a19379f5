#include "artifacts/atomicnodesjson.h"
#include "artifacts/evidencejson.h"
#include "artifacts/jsonsupport.h"
#include "artifacts/parameterjson.h"
#include "core/visibletext.h"

#include <nlohmann/json.hpp>

namespace rosarch {

using Json = nlohmann::ordered_json;
using JsonSupport::strings;
using JsonSupport::utf8;

namespace {

Json portJson(const Port &p)
{
    Json j;
    j["id"] = utf8(p.id);
    j["kind"] = utf8(portKindName(p.kind));
    j["name"] = utf8(p.name);
    j["type"] = utf8(p.type);
    if (!p.typeIsResolved()) // an expression as written, not a type ROS knows
        j["type_resolved"] = false;
    j["callback"] = utf8(p.callback);
    j["name_origin"] = utf8(nameOriginName(p.nameOrigin));
    if (!p.nameExpression.isEmpty())
        j["name_expression"] = utf8(p.nameExpression);
    if (!p.parameter.isEmpty())
        j["parameter"] = utf8(p.parameter);
    if (!p.parameterPrefix.isEmpty())
        j["parameter_prefix"] = utf8(p.parameterPrefix);
    if (!p.parameterSuffix.isEmpty())
        j["parameter_suffix"] = utf8(p.parameterSuffix);
    if (!p.guard.isEmpty())
        j["guard"] = utf8(p.guard);
    if (!p.guardParameter.isEmpty())
        j["guard_parameter"] = utf8(p.guardParameter);
    if (!p.guardDefault.isEmpty())
        j["guard_default"] = utf8(p.guardDefault);
    if (!p.via.isEmpty())
        j["via"] = utf8(p.via);
    if (!p.qos.isEmpty())
        j["qos"] = utf8(p.qos);
    if (p.inherited)
        j["inherited"] = true;
    j["evidence"] = EvidenceJson::toJson(p.evidence);
    if (!p.viaEvidence.isEmpty()) {
        Json chain = Json::array();
        for (const Evidence &e : p.viaEvidence)
            chain.push_back(EvidenceJson::toJson(e));
        j["via_evidence"] = chain;
    }
    JsonSupport::putMarks(j, p.marks);
    return j;
}

Json nodeJson(const AtomicNode &n)
{
    Json j;
    j["id"] = utf8(n.id);
    j["class_name"] = utf8(n.className);
    j["node_name"] = utf8(n.nodeName);
    j["header_file_paths"] = strings(n.headerFiles);
    j["source_file_paths"] = strings(n.sourceFiles);
    j["description"] = utf8(n.description);
    j["compile_type"] = utf8(compileTypeName(n.compileType));
    j["execution"] = utf8(n.execution());
    j["qualified_name"] = utf8(n.qualifiedName);
    j["executables"] = strings(n.executables);
    j["plugins"] = strings(n.plugins);
    j["base_classes"] = strings(n.baseClasses);
    j["lifecycle"] = n.lifecycle;
    j["procedural"] = n.procedural;
    if (n.isPlugin()) {
        j["kind"] = "plugin";
        j["plugin_interface"] = utf8(n.pluginInterface);
    }
    j["evidence"] = EvidenceJson::toJson(n.evidence);
    Json ports = Json::array();
    for (const Port &p : n.ports)
        ports.push_back(portJson(p));
    j["ports"] = ports;
    if (!n.children.isEmpty()) {
        Json children = Json::array();
        for (const ChildNode &c : n.children)
            children.push_back({{"class", utf8(c.className)},
                                {"node_name", utf8(c.nodeName)},
                                {"namespace", utf8(c.nameSpace)},
                                {"evidence", EvidenceJson::toJson(c.evidence)}});
        j["child_nodes"] = children;
    }
    if (!n.constructions.isEmpty()) { // built in an executable's own code
        Json built = Json::array();
        for (const NodeConstruction &k : n.constructions) {
            Json ports = Json::array();
            for (const Port &p : k.ports)
                ports.push_back(portJson(p));
            Json kj = {{"class", utf8(k.className)},
                       {"executable", utf8(k.executable)},
                       {"node_name", utf8(k.nodeName)}};
            if (!k.guard.isEmpty())
                kj["guard"] = utf8(k.guard);
            kj["ports"] = ports;
            kj["evidence"] = EvidenceJson::toJson(k.evidence);
            built.push_back(kj);
        }
        j["constructions"] = built;
    }
    j["parameters"] = ParameterJson::toJson(n.parameters);
    if (n.acceptsUndeclared)
        j["accepts_undeclared"] = true;
    JsonSupport::putMarks(j, n.marks);
    return j;
}

bool readPort(const Json &j, Port *p, QString *error)
{
    if (!j.is_object()) {
        *error = QStringLiteral("a port is not an object");
        return false;
    }
    p->id = JsonSupport::string(j, "id");
    if (!portKindFromName(JsonSupport::string(j, "kind"), &p->kind)) {
        *error = QStringLiteral("port %1 has an unknown kind '%2'")
                     .arg(p->id, JsonSupport::string(j, "kind"));
        return false;
    }
    p->name = JsonSupport::string(j, "name");
    p->type = JsonSupport::string(j, "type");
    p->callback = JsonSupport::string(j, "callback");
    const QString origin = JsonSupport::string(j, "name_origin");
    for (NameOrigin o : {NameOrigin::Literal, NameOrigin::Member, NameOrigin::Local,
                         NameOrigin::Parameter, NameOrigin::Expression})
        if (nameOriginName(o) == origin)
            p->nameOrigin = o;
    p->nameExpression = JsonSupport::string(j, "name_expression");
    p->parameter = JsonSupport::string(j, "parameter");
    p->parameterPrefix = JsonSupport::string(j, "parameter_prefix");
    p->parameterSuffix = JsonSupport::string(j, "parameter_suffix");
    p->guard = JsonSupport::string(j, "guard");
    p->guardParameter = JsonSupport::string(j, "guard_parameter");
    p->guardDefault = JsonSupport::string(j, "guard_default");
    p->via = JsonSupport::string(j, "via");
    p->marks = JsonSupport::marks(j);
    p->qos = JsonSupport::string(j, "qos");
    p->inherited = j.value("inherited", false);
    if (j.contains("evidence"))
        p->evidence = EvidenceJson::fromJson(j["evidence"]);
    if (j.contains("via_evidence") && j["via_evidence"].is_array())
        for (const Json &e : j["via_evidence"])
            p->viaEvidence.append(EvidenceJson::fromJson(e));
    return true;
}

/// The "ports" array of `j` (none when absent), appended to `ports`.
bool readPorts(const Json &j, QList<Port> *ports, QString *error)
{
    if (!j.contains("ports") || !j["ports"].is_array())
        return true;
    for (const Json &pj : j["ports"]) {
        Port p;
        if (!readPort(pj, &p, error))
            return false;
        ports->append(p);
    }
    return true;
}

} // namespace

QByteArray AtomicNodesJson::write(const AtomicNodeList &list)
{
    Json packages = Json::array();
    auto packageEntry = [&](const QString &name, const QString &buildType, const QString &path) {
        Json p;
        p["package_name"] = utf8(name);
        p["build_type"] = utf8(buildType);
        p["path"] = utf8(path);
        Json nodes = Json::array();
        for (const AtomicNode *n : list.nodesOfPackage(name))
            nodes.push_back(nodeJson(*n));
        p["list_atomic_ros_node_classifiers"] = nodes;
        packages.push_back(p);
    };
    for (const RosPackage &pkg : list.packages)
        packageEntry(pkg.name, pkg.buildType, pkg.path);
    // Nodes outside any package (a folder without package.xml) are listed under "".
    if (!list.nodesOfPackage(QString()).isEmpty())
        packageEntry(QString(), QString(), QString());
    Json root;
    root["list_packages"] = packages;
    // names helper code declares on whichever node it is handed (not judged undeclared)
    if (!list.helperParameters.isEmpty())
        root["helper_parameters"] = ParameterJson::toJson(list.helperParameters);
    return visibleJson(root.dump(2)) + '\n';
}

bool AtomicNodesJson::read(const QByteArray &json, AtomicNodeList *list, QString *error)
{
    const Json root = Json::parse(json.constBegin(), json.constEnd(), nullptr, false);
    if (root.is_discarded() || !root.is_object()) {
        *error = QStringLiteral("not a JSON object");
        return false;
    }
    const auto packages = root.find("list_packages");
    if (packages == root.end() || !packages->is_array()) {
        *error = QStringLiteral("missing list_packages");
        return false;
    }
    AtomicNodeList out;
    for (const Json &pj : *packages) {
        RosPackage pkg;
        pkg.name = JsonSupport::string(pj, "package_name");
        pkg.buildType = JsonSupport::string(pj, "build_type");
        pkg.path = JsonSupport::string(pj, "path");
        if (!pkg.name.isEmpty())
            out.packages.append(pkg);
        const auto nodes = pj.find("list_atomic_ros_node_classifiers");
        if (nodes == pj.end() || !nodes->is_array())
            continue;
        for (const Json &nj : *nodes) {
            AtomicNode n;
            n.id = JsonSupport::string(nj, "id");
            n.className = JsonSupport::string(nj, "class_name");
            n.nodeName = JsonSupport::string(nj, "node_name");
            n.packageName = pkg.name;
            n.headerFiles = JsonSupport::stringList(nj, "header_file_paths");
            n.sourceFiles = JsonSupport::stringList(nj, "source_file_paths");
            n.description = JsonSupport::string(nj, "description");
            n.marks = JsonSupport::marks(nj);
            n.compileType = JsonSupport::string(nj, "compile_type") == QLatin1String("python")
                                ? AtomicNode::CompileType::Python
                                : AtomicNode::CompileType::Cpp;
            n.qualifiedName = JsonSupport::string(nj, "qualified_name");
            n.executables = JsonSupport::stringList(nj, "executables");
            n.plugins = JsonSupport::stringList(nj, "plugins");
            if (n.executables.isEmpty() && n.plugins.isEmpty() &&
                !JsonSupport::string(nj, "execution").isEmpty())
                n.executables.append(JsonSupport::string(nj, "execution"));
            n.baseClasses = JsonSupport::stringList(nj, "base_classes");
            n.lifecycle = nj.value("lifecycle", false);
            n.procedural = nj.value("procedural", false);
            if (JsonSupport::string(nj, "kind") == QLatin1String("plugin"))
                n.pluginInterface = JsonSupport::string(nj, "plugin_interface");
            if (nj.contains("evidence"))
                n.evidence = EvidenceJson::fromJson(nj["evidence"]);
            if (!readPorts(nj, &n.ports, error))
                return false;
            if (nj.contains("child_nodes") && nj["child_nodes"].is_array()) {
                for (const Json &cj : nj["child_nodes"]) {
                    if (!cj.is_object())
                        continue;
                    ChildNode c;
                    c.className = JsonSupport::string(cj, "class");
                    c.nodeName = JsonSupport::string(cj, "node_name");
                    c.nameSpace = JsonSupport::string(cj, "namespace");
                    if (cj.contains("evidence"))
                        c.evidence = EvidenceJson::fromJson(cj["evidence"]);
                    n.children.append(c);
                }
            }
            if (nj.contains("constructions") && nj["constructions"].is_array()) {
                for (const Json &kj : nj["constructions"]) {
                    if (!kj.is_object())
                        continue;
                    NodeConstruction k;
                    k.className = JsonSupport::string(kj, "class");
                    k.executable = JsonSupport::string(kj, "executable");
                    k.nodeName = JsonSupport::string(kj, "node_name");
                    k.guard = JsonSupport::string(kj, "guard");
                    if (!readPorts(kj, &k.ports, error))
                        return false;
                    if (kj.contains("evidence"))
                        k.evidence = EvidenceJson::fromJson(kj["evidence"]);
                    n.constructions.append(k);
                }
            }
            if (nj.contains("parameters"))
                n.parameters = ParameterJson::fromJson(nj["parameters"]);
            n.acceptsUndeclared = nj.value("accepts_undeclared", false);
            out.nodes.append(n);
        }
    }
    if (root.contains("helper_parameters"))
        out.helperParameters = ParameterJson::fromJson(root["helper_parameters"]);
    *list = std::move(out);
    return true;
}

} // namespace rosarch
