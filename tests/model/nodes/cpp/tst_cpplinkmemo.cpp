// Stage 1 in a long-lived process links the C++ facts again only when an edit changed more than
// where things are: after an edit that only moves lines the previous link is reused with its
// locations moved, and after any other change (a class's base, a helper's port, a file added,
// removed or renamed) the facts are linked again. Either way the result is a fresh run's.
#include "cache/analysiscache.h"
#include "nodes/cpp/cpplinkmemo.h"
#include "nodes/nodeanalyzer.h"
#include "pipeline/recovery.h"
#include "pipeline/stagesession.h"
#include "support/testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

const QString kTalker = QStringLiteral("linkpkg/src/talker.cpp");
const QString kStatus = QStringLiteral("linkpkg/src/status.cpp");

const QByteArray kBase = R"(#pragma once
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace linkpkg
{
class Base : public rclcpp::Node
{
public:
  explicit Base(const std::string & name)
  : rclcpp::Node(name)
  {
    heartbeat_ = create_publisher<std_msgs::msg::String>("heartbeat", 1);
  }

protected:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr heartbeat_;
};

class Quiet
{
};
}  // namespace linkpkg
)";

const QByteArray kTalkerSource = R"(#include "linkpkg/base.hpp"

namespace linkpkg
{
void add_status(rclcpp::Node * node);

class Talker : public Base
{
public:
  Talker()
  : Base("talker")
  {
    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10);
    add_status(this);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace linkpkg

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<linkpkg::Talker>());
  return 0;
}
)";

const QByteArray kStatusSource = R"(#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace linkpkg
{
void add_status(rclcpp::Node * node)
{
  node->create_publisher<std_msgs::msg::String>("status", 1);
}
}  // namespace linkpkg
)";

const QByteArray kListenerSource = R"(#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace linkpkg
{
class Listener : public rclcpp::Node
{
public:
  Listener()
  : rclcpp::Node("listener")
  {
    sub_ = create_subscription<std_msgs::msg::String>("chatter", 10, [](std_msgs::msg::String::SharedPtr) {});
  }

private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
}  // namespace linkpkg
)";

void writeWorkspace(const QString &root)
{
    test::writeFile(root + QStringLiteral("/linkpkg/package.xml"),
                    "<?xml version=\"1.0\"?>\n<package format=\"3\"><name>linkpkg</name>"
                    "<version>0.0.1</version><description>d</description>"
                    "<maintainer email=\"a@b.c\">a</maintainer><license>MIT</license>"
                    "<export><build_type>ament_cmake</build_type></export></package>\n");
    test::writeFile(root + QStringLiteral("/linkpkg/CMakeLists.txt"),
                    "cmake_minimum_required(VERSION 3.8)\nproject(linkpkg)\n"
                    "add_executable(talker src/talker.cpp src/status.cpp)\n");
    test::writeFile(root + QStringLiteral("/linkpkg/include/linkpkg/base.hpp"), kBase);
    test::writeFile(root + QLatin1Char('/') + kTalker, kTalkerSource);
    test::writeFile(root + QLatin1Char('/') + kStatus, kStatusSource);
}

AtomicNodeList runWith(const QString &root, AnalysisCache *cache)
{
    StageControl control;
    control.cache = cache;
    return recoverAtomicNodes(root, control);
}

AtomicNodeList runFresh(const QString &root)
{
    AnalysisCache off{QString()};
    return runWith(root, &off);
}

const Port *portNamed(const AtomicNodeList &list, const QString &name)
{
    for (const AtomicNode &n : list.nodes)
        for (const Port &p : n.ports)
            if (p.name == name)
                return &p;
    return nullptr;
}

/// Puts a diagnostic that the linker never writes into the kept link, at the location of the
/// talker's publisher: it is in the next result (moved) only when that link is reused.
void markKeptLink(AnalysisCache *cache, const Evidence &at)
{
    const std::shared_ptr<const void> kept = cache->recent(CppLinkMemo::kind(), CppLinkMemo::key());
    QVERIFY(kept);
    CppLinkMemo::Memo memo = *static_cast<const CppLinkMemo::Memo *>(kept.get());
    Diagnostic d;
    d.code = QStringLiteral("test-marker");
    d.evidence = at;
    memo.analysis.diagnostics.append(d);
    cache->keepRecent(CppLinkMemo::kind(), CppLinkMemo::key(),
                      std::make_shared<const CppLinkMemo::Memo>(memo));
}

