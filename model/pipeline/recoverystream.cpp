#include "pipeline/recoverystream.h"

#include "cache/cachecodec.h"
#include "core/modelfields.h"

namespace rosarch {

namespace cachecodec {
template <class F> void cacheFields(Tag, LaunchOptions &v, F f)
{
    f(v.rootFile, v.arguments, v.externals);
}
template <class F> void cacheFields(Tag, StageRequest &v, F f)
{
    f(v.job, v.root, v.options, v.nodes, v.skipped, v.memoryBudgetMb, v.serial, v.last);
}
} // namespace cachecodec

namespace {

/// Refuses counts no honest result has, so that a damaged one cannot ask for gigabytes.
constexpr quint32 kMaxCount = 1u << 24;

} // namespace

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
        list(v.nodes.helperParameters, base.nodes.helperParameters);
    } else if (part == stagestream::LaunchPart) {
        scalar(v.launch.canceled);
        list(v.launch.launchFiles, base.launch.launchFiles);
        list(v.launch.instances, base.launch.instances);
        list(v.launch.nodes, base.launch.nodes);
        list(v.launch.arguments, base.launch.arguments);
        list(v.launch.entryPoints, base.launch.entryPoints);
        list(v.launch.viewedTopics, base.launch.viewedTopics);
        list(v.launch.externals, base.launch.externals);
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

QByteArray encodeRequest(const StageRequest &request)
{
    return cachecodec::encode(request);
}

bool decodeRequest(const QByteArray &bytes, StageRequest *request)
{
    *request = {};
    return cachecodec::decode(bytes, request);
}

} // namespace stagestream

} // namespace rosarch
