// ParseHandoff: a Python launch file read by stage 1 (for node classes) and by stage 2 (as a
// launch description) in one run is parsed once, whichever reads it first, and what the two
// readers find is what they find when each parses it alone.
#include "core/launchaction.h"
#include "launch/python/pythonlaunchreader.h"
#include "nodes/python/pythonfactscodec.h"
#include "nodes/python/pythonnodeanalyzer.h"
#include "syntax/parsehandoff.h"

#include <QtTest>

#include <thread>
#include <vector>

using namespace rosarch;

namespace {

const QByteArray kLaunch = "from launch import LaunchDescription\n"
                           "from launch_ros.actions import Node\n"
                           "def generate_launch_description():\n"
                           "    return LaunchDescription([\n"
                           "        Node(package='demo', executable='talker', name='talker'),\n"
                           "    ])\n";

SyntaxTree parsed(const QByteArray &content, const QString &file)
{
    return SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file);
}

} // namespace

class TestParseHandoff : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void onlyWithinARunAndOnlyTheSameText()
    {
        const QString file = QStringLiteral("demo/launch/talker.launch.py");
        ParseHandoff::offer(parsed(kLaunch, file)); // no run: dropped
        QCOMPARE(ParseHandoff::waitingCount(), 0);
        {
            const ParseHandoff::Run run;
            {
                const ParseHandoff::Run inner; // runs do not nest: the outer one decides
            }
            ParseHandoff::offer(parsed(kLaunch, file));
            QCOMPARE(ParseHandoff::waitingCount(), 1);
            std::optional<SyntaxTree> taken = ParseHandoff::take(file, kLaunch);
            QVERIFY(taken);
            QCOMPARE(taken->source(), kLaunch);
            QVERIFY(!ts::isNull(taken->root()));
            QVERIFY(!ParseHandoff::take(file, kLaunch)); // once only
            // A file that changed between the two reads is parsed again.
            ParseHandoff::offer(parsed(kLaunch, file));
            QVERIFY(!ParseHandoff::take(file, kLaunch + "\n# edited\n"));
            QCOMPARE(ParseHandoff::waitingCount(), 0);
            ParseHandoff::offer(parsed(kLaunch, QStringLiteral("other.launch.py")));
            QVERIFY(!ParseHandoff::take(file, kLaunch));
            QCOMPARE(ParseHandoff::waitingCount(), 1);
        }
        QCOMPARE(ParseHandoff::waitingCount(), 0); // what nobody took goes with the run
        QVERIFY(ParseHandoff::wanted(kLaunch));
        QVERIFY(!ParseHandoff::wanted("import rclpy\n"));
    }

    void bothReadersFindWhatTheyFindAlone()
    {
        const QString file = QStringLiteral("demo/launch/talker.launch.py");
        const PythonFileResult aloneNodes = PythonNodeAnalyzer::analyzeContent(
            kLaunch, file, QStringLiteral("demo"), QStringLiteral("demo.launch.talker"));
        const std::optional<LaunchFileDescription> aloneLaunch =
            PythonLaunchReader::readIfLaunchFile(kLaunch, file);
        QVERIFY(aloneLaunch);
        QCOMPARE(aloneLaunch->actions.size(), 1);
        for (bool launchFirst : {false, true}) {
            const ParseHandoff::Run run;
            std::optional<LaunchFileDescription> launch;
            PythonFileResult nodes;
            if (launchFirst)
                launch = PythonLaunchReader::readIfLaunchFile(kLaunch, file);
            else
                nodes = PythonNodeAnalyzer::analyzeContent(kLaunch, file, QStringLiteral("demo"),
                                                           QStringLiteral("demo.launch.talker"));
            QCOMPARE(ParseHandoff::waitingCount(), 1); // the first reader handed its tree over
            if (launchFirst)
                nodes = PythonNodeAnalyzer::analyzeContent(kLaunch, file, QStringLiteral("demo"),
                                                           QStringLiteral("demo.launch.talker"));
            else
                launch = PythonLaunchReader::readIfLaunchFile(kLaunch, file);
            QCOMPARE(ParseHandoff::waitingCount(), 0); // and the second took it
            QVERIFY(launch);
            QCOMPARE(launch->actions.size(), aloneLaunch->actions.size());
            for (qsizetype i = 0; i < launch->actions.size(); ++i)
                QVERIFY(launch->actions.at(i) == aloneLaunch->actions.at(i));
            QCOMPARE(launch->diagnostics.size(), aloneLaunch->diagnostics.size());
            QCOMPARE(PythonFactsCodec::encode(nodes), PythonFactsCodec::encode(aloneNodes));
        }
    }

    // Two readers on two threads, as in a run: each file's tree goes to one of them at most
    // once, and every reader gets a tree of its text.
    void readersOnTwoThreads()
    {
        const ParseHandoff::Run run;
        constexpr int kFiles = 200;
        std::vector<int> parses(2, 0);
        auto reader = [&](int who) {
            for (int i = 0; i < kFiles; ++i) {
                const QString file = QStringLiteral("f%1.launch.py").arg(i);
                std::optional<SyntaxTree> tree = ParseHandoff::take(file, kLaunch);
                if (!tree) {
                    ++parses[size_t(who)];
                    ParseHandoff::offer(parsed(kLaunch, file));
                }
            }
        };
        std::thread a(reader, 0);
        std::thread b(reader, 1);
        a.join();
        b.join();
        // Every file parsed at least once and at most twice (both read it at the same time).
        QVERIFY(parses[0] + parses[1] >= kFiles);
        QVERIFY(parses[0] + parses[1] <= 2 * kFiles);
        QVERIFY(ParseHandoff::waitingCount() <= kFiles);
    }
};

QTEST_GUILESS_MAIN(TestParseHandoff)
#include "tst_parsehandoff.moc"
