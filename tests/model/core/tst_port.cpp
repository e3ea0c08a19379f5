#include "port.h"

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
};

QTEST_GUILESS_MAIN(TestPort)
#include "tst_port.moc"
