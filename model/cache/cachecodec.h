#pragma once

#include "core/diagnostic.h"
#include "core/languageanalysis.h"
#include "core/launchaction.h"
#include "core/modelfields.h"
#include "core/port.h"
#include "core/substitution.h"

#include <QByteArray>
#include <QDataStream>
#include <QHash>
#include <QIODevice>
#include <QList>
#include <QMap>
#include <QString>
#include <QtEndian>

#include <optional>
#include <type_traits>
#include <vector>

// The binary form of per-file analysis results in the analysis cache. One field list per type
// (`cacheFields`), used both ways by `io`. A module adds the types it caches by defining
// `cacheFields(Tag, T &, F)` overloads in this namespace before it calls encode()/decode().
// Changing any field list of a cached type means bumping AnalysisCache::kFormatVersion.

namespace rosarch::cachecodec {

/// Brings this namespace into argument-dependent lookup of `cacheFields`.
struct Tag
{
};

/// The bytes QDataStream (version Qt_6_4, big-endian) writes for integers, bools, strings and
/// byte arrays, appended to a QByteArray directly: a cold run encodes every file's facts, and
/// QDataStream takes each field through QBuffer's QIODevice::write.
class Sink
{
public:
    explicit Sink(QByteArray *out) : m_out(out) {}

    template <class T, std::enable_if_t<std::is_integral_v<T>, int> = 0> Sink &operator<<(T v)
    {
        if constexpr (std::is_same_v<T, bool>) {
            m_out->append(char(v ? 1 : 0)); // QDataStream writes a bool as a qint8
        } else {
            char bytes[sizeof(T)];
            qToBigEndian(v, bytes);
            m_out->append(bytes, qsizetype(sizeof(T)));
        }
        return *this;
    }
    Sink &operator<<(const QString &v)
    {
        if (v.isNull())
            return *this << quint32(0xffffffffu);
        const qsizetype n = v.size();
        *this << quint32(n * 2);
        const qsizetype at = m_out->size();
        m_out->resize(at + n * 2);
        qToBigEndian<char16_t>(v.utf16(), n, m_out->data() + at);
        return *this;
    }
    Sink &operator<<(const QByteArray &v)
    {
        if (v.isNull())
            return *this << quint32(0xffffffffu);
        *this << quint32(v.size());
        m_out->append(v);
        return *this;
    }

private:
    QByteArray *m_out;
};

/// Writes `v` in full the first time `table` meets it and by its number after that (from 1;
/// 0 is the null string): the form of the cache's entries and of the worker's reply.
template <class Stream>
void writeNumbered(Stream &s, QHash<QString, quint32> &table, const QString &v)
{
    if (v.isNull()) {
        s << quint32(0);
        return;
    }
    if (const auto known = table.constFind(v); known != table.cend()) {
        s << *known;
        return;
    }
    const auto number = quint32(table.size() + 1);
    table.insert(v, number);
    s << number << v;
}

struct Writer
{
    static constexpr bool reading = false;
    Sink &s;
    /// The strings written so far and their numbers (from 1; 0 is the null string): each is
    /// written in full once, then by its number. An entry repeats its file's path in every
    /// piece of evidence, and names and types many times; without the table nav2's stage 2
    /// memo was 14 MB. Null: every string in full.
    QHash<QString, quint32> *strings = nullptr;

    bool good() const { return true; }
    void string(const QString &v)
    {
        if (strings)
            writeNumbered(s, *strings, v);
        else
            s << v;
    }
};

/// Reads what a Writer wrote (QDataStream's big-endian form, version Qt_6_4) straight from the
/// bytes: decoding is what a warm run spends its time on, and QDataStream reads each field
/// through a QIODevice.
struct Reader
{
    static constexpr bool reading = true;
    const char *p;
    const char *end;
    bool ok = true;
    /// The strings read so far, when the Writer had its table: number - 1 -> string. The
    /// copies share one buffer.
    QList<QString> *strings = nullptr;

