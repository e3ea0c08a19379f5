// Twin names: Set Name on a port whose name analysis left as an expression offers to give the
// same name to the class's other unresolved ports written the same way, does it in one undoable
// step and says how many ports it named. On the project_corrections fixture with a subscriber
// added that is written as the publisher is.
#include "support/acceptedwait.h"
#include "support/correctiongui.h"

#include <QCheckBox>
#include <QFile>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test;
using EKind = CorrectionController::Element::Kind;

namespace {
const QString kPose = QStringLiteral("self.frame_prefix() + '/pose'");
const QString kClass = QStringLiteral("OdometryNode");
} // namespace

class TestTwinNames : public CorrectionTestBase
{
    Q_OBJECT

    /// The ports of the class written `written`, by id.
    QStringList portsWritten(Gui &gui, const QString &written) const
    {
        QStringList ids;
        for (const AtomicNode &n : test::acceptedNow(gui.document).nodes.nodes)
            if (n.className == kClass)
                for (const Port &p : n.ports)
                    if (p.nameExpression == written || p.name == written)
                        ids.append(n.id + u'/' + p.id);
        return ids;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        qputenv("ROSARCH_AUTHOR", "tester");
        QVERIFY(m_dir.isValid());
        m_ws = m_dir.filePath(QStringLiteral("ws"));
        QVERIFY(copyFixture(QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/ws"), m_ws));
        // A subscriber written as the publisher is, and a client written otherwise.
        QFile file(m_ws + QStringLiteral("/src/cart_base/cart_base/odometry.py"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(file.readAll());
        file.close();
        const QString anchor = QStringLiteral("        self.status_pub =");
        QVERIFY(text.contains(anchor));
        text.replace(anchor,
                     QStringLiteral("        self.create_subscription(Odometry, ") + kPose +
                         QStringLiteral(", self.on_ticks, 10)\n"
                                        "        self.create_subscription(Odometry, "
                                        "self.frame_prefix() + '/twist', self.on_ticks, 10)\n") +
                         anchor);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(text.toUtf8());
        file.close();
        m_recovery = recover(m_ws);
        QVERIFY(!m_recovery.nodes.nodes.isEmpty());
    }
    void init() { forgetProjects(); }

    void setNameOffersTheTwinsAndNamesThemInOneStep()
    {
        auto gui = open();
        const QStringList pose = portsWritten(*gui, kPose);
        QCOMPARE(pose.size(), 2); // the publisher and the subscriber
        const QStringList twist =
            portsWritten(*gui, QStringLiteral("self.frame_prefix() + '/twist'"));
        QCOMPARE(twist.size(), 1);
        QString offer;
        gui->answer = [&](CorrectionDialog &d) {
            if (auto *box = d.findChild<QCheckBox *>())
                offer = box->text();
            d.setName(QStringLiteral("/cart/pose"));
            return true; // the offer stays checked
        };
        QSignalSpy said(gui->controller->editor(), &CorrectionEditor::statusMessage);
        const int steps = gui->document.undoStack()->count();
        QVERIFY(gui->controller->editor()->rename({EKind::Port, pose.first(), {}, {}}));
        QCOMPARE(gui->asked, QStringList{QStringLiteral("Set Name")});
        QVERIFY2(offer.contains(QLatin1String("1 other port")) && offer.contains(kPose),
                 qPrintable(offer));
        QCOMPARE(gui->document.session()->corrections().size(), 2);
        for (const Correction &c : gui->document.session()->corrections()) {
            QCOMPARE(c.kind, Correction::Kind::SetName);
            QCOMPARE(c.newValue, QStringLiteral("/cart/pose"));
        }
        QCOMPARE(gui->portRow(pose.at(0)), QStringLiteral("/cart/pose"));
        QCOMPARE(gui->portRow(pose.at(1)), QStringLiteral("/cart/pose"));
        QCOMPARE(gui->portRow(twist.first()), QStringLiteral("self.frame_prefix() + '/twist'"));
        QVERIFY(!said.isEmpty());
        QVERIFY2(said.last().first().toString().startsWith(QLatin1String("Named 2 ports")),
                 qPrintable(said.last().first().toString()));
        // one step: one undo takes both back
        QCOMPARE(gui->document.undoStack()->count(), steps + 1);
        gui->document.undoStack()->undo();
        QCOMPARE(gui->portRow(pose.at(0)), kPose);
        QCOMPARE(gui->portRow(pose.at(1)), kPose);
        QVERIFY(gui->document.session()->corrections().isEmpty());
    }

    void theOfferCanBeDeclined()
    {
        auto gui = open();
        const QStringList pose = portsWritten(*gui, kPose);
        QCOMPARE(pose.size(), 2);
        gui->answer = [](CorrectionDialog &d) {
            d.setAlsoChecked(false);
            d.setName(QStringLiteral("/cart/pose"));
            return true;
        };
        QVERIFY(gui->controller->editor()->rename({EKind::Port, pose.last(), {}, {}}));
        QCOMPARE(gui->document.session()->corrections().size(), 1);
        QCOMPARE(gui->portRow(pose.last()), QStringLiteral("/cart/pose"));
        QCOMPARE(gui->portRow(pose.first()), kPose);
    }

    void aPortWithoutTwinsIsNotOffered()
    {
        auto gui = open();
        const QStringList twist =
            portsWritten(*gui, QStringLiteral("self.frame_prefix() + '/twist'"));
        QCOMPARE(twist.size(), 1);
        bool offered = true;
        gui->answer = [&](CorrectionDialog &d) {
            offered = d.findChild<QCheckBox *>() != nullptr;
            d.setName(QStringLiteral("/cart/twist"));
            return true;
        };
        QVERIFY(gui->controller->editor()->rename({EKind::Port, twist.first(), {}, {}}));
        QVERIFY(!offered);
        QCOMPARE(gui->document.session()->corrections().size(), 1);
    }
};

QTEST_MAIN(TestTwinNames)
#include "tst_twinnames.moc"
