#include "recoverystream.h"

namespace rosarch {

namespace {

// One field list per type, used both ways: `f` streams every field in or out.
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
    f(v.severity, v.code, v.message, v.evidence, v.related, v.contexts, v.aliases);
}
template <class F> void fields(Port &v, F f)
{
    f(v.id, v.kind, v.name, v.type, v.callback, v.nameOrigin, v.nameExpression, v.parameter,
      v.parameterPrefix, v.parameterSuffix, v.guard, v.guardParameter, v.guardDefault, v.via, v.qos,
      v.inherited, v.evidence, v.viaEvidence);
}
template <class F> void fields(AtomicNode &v, F f)
{
    f(v.id, v.className, v.qualifiedName, v.nodeName, v.packageName, v.headerFiles, v.sourceFiles,
      v.description, v.compileType, v.baseClasses, v.lifecycle, v.procedural, v.executables,
      v.plugins, v.pluginInterface, v.evidence, v.ports);
}
template <class F> void fields(Executable &v, F f)
{
    f(v.kind, v.name, v.target, v.plugin, v.sources, v.evidence);
}
template <class F> void fields(RosPackage &v, F f)
{
    f(v.name, v.buildType, v.path, v.evidence, v.executables);
}
template <class F> void fields(AtomicNodeList &v, F f)
{
    f(v.workspaceRoot, v.packages, v.nodes, v.diagnostics, v.canceled);
}
template <class F> void fields(Unresolved &v, F f)
{
    f(v.kind, v.expression, v.guess, v.evidence);
}
template <class F> void fields(ParameterSetting &v, F f)
{
    f(v.name, v.value, v.source, v.file, v.evidence);
}
template <class F> void fields(NodeInstance &v, F f)
{
    f(v.id, v.launchFileId, v.nodeKind, v.package, v.execName, v.className, v.classId, v.nodeName,
      v.nameSpace, v.container, v.lifecycle, v.remaps, v.parameters, v.effectiveParameters,
      v.plugins, v.condition, v.active, v.unresolved, v.evidence);
}
template <class F> void fields(LaunchFileInstance &v, F f)
{
    f(v.id, v.type, v.file, v.package, v.format, v.parentId, v.external, v.nodes,
      v.includedLaunchFiles, v.namespaces, v.arguments, v.condition, v.active, v.unresolved,
      v.evidence);
}
template <class F> void fields(LaunchArgument &v, F f)
{
    f(v.name, v.defaultValue, v.hasDefault, v.description, v.launchFile, v.evidence);
}
template <class F> void fields(LaunchDependencies &v, F f)
{
    f(v.launchFiles, v.instances, v.nodes, v.arguments, v.classifierInstances, v.classifierNodes,
      v.diagnostics, v.canceled);
}
template <class F> void fields(PartPort &v, F f)
{
    f(v.id, v.kind, v.nameAsWritten, v.name, v.type, v.resolved, v.parameterDerived, v.remapped,
      v.active, v.guard, v.qos, v.evidence);
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
    f(v.id, v.kind, v.name, v.type);
}
template <class F> void fields(Connection &v, F f)
{
    f(v.kind, v.partId, v.portId, v.targetId);
}
template <class F> void fields(Composite &v, F f)
{
    f(v.instanceId, v.stem, v.file, v.package, v.parentId, v.parts, v.channels, v.boundary,
      v.connections);
}
template <class F> void fields(Architecture &v, F f)
{
    f(v.composites, v.classifiers, v.diagnostics, v.canceled);
}
template <class F> void fields(Recovery &v, F f)
{
    f(v.nodes, v.launch, v.architecture);
}
template <class F> void fields(LaunchOptions &v, F f)
{
    f(v.rootFile, v.arguments);
}
template <class F> void fields(StageRequest &v, F f)
{
    f(v.job, v.root, v.options, v.nodes, v.skipped, v.memoryBudgetMb, v.serial);
}

} // namespace

// Declared first so that the containers' stream operators find the nested types by ADL.
#define ROSARCH_DECLARE_STREAM(T)                                                                  \
    QDataStream &operator<<(QDataStream &s, const T &v);                                           \
    QDataStream &operator>>(QDataStream &s, T &v);
ROSARCH_DECLARE_STREAM(Evidence)
ROSARCH_DECLARE_STREAM(Diagnostic::Related)
ROSARCH_DECLARE_STREAM(Diagnostic)
ROSARCH_DECLARE_STREAM(Port)
ROSARCH_DECLARE_STREAM(AtomicNode)
ROSARCH_DECLARE_STREAM(Executable)
ROSARCH_DECLARE_STREAM(RosPackage)
ROSARCH_DECLARE_STREAM(Unresolved)
ROSARCH_DECLARE_STREAM(ParameterSetting)
ROSARCH_DECLARE_STREAM(NodeInstance)
ROSARCH_DECLARE_STREAM(LaunchFileInstance)
ROSARCH_DECLARE_STREAM(LaunchArgument)
ROSARCH_DECLARE_STREAM(LaunchDependencies)
ROSARCH_DECLARE_STREAM(PartPort)
ROSARCH_DECLARE_STREAM(RosNodePart)
ROSARCH_DECLARE_STREAM(Channel)
ROSARCH_DECLARE_STREAM(BoundaryPort)
ROSARCH_DECLARE_STREAM(Connection)
ROSARCH_DECLARE_STREAM(Composite)
ROSARCH_DECLARE_STREAM(Architecture)
#undef ROSARCH_DECLARE_STREAM

