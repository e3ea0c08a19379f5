// The cache codec's reader reads what its writer (QDataStream, Qt_6_4, big-endian) wrote,
// exactly as QDataStream would read it back (null and empty strings stay apart), and refuses
// truncated, oversized or trailing bytes instead of reading past them.
#include "cachecodec.h"

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
};

} // namespace

namespace rosarch::cachecodec {
template <class F> void cacheFields(Tag, Sample &v, F f)
{
    f(v.null, v.empty, v.text, v.bytes, v.nullBytes, v.flag, v.negative, v.big, v.wide, v.list,
      v.map, v.maybe, v.severity);
}
} // namespace rosarch::cachecodec

class TestCacheCodec : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void whatIsWrittenIsReadAsQDataStreamReadsIt()
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

        // What QDataStream reads from the same bytes.
        QDataStream s(bytes);
        s.setVersion(QDataStream::Qt_6_4);
        QString null, empty, text;
        s >> null >> empty >> text;
        QCOMPARE(null.isNull(), out.null.isNull());
        QCOMPARE(empty.isNull(), out.empty.isNull());
        QCOMPARE(text, out.text);
    }

    void damagedBytesAreRefused()
    {
        const QByteArray bytes = cachecodec::encode(Sample());
        Sample out;
        for (qsizetype cut = 0; cut < bytes.size(); ++cut)
            QVERIFY2(!cachecodec::decode(bytes.first(cut), &out), qPrintable(QString::number(cut)));
        QVERIFY(!cachecodec::decode(bytes + 'x', &out)); // trailing bytes
        QByteArray odd = bytes;
        odd[7] = 1; // the empty string's byte count (bytes 4 to 7) made odd: not UTF-16
        QVERIFY(!cachecodec::decode(odd, &out));
        QList<QString> list;
        QVERIFY(!cachecodec::decode(QByteArray("\x7f\xff\xff\xff", 4), &list)); // too many
    }
};

QTEST_GUILESS_MAIN(TestCacheCodec)
#include "tst_cachecodec.moc"
