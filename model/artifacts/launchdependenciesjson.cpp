#include "artifacts/launchdependenciesjson.h"
#include "artifacts/evidencejson.h"
#include "artifacts/jsonsupport.h"
#include "core/visibletext.h"

#include <nlohmann/json.hpp>

namespace rosarch {

using Json = nlohmann::ordered_json;
using JsonSupport::strings;
using JsonSupport::utf8;

namespace {

Json pairs(const QList<QPair<QString, QString>> &list, const char *first, const char *second)
{
    Json a = Json::array();
    for (const auto &[k, v] : list) {
        Json j;
        j[first] = utf8(k);
        j[second] = utf8(v);
        a.push_back(j);
    }
    return a;
}

Json unresolvedJson(const QList<Unresolved> &list)
{
    Json a = Json::array();
    for (const Unresolved &u : list) {
        Json j;
        j["kind"] = utf8(u.kind);
        j["expression"] = utf8(u.expression);
        j["guess"] = utf8(u.guess);
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
        j["id"] = utf8(i.id);
        j["type"] = utf8(i.type);
        j["nodes"] = strings(i.nodes);
        j["included_launch_files"] = strings(i.includedLaunchFiles);
        Json ns = Json::object();
        for (auto it = i.namespaces.cbegin(); it != i.namespaces.cend(); ++it)
            ns[utf8(it.key())] = strings(it.value());
        j["namespace"] = ns;
        j["file"] = utf8(i.file);
        j["package"] = utf8(i.package);
        j["format"] = utf8(i.format);
        j["parent"] = utf8(i.parentId);
        j["external"] = i.external;
        j["arguments"] = pairs(i.arguments, "name", "value");
        j["condition"] = utf8(i.condition);
        j["active"] = i.active;
        j["unresolved"] = unresolvedJson(i.unresolved);
        j["evidence"] = EvidenceJson::toJson(i.evidence);
        if (!i.interfaceModel.isEmpty())
            j["interface_model"] = utf8(i.interfaceModel);
        files.push_back(j);
    }
    Json nodes = Json::array();
    for (const NodeInstance &n : launch.nodes) {
        Json j;
        j["id"] = utf8(n.id);
        j["node_kind"] = utf8(n.nodeKind);
        j["exec_name"] = utf8(n.execName);
        j["class_name"] = utf8(n.className);
        j["node_name"] = utf8(n.nodeName);
        j["namespace"] = utf8(n.nameSpace);
        if (n.guessedNamespace)
            j["namespace_unresolved"] = true;
        if (n.guessedName)
            j["node_name_unresolved"] = true;
        if (!n.interfaceModel.isEmpty())
            j["interface_model"] = utf8(n.interfaceModel);
        j["package"] = utf8(n.package);
        j["class_id"] = utf8(n.classId);
        j["launch_file"] = utf8(n.launchFileId);
        j["container"] = utf8(n.container);
        j["lifecycle"] = n.lifecycle;
        j["remaps"] = pairs(n.remaps, "from", "to");
        for (int i : n.guessedRemaps) // the target rests on a guess
            if (i >= 0 && i < int(j["remaps"].size()))
                j["remaps"][size_t(i)]["unresolved"] = true;
        j["parameters"] = pairs(n.parameters, "name", "value");
        Json effective = Json::array();
        for (const ParameterSetting &p : n.effectiveParameters) {
            Json e;
            e["name"] = utf8(p.name);
            e["value"] = utf8(p.value);
            e["source"] = utf8(p.source);
            // where it is set: the YAML line, the launch line, or the declaration in code (a
            // navigation stack has a hundred thousand of these: a line, not a range)
            e["file"] = utf8(p.evidence.file);
            e["line"] = p.evidence.line;
            effective.push_back(e);
        }
        j["effective_parameters"] = effective;
        Json plugins = Json::array();
        for (const ParameterSetting &p : n.plugins)
            plugins.push_back({{"name", utf8(p.name)},
                               {"class", utf8(p.value)},
                               {"file", utf8(p.evidence.file)},
                               {"line", p.evidence.line}});
        j["plugins"] = plugins;
        j["condition"] = utf8(n.condition);
        j["active"] = n.active;
        if (n.activeByGuess)
            j["active_by_guess"] = true;
        if (!n.parentNode.isEmpty())
            j["parent_node"] = utf8(n.parentNode);
        j["unresolved"] = unresolvedJson(n.unresolved);
        j["evidence"] = EvidenceJson::toJson(n.evidence);
        JsonSupport::putMarks(j, n.marks);
        nodes.push_back(j);
    }
    Json args = Json::array();
    for (const LaunchArgument &a : launch.arguments) {
        Json j;
        j["name"] = utf8(a.name);
        j["default"] = utf8(a.defaultValue);
        j["has_default"] = a.hasDefault;
        j["description"] = utf8(a.description);
        j["launch_file"] = utf8(a.launchFile);
        j["evidence"] = EvidenceJson::toJson(a.evidence);
        args.push_back(j);
    }
    Json root;
    root["list_launch_file"] = files;
    root["list_atom_node_instances"] = nodes;
    root["entry_points"] = strings(launch.entryPoints);
    root["launch_arguments"] = args;
    root["launch_files"] = strings(launch.launchFiles);
    return visibleJson(root.dump(2)) + '\n';
}

} // namespace rosarch
