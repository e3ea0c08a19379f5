#pragma once

#include "core/languageanalysis.h"
#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cppconstructions.h"
#include "nodes/cpp/cppentrypoints.h"
#include "nodes/cpp/cppfacts.h"
#include "nodes/cpp/cpphelperports.h"
#include "nodes/cpp/cpplinkcontext.h"
#include "nodes/cpp/cppnameresolver.h"
#include "nodes/cpp/cppnodenames.h"
#include "nodes/cpp/cppparameterlinker.h"
#include "nodes/cpp/cppsharednames.h"

#include <QHash>

namespace rosarch {

/// Phase 2 of the C++ analysis (single-threaded): links the per-file facts into node classes,
/// procedural nodes, entry points and component registrations, with the ports of project base
/// classes. Names and types are resolved by CppNameResolver, ports created through helpers
/// found by CppHelperPorts.
class CppNodeLinker
{
public:
    explicit CppNodeLinker(const QList<CppFileFacts> &files);
    // The resolver and the helper ports refer to this object's members.
    CppNodeLinker(const CppNodeLinker &) = delete;
    CppNodeLinker &operator=(const CppNodeLinker &) = delete;

    LanguageAnalysis link() const;

private:
    AtomicNode classNode(int index, const CppProceduralNode *ownedNode = nullptr) const;
    const CppProceduralNode *ownedNode(int cls) const;
    QList<ChildNode> childNodesOf(int index) const;
    /// The ports class `cls` makes; `templateArguments` type those typed by its template
    /// parameters, as a derived class instantiates it (`inherited`).
    QList<Port> portsOf(int cls, bool inherited,
                        const QHash<QString, QString> &templateArguments = {}) const;
    /// A pluginlib plugin's classifier: the ports it creates through the node it is given.
    int pluginClass(const QString &written, const CppFileFacts &file,
                    QHash<QString, QString> *templateArguments) const;
    AtomicNode pluginNode(int index, const CppPluginExport &exported,
                          const QHash<QString, QString> &templateArguments) const;
    /// What stands for the parameters and template parameters of each class on a plugin's
    /// lineage (the plugin's own code is handed the node by the loader).
    std::map<int, CppSubstitution>
    pluginSubstitutions(int plugin, const QHash<QString, QString> &templateArguments) const;
    QList<Port> pluginPorts(int plugin, const std::map<int, CppSubstitution> &substitutions) const;
    void addProceduralNodes(const CppClassIndex::FunctionRef &ref, QList<AtomicNode> *nodes,
                            QHash<QString, int> *stems) const;
    /// `builderBoundsHit`: the calls from main() not followed (CppEntryPoints' bound)
    void addEntryPoint(const CppClassIndex::FunctionRef &ref, const QList<AtomicNode> &procedural,
                       QList<EntryPoint> *entryPoints, QList<Evidence> *builderBoundsHit) const;

    const QList<CppFileFacts> &m_files;
    CppClassIndex m_index;
    CppSharedNames m_shared;             ///< after the index it reads
    std::vector<CppMemberFacts> m_facts; ///< by class, built up front (resolution keeps pointers)
    std::vector<const CppProceduralNode *> m_ownedNodes;
    QHash<QString, QList<CppClassIndex::FunctionRef>> m_freeFunctionsByName;
    /// Namespace-level aliases of interface types from any file (typedefs in included
    /// headers): package -> alias -> target, and "" -> alias -> target for the workspace.
    QHash<QString, QHash<QString, QString>> m_interfaceAliases;
    CppNameResolver m_names;          ///< after the containers it reads
    CppHelperPorts m_helpers;         ///< after the containers it reads
    CppConstructions m_constructions; ///< after the resolver and the helper ports
    CppParameterLinker m_parameters;  ///< after the resolver and the helper ports
    CppNodeNames m_nodeNames;         ///< after the constructions
    CppEntryPoints m_entryPoints;     ///< after the node names
};

} // namespace rosarch
