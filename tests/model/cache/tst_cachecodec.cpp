// The cache codec's reader reads what its writer (QDataStream, Qt_6_4, big-endian, each string
// in full once and then by its number) wrote, with null and empty strings apart as QDataStream
// keeps them, and refuses truncated, oversized, trailing or misnumbered bytes instead of
// reading past them. Without its string table the writer writes what QDataStream writes.
#include "cache/cachecodec.h"

#include <QtTest>

using namespace rosarch;

namespace {

struct Sample
{
    QString null;
    QString empty = QLatin1String("");
    QString text = QStringLiteral("/scan — ü 🙂");
    QByteArray bytes = QByteArrayLiteral("a\0b");
    QByteArray nullBytes;
    bool flag = true;
    qint32 negative = -7;
    quint32 big = 0xfffffffeu;
    qint64 wide = -(qint64(1) << 40);
    QList<QString> list{QStringLiteral("x"), QString(), QStringLiteral("y")};
    QHash<QString, qint32> map{{QStringLiteral("k"), 3}};
    std::optional<QString> maybe = QStringLiteral("m");
    Diagnostic::Severity severity = Diagnostic::Severity::Error;
    QList<QString> repeated = QList<QString>(50, QStringLiteral("nav2_bringup/launch/x.py"));
};

} // namespace

namespace rosarch::cachecodec {
template <class F> void cacheFields(Tag, Sample &v, F f)
{
    f(v.null, v.empty, v.text, v.bytes, v.nullBytes, v.flag, v.negative, v.big, v.wide, v.list,
      v.map, v.maybe, v.severity, v.repeated);
}
} // namespace rosarch::cachecodec

class TestCacheCodec : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void whatIsWrittenIsReadBack()
    {
        const Sample in;
        const QByteArray bytes = cachecodec::encode(in);
        Sample out;
        out.flag = false;
        out.text.clear();
        out.list.clear();
        out.maybe.reset();
        QVERIFY(cachecodec::decode(bytes, &out));
        QVERIFY(out.null.isNull());
        QVERIFY(!out.empty.isNull() && out.empty.isEmpty());
        QCOMPARE(out.text, in.text);
        QCOMPARE(out.bytes, in.bytes);
        QCOMPARE(out.bytes.size(), 3);
        QVERIFY(out.nullBytes.isNull());
        QCOMPARE(out.flag, true);
        QCOMPARE(out.negative, -7);
        QCOMPARE(out.big, 0xfffffffeu);
        QCOMPARE(out.wide, in.wide);
        QCOMPARE(out.list, in.list);
        QVERIFY(out.list.at(1).isNull());
        QCOMPARE(out.map, in.map);
        QCOMPARE(out.maybe, in.maybe);
        QCOMPARE(out.severity, Diagnostic::Severity::Error);
        QCOMPARE(out.repeated, in.repeated);

        // A repeated string is written once and read into copies of one string.
        Sample once;
        once.repeated.resize(1);
        QCOMPARE(bytes.size() - cachecodec::encode(once).size(), 49 * 4); // 49 numbers
        QCOMPARE(out.repeated.first().constData(), out.repeated.last().constData());
        QCOMPARE(cachecodec::encode(in), bytes); // the same value, the same bytes (cache keys)
    }

    void withoutItsTableTheWriterWritesWhatQDataStreamWrites()
    {
        Sample in;
        QByteArray ours;
        {
            cachecodec::Sink s(&ours);
            cachecodec::Writer w{s};
            cachecodec::io(w, in.null);
            cachecodec::io(w, in.empty);
            cachecodec::io(w, in.text);
            cachecodec::io(w, in.text);
        }
        QByteArray theirs;
        {
            QDataStream s(&theirs, QIODevice::WriteOnly);
            s.setVersion(QDataStream::Qt_6_4);
            s << in.null << in.empty << in.text << in.text;
        }
        QCOMPARE(ours, theirs);
        QDataStream s(ours);
        s.setVersion(QDataStream::Qt_6_4);
        QString null, empty, text;
        s >> null >> empty >> text;
        QVERIFY(null.isNull());
        QVERIFY(!empty.isNull() && empty.isEmpty());
        QCOMPARE(text, in.text);
    }

    // The sink writes the bytes QDataStream writes, for every kind of field an entry holds.
    void theSinkWritesWhatQDataStreamWrites()
    {
        const QString text = QStringLiteral("Grüße, 世界 \U0001F916");
        QByteArray ours;
        cachecodec::Sink sink(&ours);
        sink << true << false << qint8(-3) << quint8(200) << qint16(-2) << quint16(65000)
             << qint32(-123456) << quint32(4000000000u) << qint64(-1) << quint64(1) << QString()
             << QString(QLatin1StringView("")) << text << QByteArray() << QByteArray("")
             << QByteArray("a\0b", 3);
        QByteArray theirs;
        {
            QDataStream s(&theirs, QIODevice::WriteOnly);
            s.setVersion(QDataStream::Qt_6_4);
            s << true << false << qint8(-3) << quint8(200) << qint16(-2) << quint16(65000)
              << qint32(-123456) << quint32(4000000000u) << qint64(-1) << quint64(1) << QString()
              << QString(QLatin1StringView("")) << text << QByteArray() << QByteArray("")
              << QByteArray("a\0b", 3);
        }
        QCOMPARE(ours, theirs);
    }

    // Writing changes nothing it writes, not even how a list or a map is shared: the worker
    // encodes a stage's result on one thread while others read it (a detach there crashed it).
    void encodingLeavesSharedValuesShared()
    {
        const QStringList names{QStringLiteral("a"), QStringLiteral("b")};
        std::pair<QList<QStringList>, QMap<QString, QStringList>> value;
        value.first = {names, names}; // a list of its own, whose elements share names' data
        value.second.insert(QStringLiteral("k"), names);
        const QMap<QString, QStringList> mapCopy = value.second; // the map itself shared
        const QByteArray bytes = cachecodec::encode(value);
        QVERIFY(!bytes.isEmpty());
        QCOMPARE(value.first.at(0).constData(), names.constData());
        QCOMPARE(value.first.at(1).constData(), names.constData());
        QVERIFY(value.second.isSharedWith(mapCopy));
        QCOMPARE(value.second.constBegin()->constData(), names.constData());
        std::pair<QList<QStringList>, QMap<QString, QStringList>> back;
        QVERIFY(cachecodec::decode(bytes, &back));
        QCOMPARE(back, value);
    }

    void damagedBytesAreRefused()
    {
        const QByteArray bytes = cachecodec::encode(Sample());
        Sample out;
        for (qsizetype cut = 0; cut < bytes.size(); ++cut)
            QVERIFY2(!cachecodec::decode(bytes.first(cut), &out), qPrintable(QString::number(cut)));
        QVERIFY(!cachecodec::decode(bytes + 'x', &out)); // trailing bytes
        // Bytes 0-3: the null string (number 0); 4-7: the empty string's number (1), 8-11 its
        // byte count (0).
        QByteArray odd = bytes;
        odd[11] = 1; // a byte count made odd: not UTF-16
        QVERIFY(!cachecodec::decode(odd, &out));
        QByteArray ahead = bytes;
        ahead[7] = 2; // a number no string has yet
        QVERIFY(!cachecodec::decode(ahead, &out));
        QList<QString> list;
        QVERIFY(!cachecodec::decode(QByteArray("\x7f\xff\xff\xff", 4), &list)); // too many
    }
};

QTEST_GUILESS_MAIN(TestCacheCodec)
#include "tst_cachecodec.moc"