const Diagnostic *marker(const AtomicNodeList &list)
{
    for (const Diagnostic &d : list.diagnostics)
        if (d.code == QLatin1String("test-marker"))
            return &d;
    return nullptr;
}

void replaceIn(const QString &file, const QByteArray &before, const QByteArray &after)
{
    QByteArray text = test::readFile(file);
    QVERIFY(text.contains(before));
    text.replace(before, after);
    test::writeFile(file, text);
}

} // namespace

class TestCppLinkMemo : public QObject
{
    Q_OBJECT

    QTemporaryDir m_temp;
    QString m_ws;
    QString m_cache;

private Q_SLOTS:
    void init()
    {
        QVERIFY(m_temp.isValid());
        // One workspace and one cache folder per test function and row.
        const QString name = QStringLiteral("%1-%2").arg(
            QLatin1String(QTest::currentTestFunction()),
            QString::fromLatin1(QTest::currentDataTag()).replace(QLatin1Char(' '), u'_'));
        m_ws = m_temp.filePath(QStringLiteral("ws-") + name);
        m_cache = m_temp.filePath(QStringLiteral("cache-") + name);
        writeWorkspace(m_ws);
    }

    void fixtureLinksAcrossFiles()
    {
        const AtomicNodeList list = runFresh(m_ws);
        // The talker's ports come from three files: its own, its base's and its helper's.
        QVERIFY(portNamed(list, QStringLiteral("chatter")));
        QCOMPARE(portNamed(list, QStringLiteral("heartbeat"))->evidence.file,
                 QStringLiteral("linkpkg/include/linkpkg/base.hpp"));
        QCOMPARE(portNamed(list, QStringLiteral("status"))->evidence.file, kStatus);
    }