#define ROSARCH_DEFINE_STREAM(T)                                                                   \
    QDataStream &operator<<(QDataStream &s, const T &v)                                            \
    {                                                                                              \
        fields(const_cast<T &>(v), [&s](const auto &...x) { (s << ... << x); });                   \
        return s;                                                                                  \
    }                                                                                              \
    QDataStream &operator>>(QDataStream &s, T &v)                                                  \
    {                                                                                              \
        fields(v, [&s](auto &...x) { (s >> ... >> x); });                                          \
        return s;                                                                                  \
    }
ROSARCH_DEFINE_STREAM(Evidence)
ROSARCH_DEFINE_STREAM(Diagnostic::Related)
ROSARCH_DEFINE_STREAM(Diagnostic)
ROSARCH_DEFINE_STREAM(Port)
ROSARCH_DEFINE_STREAM(AtomicNode)
ROSARCH_DEFINE_STREAM(Executable)
ROSARCH_DEFINE_STREAM(RosPackage)
ROSARCH_DEFINE_STREAM(Unresolved)
ROSARCH_DEFINE_STREAM(ParameterSetting)
ROSARCH_DEFINE_STREAM(NodeInstance)
ROSARCH_DEFINE_STREAM(LaunchFileInstance)
ROSARCH_DEFINE_STREAM(LaunchArgument)
ROSARCH_DEFINE_STREAM(LaunchDependencies)
ROSARCH_DEFINE_STREAM(PartPort)
ROSARCH_DEFINE_STREAM(RosNodePart)
ROSARCH_DEFINE_STREAM(Channel)
ROSARCH_DEFINE_STREAM(BoundaryPort)
ROSARCH_DEFINE_STREAM(Connection)
ROSARCH_DEFINE_STREAM(Composite)
ROSARCH_DEFINE_STREAM(Architecture)
ROSARCH_DEFINE_STREAM(AtomicNodeList)
ROSARCH_DEFINE_STREAM(Recovery)
ROSARCH_DEFINE_STREAM(LaunchOptions)
ROSARCH_DEFINE_STREAM(StageRequest)
#undef ROSARCH_DEFINE_STREAM

namespace {

// Delta encoding of the worker's reply: mode 0 = the list equals base's; 1 = a count, then
// per element a flag "equal to base's at this index" or the element.
template <class T> void writeList(QDataStream &s, const QList<T> &v, const QList<T> &base)
{
    QList<bool> same(v.size());
    bool all = v.size() == base.size();
    for (qsizetype i = 0; i < v.size(); ++i) {
        same[i] = i < base.size() && v.at(i) == base.at(i);
        all = all && same[i];
    }
    if (all) {
        s << quint8(0);
        return;
    }
    s << quint8(1) << quint32(v.size());
    for (qsizetype i = 0; i < v.size(); ++i) {
        s << same.at(i);
        if (!same.at(i))
            s << v.at(i);
    }
}

template <class T> void readList(QDataStream &s, QList<T> &v, const QList<T> &base)
{
    quint8 mode = 0;
    s >> mode;
    if (s.status() != QDataStream::Ok)
        return;
    if (mode == 0) {
        v = base;
        return;
    }
    quint32 n = 0;
    s >> n;
    if (mode != 1 || n > (1u << 24)) {
        s.setStatus(QDataStream::ReadCorruptData);
        return;
    }
    v.clear();
    v.reserve(n);
    for (quint32 i = 0; i < n && s.status() == QDataStream::Ok; ++i) {
        bool same = false;
        s >> same;
        if (same && qsizetype(i) >= base.size()) {
            s.setStatus(QDataStream::ReadCorruptData);
            return;
        }
        if (same) {
            v.append(base.at(i));
        } else {
            T element;
            s >> element;
            v.append(std::move(element));
        }
    }
}

/// The lists of a Recovery with their counterparts in the base, and its scalars, both ways.
template <class R, class B, class L, class F> void deltaFields(R &v, B &base, L list, F scalar)
{
    scalar(v.nodes.workspaceRoot, v.nodes.canceled, v.launch.canceled, v.architecture.canceled);
    list(v.nodes.packages, base.nodes.packages);
    list(v.nodes.nodes, base.nodes.nodes);
    list(v.nodes.diagnostics, base.nodes.diagnostics);
    list(v.launch.launchFiles, base.launch.launchFiles);
    list(v.launch.instances, base.launch.instances);
    list(v.launch.nodes, base.launch.nodes);
    list(v.launch.arguments, base.launch.arguments);
    list(v.launch.classifierInstances, base.launch.classifierInstances);
    list(v.launch.classifierNodes, base.launch.classifierNodes);
    list(v.launch.diagnostics, base.launch.diagnostics);
    list(v.architecture.composites, base.architecture.composites);
    list(v.architecture.classifiers, base.architecture.classifiers);
    list(v.architecture.diagnostics, base.architecture.diagnostics);
}

} // namespace

namespace stagestream {

void writeResult(QDataStream &s, const Recovery &v, const Recovery &base)
{
    deltaFields(
        v, base, [&s](const auto &list, const auto &from) { writeList(s, list, from); },
        [&s](const auto &...x) { (s << ... << x); });
}

bool readResult(QDataStream &s, Recovery *v, const Recovery &base)
{
    *v = {};
    deltaFields(
        *v, base, [&s](auto &list, const auto &from) { readList(s, list, from); },
        [&s](auto &...x) { (s >> ... >> x); });
    return s.status() == QDataStream::Ok;
}

} // namespace stagestream

} // namespace rosarch