    bool good() const { return ok; }
    /// The next `n` bytes, or null (and not good()) when there are fewer.
    const char *take(qsizetype n)
    {
        if (!ok || n < 0 || end - p < n) {
            ok = false;
            return nullptr;
        }
        const char *at = p;
        p += n;
        return at;
    }
    template <class T> void integer(T *v)
    {
        if constexpr (std::is_same_v<T, bool>) {
            const char *at = take(1);
            *v = at && *at != 0;
        } else if (const char *at = take(qsizetype(sizeof(T)))) {
            *v = qFromBigEndian<T>(at);
        } else {
            *v = T();
        }
    }
    void string(QString *v)
    {
        if (!strings) {
            fullString(v);
            return;
        }
        quint32 number = 0;
        integer(&number);
        if (!ok || number == 0) {
            *v = QString();
        } else if (number <= quint32(strings->size())) {
            *v = strings->at(number - 1);
        } else if (number == quint32(strings->size()) + 1) {
            fullString(v);
            strings->append(*v);
        } else {
            ok = false;
            *v = QString();
        }
    }
    void fullString(QString *v)
    {
        quint32 bytes = 0;
        integer(&bytes);
        if (!ok || bytes == 0xffffffffu) {
            *v = QString();
            return;
        }
        if (bytes == 0) {
            *v = QString(QLatin1StringView("")); // empty, not null, as QDataStream reads it
            return;
        }
        const char *at = (bytes & 1) ? nullptr : take(qsizetype(bytes));
        if (!at) {
            ok = false;
            *v = QString();
            return;
        }
        QString out(qsizetype(bytes / 2), Qt::Uninitialized);
        qFromBigEndian<char16_t>(at, qsizetype(bytes / 2), out.data());
        *v = std::move(out);
    }
    void byteArray(QByteArray *v)
    {
        quint32 bytes = 0;
        integer(&bytes);
        if (!ok || bytes == 0xffffffffu) {
            *v = QByteArray();
            return;
        }
        const char *at = take(qsizetype(bytes));
        *v = at ? QByteArray(at, qsizetype(bytes)) : QByteArray();
    }
};

/// Refuses sizes no honest entry has, so that a damaged entry cannot ask for gigabytes.
constexpr quint32 kMaxElements = 1u << 22;

template <class A, class T> void io(A &a, T &v);
template <class A, class T> void io(A &a, QList<T> &v);
template <class A, class T> void io(A &a, std::vector<T> &v);
template <class A, class K, class V> void io(A &a, QHash<K, V> &v);
template <class A, class K, class V> void io(A &a, QMap<K, V> &v);
template <class A, class X, class Y> void io(A &a, std::pair<X, Y> &v);
template <class A, class T> void io(A &a, std::optional<T> &v);

template <class A> bool size(A &a, quint32 *n)
{
    if constexpr (A::reading) {
        a.integer(n);
        if (!a.ok || *n > kMaxElements) {
            a.ok = false;
            return false;
        }
    } else {
        a.s << *n;
    }
    return true;
}

template <class A, class T> void io(A &a, T &v)
{
    if constexpr (std::is_same_v<T, QString> || std::is_same_v<T, QByteArray> ||
                  std::is_same_v<T, bool> || std::is_integral_v<T>) {
        if constexpr (!A::reading && std::is_same_v<T, QString>)
            a.string(v);
        else if constexpr (!A::reading)
            a.s << v;
        else if constexpr (std::is_same_v<T, QString>)
            a.string(&v);
        else if constexpr (std::is_same_v<T, QByteArray>)
            a.byteArray(&v);
        else
            a.integer(&v);
    } else if constexpr (std::is_enum_v<T>) {
        auto raw = qint32(v);
        io(a, raw);
        if constexpr (A::reading)
            v = T(raw);
    } else {
        cacheFields(Tag{}, v, [&a](auto &...x) { (io(a, x), ...); });
    }
}

template <class A, class T> void io(A &a, QList<T> &v)
{
    auto n = quint32(v.size());
    if (!size(a, &n))
        return;
    if constexpr (A::reading) {
        v.clear();
        v.reserve(n);
        for (quint32 i = 0; i < n && a.good(); ++i)
            io(a, v.emplace_back());
    } else {
        // Writing never changes what it writes, not even a list's sharing (a non-const loop
        // would detach it): another thread may be reading the same value (the worker encodes a
        // stage's result while the next stage reads it).
        for (const T &x : std::as_const(v))
            io(a, const_cast<T &>(x));
    }
}

template <class A, class T> void io(A &a, std::vector<T> &v)
{
    auto n = quint32(v.size());
    if (!size(a, &n))
        return;
    if constexpr (A::reading) {
        v.clear();
        v.reserve(n);
        for (quint32 i = 0; i < n && a.good(); ++i)
            io(a, v.emplace_back());
    } else {
        for (T &x : v)
            io(a, x);
    }
}

// A QHash or a QMap: its size, then each key and value.
template <class A, template <class, class> class Map, class K, class V>
void ioMap(A &a, Map<K, V> &v)
{
    auto n = quint32(v.size());
    if (!size(a, &n))
        return;
    if constexpr (A::reading) {
        v.clear();
        for (quint32 i = 0; i < n && a.good(); ++i) {
            K key;
            V value;
            io(a, key);
            io(a, value);
            v.insert(key, value);
        }
    } else {
        for (auto it = v.cbegin(); it != v.cend(); ++it) { // no detach (io(QList) says why)
            K key = it.key();
            io(a, key);
            io(a, const_cast<V &>(it.value()));
        }
    }
}

template <class A, class K, class V> void io(A &a, QHash<K, V> &v)
{
    ioMap(a, v);
}

template <class A, class K, class V> void io(A &a, QMap<K, V> &v)
{
    ioMap(a, v);
}

template <class A, class X, class Y> void io(A &a, std::pair<X, Y> &v)
{
    io(a, v.first);
    io(a, v.second);
}

template <class A, class T> void io(A &a, std::optional<T> &v)
{
    bool has = v.has_value();
    io(a, has);
    if (!has) {
        if constexpr (A::reading)
            v.reset();
        return;
    }
    if constexpr (A::reading)
        v.emplace();
    io(a, *v);
}

// The model value types (Evidence, Diagnostic, Port, AtomicNodeList, LaunchDependencies, ...):
// their one field list in modelfields.h. A module's own overload for a type is preferred.
template <class T, class F> auto cacheFields(Tag, T &v, F f) -> decltype(fields(v, f))
{
    return fields(v, f);
}
template <class F> void cacheFields(Tag, ComponentRegistration &v, F f)
{
    f(v.file, v.pluginClass, v.evidence);
}
template <class F> void cacheFields(Tag, Substitution &v, F f)
{
    f(v.kind, v.text, v.parts);
}

/// `value` as bytes.
template <class T> QByteArray encode(const T &value)
{
    QByteArray bytes;
    Sink s(&bytes);
    QHash<QString, quint32> strings;
    Writer w{s, &strings};
    io(w, const_cast<T &>(value));
    return bytes;
}

/// Reads `bytes` into `value`; false when they are not a whole, well-formed `T`.
template <class T> bool decode(const QByteArray &bytes, T *value)
{
    QList<QString> strings;
    Reader r{bytes.constData(), bytes.constData() + bytes.size()};
    r.strings = &strings;
    io(r, *value);
    return r.ok && r.p == r.end;
}

} // namespace rosarch::cachecodec
