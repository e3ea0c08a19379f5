#include "launchdependenciesjson.h"
#include "evidencejson.h"

#include <nlohmann/json.hpp>

namespace rosarch {

using Json = nlohmann::ordered_json;

namespace {

std::string s(const QString &q)
{
    return q.toStdString();
}

Json strings(const QStringList &list)
{
    Json a = Json::array();
    for (const QString &v : list)
        a.push_back(s(v));
    return a;
}

Json pairs(const QList<QPair<QString, QString>> &list, const char *first, const char *second)
{
    Json a = Json::array();
    for (const auto &[k, v] : list) {
        Json j;
        j[first] = s(k);
        j[second] = s(v);
        a.push_back(j);
    }
    return a;
}

Json unresolvedJson(const QList<Unresolved> &list)
{
    Json a = Json::array();
    for (const Unresolved &u : list) {
        Json j;
        j["kind"] = s(u.kind);
        j["expression"] = s(u.expression);
        j["guess"] = s(u.guess);
        j["evidence"] = EvidenceJson::toJson(u.evidence);
        a.push_back(j);
    }
    return a;
}

} // namespace

QByteArray LaunchDependenciesJson::write(const LaunchDependencies &launch)
{
    Json files = Json::array();
    for (const LaunchFileInstance &i : launch.instances) {
        Json j;
        j["id"] = s(i.id);
        j["type"] = s(i.type);
        j["nodes"] = strings(i.nodes);
        j["included_launch_files"] = strings(i.includedLaunchFiles);
        Json ns = Json::object();
        for (auto it = i.namespaces.cbegin(); it != i.namespaces.cend(); ++it)
            ns[s(it.key())] = strings(it.value());
        j["namespace"] = ns;
        j["file"] = s(i.file);
        j["package"] = s(i.package);
        j["format"] = s(i.format);
        j["parent"] = s(i.parentId);
        j["external"] = i.external;
        j["arguments"] = pairs(i.arguments, "name", "value");
        j["condition"] = s(i.condition);
        j["active"] = i.active;
        j["unresolved"] = unresolvedJson(i.unresolved);
        j["evidence"] = EvidenceJson::toJson(i.evidence);
        files.push_back(j);
    }
    Json nodes = Json::array();
    for (const NodeInstance &n : launch.nodes) {
        Json j;
        j["id"] = s(n.id);
        j["node_kind"] = s(n.nodeKind);
        j["exec_name"] = s(n.execName);
        j["class_name"] = s(n.className);
        j["node_name"] = s(n.nodeName);
        j["namespace"] = s(n.nameSpace);
        j["package"] = s(n.package);
        j["class_id"] = s(n.classId);
        j["launch_file"] = s(n.launchFileId);
        j["container"] = s(n.container);
        j["lifecycle"] = n.lifecycle;
        j["remaps"] = pairs(n.remaps, "from", "to");
        j["parameters"] = pairs(n.parameters, "name", "value");
        j["condition"] = s(n.condition);
        j["active"] = n.active;
        j["unresolved"] = unresolvedJson(n.unresolved);
        j["evidence"] = EvidenceJson::toJson(n.evidence);
        nodes.push_back(j);
    }
    Json args = Json::array();
    for (const LaunchArgument &a : launch.arguments) {
        Json j;
        j["name"] = s(a.name);
        j["default"] = s(a.defaultValue);
        j["has_default"] = a.hasDefault;
        j["description"] = s(a.description);
        j["launch_file"] = s(a.launchFile);
        j["evidence"] = EvidenceJson::toJson(a.evidence);
        args.push_back(j);
    }
    Json root;
    root["list_launch_file"] = files;
    root["list_atom_node_instances"] = nodes;
    root["launch_arguments"] = args;
    root["launch_files"] = strings(launch.launchFiles);
    return QByteArray::fromStdString(root.dump(2)) + '\n';
}

} // namespace rosarch
