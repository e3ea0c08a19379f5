#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/diagnostic.h"
#include "core/evidence.h"
#include "core/launchdependencies.h"
#include "core/port.h"
#include "core/rospackage.h"

// The field list of every model value type that crosses a process or goes to disk whole: one
// list per type, used both ways (`f` reads or writes every field). The analysis worker's stream
// (model/pipeline/recoverystream.cpp) and the analysis cache's stage memos
// (model/cache/stagecodec.h) both serialise through them, so a field added to a type is added
// here once. Changing a list means bumping stagestream::kVersion and
// AnalysisCache::kFormatVersion.

namespace rosarch {

template <class F> void fields(Evidence &v, F f)
{
    f(v.file, v.line, v.column, v.endLine, v.endColumn);
}
template <class F> void fields(Diagnostic::Related &v, F f)
{
    f(v.message, v.evidence);
}
template <class F> void fields(Diagnostic &v, F f)
{
    f(v.severity, v.code, v.message, v.evidence, v.related, v.contexts, v.aliases, v.external);
}
template <class F> void fields(Port &v, F f)
{
    f(v.id, v.kind, v.name, v.type, v.callback, v.nameOrigin, v.nameExpression, v.parameter,
      v.parameterPrefix, v.parameterSuffix, v.guard, v.guardParameter, v.guardDefault, v.via, v.qos,
      v.inherited, v.evidence, v.viaEvidence);
}
template <class F> void fields(ChildNode &v, F f)
{
    f(v.className, v.nodeName, v.nameSpace, v.evidence);
}
template <class F> void fields(NodeConstruction &v, F f)
{
    f(v.className, v.executable, v.nodeName, v.guard, v.ports, v.evidence);
}
template <class F> void fields(ParameterDeclaration &v, F f)
{
    f(v.name, v.nameExpression, v.type, v.defaultValue, v.hasDefault, v.readOnly, v.dynamicTyping,
      v.description, v.range, v.guard, v.via, v.inherited, v.evidence);
}
template <class F> void fields(AtomicNode &v, F f)
{
    f(v.id, v.className, v.qualifiedName, v.nodeName, v.packageName, v.headerFiles, v.sourceFiles,
      v.description, v.compileType, v.baseClasses, v.lifecycle, v.procedural, v.executables,
      v.plugins, v.pluginInterface, v.evidence, v.ports, v.children, v.constructions, v.parameters,
      v.acceptsUndeclared);
}
template <class F> void fields(Executable &v, F f)
{
    f(v.kind, v.name, v.target, v.plugin, v.sources, v.evidence);
}
template <class F> void fields(RosPackage &v, F f)
{
    f(v.name, v.buildType, v.path, v.version, v.evidence, v.executables);
}
template <class F> void fields(AtomicNodeList &v, F f)
{
    f(v.workspaceRoot, v.packages, v.nodes, v.diagnostics, v.canceled, v.helperParameters);
}
template <class F> void fields(Unresolved &v, F f)
{
    f(v.kind, v.expression, v.guess, v.evidence);
}
template <class F> void fields(ParameterSetting &v, F f)
{
    f(v.name, v.value, v.source, v.file, v.evidence, v.type, v.wildcard);
}
template <class F> void fields(NodeInstance &v, F f)
{
    f(v.id, v.launchFileId, v.nodeKind, v.package, v.execName, v.className, v.classId, v.nodeName,
      v.nameSpace, v.guessedNamespace, v.guessedName, v.namedByLaunch, v.container, v.lifecycle,
      v.remaps, v.guessedRemaps, v.parameters, v.effectiveParameters, v.plugins, v.condition,
      v.active, v.activeByGuess, v.unresolved, v.evidence, v.interfaceModel, v.modelledPorts,
      v.modelConfig, v.parentNode, v.constructedPorts);
}
template <class F> void fields(LaunchGroupCondition &v, F f)
{
    f(v.condition, v.unless, v.holds, v.undecided, v.evidence);
}
template <class F> void fields(LaunchFileInstance &v, F f)
{
    f(v.id, v.type, v.file, v.package, v.format, v.parentId, v.external, v.nodes,
      v.includedLaunchFiles, v.namespaces, v.arguments, v.condition, v.active, v.unresolved,
      v.evidence, v.interfaceModel, v.modelledPorts, v.modelNamespace, v.groups);
}
template <class F> void fields(LaunchArgument &v, F f)
{
    f(v.name, v.defaultValue, v.hasDefault, v.description, v.launchFile, v.evidence);
}
template <class F> void fields(ExpectedExternal &v, F f)
{
    f(v.name, v.output, v.reason);
}
template <class F> void fields(LaunchDependencies &v, F f)
{
    f(v.launchFiles, v.instances, v.nodes, v.arguments, v.entryPoints, v.viewedTopics, v.externals,
      v.classifierInstances, v.classifierNodes, v.diagnostics, v.canceled);
}
template <class F> void fields(PartPort &v, F f)
{
    f(v.id, v.kind, v.nameAsWritten, v.name, v.type, v.resolved, v.guessed, v.parameterDerived,
      v.remapped, v.remap, v.active, v.guard, v.qos, v.evidence, v.model);
}
template <class F> void fields(RosNodePart &v, F f)
{
    f(v.id, v.kind, v.instanceId, v.name, v.typeName, v.typeId, v.nameSpace, v.active, v.external,
      v.typed, v.ports, v.evidence, v.subsystem);
}
template <class F> void fields(Channel &v, F f)
{
    f(v.id, v.kind, v.name, v.type);
}
template <class F> void fields(BoundaryPort &v, F f)
{
    f(v.id, v.kind, v.name, v.type, v.guessed);
}
template <class F> void fields(Connection &v, F f)
{
    f(v.kind, v.partId, v.portId, v.targetId);
}
template <class F> void fields(Composite &v, F f)
{
    f(v.instanceId, v.stem, v.file, v.package, v.parentId, v.executable, v.parts, v.channels,
      v.boundary, v.connections);
}
template <class F> void fields(Architecture &v, F f)
{
    f(v.composites, v.classifiers, v.diagnostics, v.canceled);
}
} // namespace rosarch