    void movedLinesReuseTheLink()
    {
        AnalysisCache cache(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const AtomicNodeList before = runWith(m_ws, &cache);
        const Port *chatter = portNamed(before, QStringLiteral("chatter"));
        QVERIFY(chatter);
        markKeptLink(&cache, chatter->evidence);
        const QString talker = m_ws + QLatin1Char('/') + kTalker;
        test::writeFile(talker, "// one\n// two\n\n" + test::readFile(talker));

        AtomicNodeList after = runWith(m_ws, &cache);
        const Diagnostic *kept = marker(after);
        QVERIFY2(kept, "the facts were linked again instead of the link reused");
        QCOMPARE(kept->evidence.line, chatter->evidence.line + 3);
        after.diagnostics.removeOne(*kept);
        const AtomicNodeList fresh = runFresh(m_ws);
        QCOMPARE(portNamed(fresh, QStringLiteral("chatter"))->evidence.line,
                 chatter->evidence.line + 3);
        QVERIFY(after == fresh);

        // Moved again, in another file: the link kept is the moved one, reused once more.
        const QString status = m_ws + QLatin1Char('/') + kStatus;
        test::writeFile(status, "\n" + test::readFile(status));
        AtomicNodeList again = runWith(m_ws, &cache);
        QVERIFY(marker(again));
        QCOMPARE(marker(again)->evidence.line, chatter->evidence.line + 3);
        again.diagnostics.removeOne(*marker(again));
        QVERIFY(again == runFresh(m_ws));
    }

    void otherChangesLinkAgain_data()
    {
        QTest::addColumn<QString>("change");
        QTest::newRow("a class's base") << QStringLiteral("base");
        QTest::newRow("a helper's port") << QStringLiteral("helper");
        QTest::newRow("a base's port, with lines moved") << QStringLiteral("base-port");
        QTest::newRow("a file added") << QStringLiteral("added");
        QTest::newRow("a file removed") << QStringLiteral("removed");
        QTest::newRow("a file renamed") << QStringLiteral("renamed");
        QTest::newRow("a package ignored") << QStringLiteral("ignored");
    }

    void otherChangesLinkAgain()
    {
        QFETCH(QString, change);
        AnalysisCache cache(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const AtomicNodeList before = runWith(m_ws, &cache);
        QVERIFY(before == runFresh(m_ws));
        markKeptLink(&cache, portNamed(before, QStringLiteral("chatter"))->evidence);

        const QString talker = m_ws + QLatin1Char('/') + kTalker;
        const QString status = m_ws + QLatin1Char('/') + kStatus;
        const QString base = m_ws + QStringLiteral("/linkpkg/include/linkpkg/base.hpp");
        if (change == QLatin1String("base")) {
            replaceIn(talker, "class Talker : public Base", "class Talker : public Quiet");
        } else if (change == QLatin1String("helper")) {
            replaceIn(status, "\"status\"", "\"health_report\"");
        } else if (change == QLatin1String("base-port")) {
            replaceIn(base, "\"heartbeat\", 1);", "\n\"pulse\", 1);");
        } else if (change == QLatin1String("added")) {
            test::writeFile(m_ws + QStringLiteral("/linkpkg/src/listener.cpp"), kListenerSource);
        } else if (change == QLatin1String("removed")) {
            QVERIFY(QFile::remove(status));
        } else if (change == QLatin1String("renamed")) {
            QVERIFY(QFile::rename(status, m_ws + QStringLiteral("/linkpkg/src/state.cpp")));
        } else if (change == QLatin1String("ignored")) {
            test::writeFile(m_ws + QStringLiteral("/linkpkg/COLCON_IGNORE"), QByteArray());
        }
        const AtomicNodeList after = runWith(m_ws, &cache);
        QVERIFY2(!marker(after), "the link was reused after a change the linker uses");
        const AtomicNodeList fresh = runFresh(m_ws);
        QVERIFY(after == fresh);
        QVERIFY(!(after == before));
    }

    // The GUI's path: one long-lived worker with the analysis cache on, across edits of every
    // kind; each result is what a fresh run without the cache gives.
    void aLongLivedWorkerFollowsEveryChange()
    {
        const QByteArray noCache = qgetenv("ROSARCH_NO_CACHE");
        const QByteArray cacheDir = qgetenv("ROSARCH_CACHE_DIR");
        qunsetenv("ROSARCH_NO_CACHE");
        qputenv("ROSARCH_CACHE_DIR", QFile::encodeName(m_cache));
        const auto restore = qScopeGuard([&] {
            if (!noCache.isNull())
                qputenv("ROSARCH_NO_CACHE", noCache);
            if (cacheDir.isNull())
                qunsetenv("ROSARCH_CACHE_DIR");
            else
                qputenv("ROSARCH_CACHE_DIR", cacheDir);
        });
        StageSession session;
        const auto same = [&](const char *step) {
            const StageProcess::Result r = session.recover(m_ws, {}, {});
            QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
            AnalysisCache off{QString()};
            StageControl fresh;
            fresh.cache = &off;
            QVERIFY2(r.recovery == recoverWorkspace(m_ws, {}, fresh), step);
        };
        same("first");
        const QString talker = m_ws + QLatin1Char('/') + kTalker;
        const QString status = m_ws + QLatin1Char('/') + kStatus;
        test::writeFile(talker, "// moved\n" + test::readFile(talker));
        same("lines moved");
        replaceIn(status, "\"status\"", "\"health_report\"");
        same("a helper's port");
        replaceIn(talker, "class Talker : public Base", "class Talker : public Quiet");
        same("a class's base");
        test::writeFile(m_ws + QStringLiteral("/linkpkg/src/listener.cpp"), kListenerSource);
        same("a file added");
        QVERIFY(QFile::rename(status, m_ws + QStringLiteral("/linkpkg/src/state.cpp")));
        same("a file renamed");
        test::copyTree(m_ws + QStringLiteral("/linkpkg"), m_ws + QStringLiteral("/otherpkg"));
        replaceIn(m_ws + QStringLiteral("/otherpkg/package.xml"), "<name>linkpkg</name>",
                  "<name>otherpkg</name>");
        same("a package added");
        test::writeFile(m_ws + QStringLiteral("/otherpkg/COLCON_IGNORE"), QByteArray());
        same("a package ignored");
        QVERIFY(QFile::remove(m_ws + QStringLiteral("/linkpkg/src/listener.cpp")));
        same("a file removed");
        QVERIFY2(QDir(m_cache).exists(), "the worker ran without the analysis cache");
    }
};

QTEST_GUILESS_MAIN(TestCppLinkMemo)
#include "tst_cpplinkmemo.moc"
