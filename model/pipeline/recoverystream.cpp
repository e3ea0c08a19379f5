#include "recoverystream.h"

#include "modelfields.h"

namespace rosarch {

namespace {

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

} // namespace rosarch
