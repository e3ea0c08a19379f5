#include "core/editdistance.h"
#include "core/port.h"

#include <QtTest>

using namespace rosarch;

class TestPort : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void kindNamesRoundTrip()
    {
        for (PortKind k :
             {PortKind::Publisher, PortKind::Subscriber, PortKind::ServiceServer,
              PortKind::ServiceClient, PortKind::ActionServer, PortKind::ActionClient}) {
            PortKind back = PortKind::Publisher;
            QVERIFY(portKindFromName(portKindName(k), &back));
            QCOMPARE(back, k);
        }
        PortKind dummy;
        QVERIFY(!portKindFromName(QStringLiteral("timer"), &dummy));
        QCOMPARE(portIdPrefix(PortKind::ServiceServer), QStringLiteral("ps"));
        QCOMPARE(portIdPrefix(PortKind::ActionClient), QStringLiteral("ra"));
    }

    // The near-name hints only want distances below a limit; a bounded distance must agree
    // with the full one below it and report the limit above it.
    void boundedEditDistance()
    {
        const QStringList words{QString(),
                                QStringLiteral("scan"),
                                QStringLiteral("scna"),
                                QStringLiteral("/robot/scan"),
                                QStringLiteral("cmd_vel"),
                                QStringLiteral("cmd_vel_nav"),
                                QStringLiteral("odom")};
        for (const QString &a : words) {
            for (const QString &b : words) {
                const int full = editDistance(a, b);
                for (int limit = 0; limit < 12; ++limit)
                    QCOMPARE(editDistance(a, b, limit), std::min(full, limit));
            }
        }
        QCOMPARE(editDistance(QStringLiteral("scan"), QStringLiteral("scna")), 2);
        QCOMPARE(editDistance(QStringLiteral("/a/very/long/topic/name"), QStringLiteral("x"), 3),
                 3);
    }
};

QTEST_GUILESS_MAIN(TestPort)
#include "tst_port.moc"
