#include "recoverystream.h"

#include "cachecodec.h"
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
    f(v.job, v.root, v.options, v.nodes, v.skipped, v.memoryBudgetMb, v.serial, v.last);
}

} // namespace

namespace {

/// Refuses counts no honest result has, so that a damaged one cannot ask for gigabytes.
constexpr quint32 kMaxCount = 1u << 24;

/// Reads a count of items that follow; false (and the stream marked corrupt) when it is more
/// than any real reply holds.
bool countIn(QDataStream &s, quint32 *n)
{
    *n = 0;
    s >> *n;
    if (*n <= kMaxCount)
        return true;
    s.setStatus(QDataStream::ReadCorruptData);
    return false;
}

template <class T> void put(QDataStream &s, const T &v);
template <class T> void get(QDataStream &s, T &v);

template <class X, class Y> void put(QDataStream &s, const QPair<X, Y> &v)
{
    put(s, v.first);
    put(s, v.second);
}
template <class X, class Y> void get(QDataStream &s, QPair<X, Y> &v)
{
    get(s, v.first);
    get(s, v.second);
}

template <class T> void put(QDataStream &s, const QList<T> &v)
{
    s << quint32(v.size());
    for (const T &x : v)
        put(s, x);
}
template <class T> void get(QDataStream &s, QList<T> &v)
{
    quint32 n = 0;
    v.clear();
    if (!countIn(s, &n))
        return;
    v.reserve(n);
    for (quint32 i = 0; i < n && s.status() == QDataStream::Ok; ++i)
        get(s, v.emplace_back());
}

template <class K, class V> void put(QDataStream &s, const QMap<K, V> &v)
{
    s << quint32(v.size());
    for (auto it = v.cbegin(); it != v.cend(); ++it) {
        put(s, it.key());
        put(s, it.value());
    }
}
template <class K, class V> void get(QDataStream &s, QMap<K, V> &v)
{
    quint32 n = 0;
    v.clear();
    if (!countIn(s, &n))
        return;
    for (quint32 i = 0; i < n && s.status() == QDataStream::Ok; ++i) {
        K key;
        V value;
        get(s, key);
        get(s, value);
        v.insert(key, value);
    }
}

/// Scalars, enums and the model types (their operators below).
template <class T> void put(QDataStream &s, const T &v)
{
    s << v;
}
template <class T> void get(QDataStream &s, T &v)
{
    s >> v;
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
        fields(const_cast<T &>(v), [&s](const auto &...x) { (put(s, x), ...); });                  \
        return s;                                                                                  \
    }                                                                                              \
    QDataStream &operator>>(QDataStream &s, T &v)                                                  \
    {                                                                                              \
        fields(v, [&s](auto &...x) { (get(s, x), ...); });                                         \
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
// per element a flag "equal to base's at this index" or the element. Written and read straight
// from bytes (cachecodec's Sink and Reader), not through QDataStream's QIODevice field by field:
// the window decodes the last part of a reply while a person waits for it.
template <class T> void writeList(cachecodec::Writer &w, const QList<T> &v, const QList<T> &base)
{
    QList<bool> same(v.size());
    bool all = v.size() == base.size();
    for (qsizetype i = 0; i < v.size(); ++i) {
        same[i] = i < base.size() && v.at(i) == base.at(i);
        all = all && same[i];
    }
    if (all) {
        w.s << quint8(0);
        return;
    }
    w.s << quint8(1) << quint32(v.size());
    for (qsizetype i = 0; i < v.size(); ++i) {
        w.s << same.at(i);
        if (!same.at(i))
            cachecodec::io(w, const_cast<T &>(v.at(i)));
    }
}

template <class T> void readList(cachecodec::Reader &r, QList<T> &v, const QList<T> &base)
{
    quint8 mode = 0;
    r.integer(&mode);
    if (!r.ok)
        return;
    if (mode == 0) {
        v = base;
        return;
    }
    quint32 n = 0;
    r.integer(&n);
    if (mode != 1 || n > kMaxCount) {
        r.ok = false;
        return;
    }
    v.clear();
    v.reserve(n);
    for (quint32 i = 0; i < n && r.ok; ++i) {
        bool same = false;
        r.integer(&same);
        if (same && qsizetype(i) >= base.size()) {
            r.ok = false;
            return;
        }
        if (same)
            v.append(base.at(i));
        else
            cachecodec::io(r, v.emplace_back());
    }
}

/// The lists of one part of a Recovery (stagestream::Part) with their counterparts in the
/// base, and its scalars, both ways.
template <class R, class B, class L, class F>
void deltaFields(quint8 part, R &v, B &base, L list, F scalar)
{
    if (part == stagestream::NodesPart) {
        scalar(v.nodes.workspaceRoot, v.nodes.canceled);
        list(v.nodes.packages, base.nodes.packages);
        list(v.nodes.nodes, base.nodes.nodes);
        list(v.nodes.diagnostics, base.nodes.diagnostics);
    } else if (part == stagestream::LaunchPart) {
        scalar(v.launch.canceled);
        list(v.launch.launchFiles, base.launch.launchFiles);
        list(v.launch.instances, base.launch.instances);
        list(v.launch.nodes, base.launch.nodes);
        list(v.launch.arguments, base.launch.arguments);
        list(v.launch.classifierInstances, base.launch.classifierInstances);
        list(v.launch.classifierNodes, base.launch.classifierNodes);
        list(v.launch.diagnostics, base.launch.diagnostics);
    } else {
        scalar(v.architecture.canceled);
        list(v.architecture.composites, base.architecture.composites);
        list(v.architecture.classifiers, base.architecture.classifiers);
        list(v.architecture.diagnostics, base.architecture.diagnostics);
    }
}

constexpr quint8 kParts[] = {stagestream::NodesPart, stagestream::LaunchPart,
                             stagestream::ArchitecturePart};

} // namespace

namespace stagestream {

void writeParts(QDataStream &s, quint8 parts, const Recovery &v, const Recovery &base)
{
    QByteArray bytes;
    cachecodec::Sink sink(&bytes);
    sink << parts;
    for (const quint8 part : kParts) {
        if (!(parts & part))
            continue;
        // A string table per part: a part is decoded without the ones sent before it.
        QHash<QString, quint32> table;
        cachecodec::Writer w{sink, &table};
        deltaFields(
            part, v, base, [&w](const auto &list, const auto &from) { writeList(w, list, from); },
            [&w](const auto &...x) {
                (cachecodec::io(w, const_cast<std::remove_cvref_t<decltype(x)> &>(x)), ...);
            });
    }
    s.writeRawData(bytes.constData(), int(bytes.size()));
}

bool readParts(QDataStream &s, Recovery *v, const Recovery &base, quint8 *parts)
{
    if (!s.device() || s.status() != QDataStream::Ok)
        return false;
    const QByteArray bytes = s.device()->readAll(); // the parts are the rest of the stream
    cachecodec::Reader r{bytes.constData(), bytes.constData() + bytes.size()};
    quint8 read = 0;
    r.integer(&read);
    if (!r.ok || (read & ~quint8(AllParts)) != 0)
        return false;
    for (const quint8 part : kParts) {
        if (!(read & part))
            continue;
        QList<QString> table;
        r.strings = &table;
        deltaFields(
            part, *v, base, [&r](auto &list, const auto &from) { readList(r, list, from); },
            [&r](auto &...x) { (cachecodec::io(r, x), ...); });
        r.strings = nullptr;
    }
    if (!r.ok || r.p != r.end)
        return false;
    *parts |= read;
    return true;
}

void writeResult(QDataStream &s, const Recovery &v, const Recovery &base)
{
    writeParts(s, AllParts, v, base);
}

bool readResult(QDataStream &s, Recovery *v, const Recovery &base)
{
    *v = {};
    quint8 parts = 0;
    return readParts(s, v, base, &parts) && parts == AllParts;
}

} // namespace stagestream

} // namespace rosarch
