// Pathological input, generated here, never crashes, hangs or silently drops anything: each
// case is a workspace with one hostile file next to a healthy node, and the run must finish
// with the healthy part recovered and a diagnostic naming what was skipped and why.
#include "cache/analysiscache.h"
#include "pipeline/recovery.h"
#include "support/recoverytest.h"
#include "support/testsupport.h"
#include "syntax/syntaxtree.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using test::writeFile;

namespace {

QStringList codes(const Recovery &r, const QString &code)
{
    return test::diagnosticsWithCode(r, code);
}

QStringList classes(const Recovery &r)
{
    return test::classNames(r);
}

QStringList instances(const Recovery &r)
{
    QStringList out;
    for (const NodeInstance &n : r.launch.nodes)
        out << n.nodeName;
    return out;
}

/// A Python package `pkg` with one healthy node class, Good, started as `good`.
void healthyPackage(const QString &root)
{
    test::healthyPythonPackage(root);
}

/// A C++ package `cpp` whose CMakeLists.txt is `cmake` and whose node is Worker.
void cppPackage(const QString &root, const QByteArray &cmake)
{
    writeFile(root + "/src/cpp/package.xml", "<package format=\"3\"><name>cpp</name></package>\n");
    writeFile(root + "/src/cpp/CMakeLists.txt", cmake);
    writeFile(root + "/src/cpp/src/worker.cpp",
              "#include \"rclcpp/rclcpp.hpp\"\nclass Worker : public rclcpp::Node {\npublic:\n"
              "  Worker() : Node(\"worker\") {\n    pub_ = create_publisher<std_msgs::msg::String>("
              "\"work\", 10);\n  }\n  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n"
              "};\n");
}

} // namespace

class TestBoundedInput : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void symlinksOutOfTheWorkspaceAreNotFollowed()
    {
        // Before: the scanner walked the whole file system through the link, then crashed.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        QVERIFY(QFile::link(QStringLiteral("/"), dir.path() + "/src/pkg/root"));
        QVERIFY(QFile::link(QStringLiteral("/etc/hostname"), dir.path() + "/src/pkg/host.py"));
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(classes(r), QStringList{QStringLiteral("Good")});
        const QStringList outside = codes(r, QStringLiteral("symlink-outside"));
        QCOMPARE(outside.size(), 2);
        QVERIFY(outside.join('\n').contains(QLatin1String("src/pkg/root: Skipped src/pkg/root: "
                                                          "it links to /, outside the workspace")));
    }

    void selfReferencingParameterDefaultsEnd()
    {
        // A common idiom: a local read back from a parameter whose default is the local itself.
        // Before: C++ value evaluation restarted its depth at every parameter call and
        // recursed until the stack overflowed (autoware.universe crashed on it).
        QTemporaryDir dir;
        cppPackage(dir.path(), "project(cpp)\nadd_executable(worker src/worker.cpp)\n");
        writeFile(dir.path() + "/src/cpp/src/labels.cpp",
                  "#include \"rclcpp/rclcpp.hpp\"\n"
                  "std::vector<std::string> readLabels(rclcpp::Node & node, const std::string & "
                  "prefix)\n{\n  std::vector<std::string> labels;\n"
                  "  labels = node.declare_parameter<std::vector<std::string>>(prefix + "
                  "\"labels\", labels);\n  std::string topic = \"out\";\n"
                  "  topic = node.declare_parameter<std::string>(topic, topic);\n"
                  "  return labels;\n}\n");
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(classes(r), QStringList{QStringLiteral("Worker")});
    }

    void setupPyNestingIsBounded()
    {
        // Before: the setup.py evaluator overflowed the stack on 50,000 nested parentheses
        // and on a 50,000-term `+` chain.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        const QByteArray deep = "x = " + QByteArray(50000, '(') + "'a'" + QByteArray(50000, ')');
        QByteArray chain = "y = 'a'";
        for (int i = 0; i < 50000; ++i)
            chain += " + 'a'";
        writeFile(dir.path() + "/src/pkg/setup.py",
                  "from setuptools import setup\n" + deep + "\n" + chain +
                      "\nsetup(name='pkg', version=y, entry_points={'console_scripts': "
                      "['good = pkg.good:main']})\n");
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(classes(r), QStringList{QStringLiteral("Good")});
        QCOMPARE(r.nodes.nodes.first().executables, QStringList{QStringLiteral("good")});
    }

    void deepNestingInSourceFilesIsBounded()
    {
        // Before: 50,000 nested parentheses overflowed the stack in the C++ syntax-tree walk,
        // and in the syntax-error walk of a Python file that also has a syntax error.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        cppPackage(dir.path(), "project(cpp)\nadd_executable(worker src/worker.cpp)\n");
        writeFile(dir.path() + "/src/cpp/src/deep.cpp", "int f() { return " +
                                                            QByteArray(50000, '(') + "1" +
                                                            QByteArray(50000, ')') + "; }\n");
        writeFile(dir.path() + "/src/pkg/pkg/deep.py", "x = " + QByteArray(50000, '(') + "1" +
                                                           QByteArray(50000, ')') +
                                                           "\ndef broken(:\n    pass\n");
        const Recovery r = recoverWorkspace(dir.path());
        QStringList found = classes(r);
        found.sort();
        QCOMPARE(found, (QStringList{QStringLiteral("Good"), QStringLiteral("Worker")}));
        bool deepPy = false;
        for (const QString &e : codes(r, QStringLiteral("syntax-error")))
            deepPy = deepPy || e.startsWith(QLatin1String("src/pkg/pkg/deep.py"));
        QVERIFY(deepPy);
    }

    void aParseOverItsTimeBudgetIsSaidAndSafe()
    {
        // Before: a parse that hit tree-sitter's timeout ended in `free(): invalid size` when
        // the parser was deleted. Now the file is reported and the run goes on. (The budget is
        // cut to a microsecond here so that a 1 MB file overruns it.)
        QTemporaryDir dir;
        healthyPackage(dir.path());
        QByteArray big = "from setuptools import setup\n";
        while (big.size() < 1024 * 1024)
            big += "x = [" + QByteArray("1, ").repeated(40) + "]\n";
        writeFile(dir.path() + "/src/pkg/pkg/big.py", big);
        const auto before = SyntaxTree::parseTimeout();
        SyntaxTree::setParseTimeout(std::chrono::microseconds(1));
        const Recovery r = recoverWorkspace(dir.path());
        SyntaxTree::setParseTimeout(before);
        const QStringList failed = codes(r, QStringLiteral("parse-failed"));
        QVERIFY2(failed.contains(QStringLiteral(
                     "src/pkg/pkg/big.py: src/pkg/pkg/big.py was not analysed: parsing it took "
                     "longer than the time budget of 1e-06 s per file.")),
                 qPrintable(failed.join(QLatin1Char('\n'))));
        QCOMPARE(r.nodes.packages.size(), 1);
    }

    void yamlAliasesHaveABudget()
    {
        // Before: nine levels of ten aliases each (10^9 nodes from 1 KB) never finished.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        QByteArray yaml = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
        for (int i = 1; i <= 8; ++i) {
            QByteArrayList refs;
            for (int k = 0; k < 10; ++k)
                refs << "*a" + QByteArray::number(i - 1);
            yaml += "a" + QByteArray::number(i) + ": &a" + QByteArray::number(i) + " [" +
                    refs.join(", ") + "]\n";
        }
        yaml += "launch:\n- node: {pkg: pkg, exec: good, name: good, namespace: *a8}\n";
        writeFile(dir.path() + "/src/pkg/launch/bomb.launch.yaml", yaml);
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(instances(r), QStringList{QStringLiteral("good")}); // the node is still read
        const QStringList limit = codes(r, QStringLiteral("launch-evaluation-limit"));
        QCOMPARE(limit.size(), 1);
        QVERIFY(limit.first().contains(QLatin1String("expands (through aliases)")));
    }

    void cmakeSubdirectoriesAreReadOnce()
    {
        // Before: four add_subdirectory(.) re-read the file 4^n times (39 s, 1.1 GB).
        QTemporaryDir dir;
        cppPackage(dir.path(), "project(cpp)\nadd_subdirectory(.)\nadd_subdirectory(.)\n"
                               "add_subdirectory(./)\nadd_subdirectory(../cpp)\n"
                               "add_executable(worker src/worker.cpp)\n");
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(classes(r), QStringList{QStringLiteral("Worker")});
        QCOMPARE(r.nodes.nodes.first().executables, QStringList{QStringLiteral("worker")});
        QCOMPARE(codes(r, QStringLiteral("cmake-depth")).size(), 4);
    }

    void wideAndDeepFilesStayLinear()
    {
        // A package.xml 20,000 elements deep, and a 200 KB header that is one long syntax
        // error (each was quadratic: seconds per file). The healthy node is still found.
        QTemporaryDir dir;
        cppPackage(dir.path(), "project(cpp)\nadd_executable(worker src/worker.cpp)\n");
        writeFile(dir.path() + "/src/cpp/package.xml",
                  "<package format=\"3\"><name>cpp</name>" +
                      QByteArray(20000 * 3, ' ').replace(QByteArray("   "), QByteArray("<x>")) +
                      QByteArray(20000 * 4, ' ').replace(QByteArray("    "), QByteArray("</x>")) +
                      "</package>\n");
        QByteArray header;
        for (int i = 0; header.size() < 200 * 1024; ++i)
            header += "class C" + QByteArray::number(i) + " { int a = ; void f( { }\n";
        writeFile(dir.path() + "/src/cpp/include/cpp/broken.hpp", header);
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(classes(r), QStringList{QStringLiteral("Worker")});
        QCOMPARE(r.nodes.packages.first().name, QStringLiteral("cpp"));
        QVERIFY(!codes(r, QStringLiteral("syntax-error")).isEmpty());
    }

    void otherEncodingsAreReadAndSaid()
    {
        // Before: one Latin-1 byte made the XML launch file silently empty, and a file name
        // that is not UTF-8 was dropped without a word.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        writeFile(dir.path() + "/src/pkg/launch/cafe.launch.xml",
                  "<launch>\n  <!-- caf\xe9 au lait -->\n  <node pkg=\"pkg\" exec=\"good\" "
                  "name=\"latin\"/>\n</launch>\n");
        const QByteArray badName =
            QFile::encodeName(dir.path()) + "/src/pkg/launch/caf\xe9.launch.py";
        FILE *f = fopen(badName.constData(), "w");
        QVERIFY(f);
        fputs("from launch import LaunchDescription\n", f);
        fclose(f);
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(instances(r), QStringList{QStringLiteral("latin")});
        QCOMPARE(codes(r, QStringLiteral("not-utf8")).size(), 1);
        const QStringList names = codes(r, QStringLiteral("unreadable-name"));
        QCOMPARE(names.size(), 1);
        QVERIFY(names.first().contains(QLatin1String("not valid UTF-8")));
    }

    void aCppFileNotInUtf8IsSaidAlsoWhenItComesFromTheCache()
    {
        // The C++ reader's warning is part of what the cache keeps of the file: a later run
        // that takes the file from the cache (another file edited, another process) says it too.
        QTemporaryDir dir;
        const QString ws = dir.filePath(QStringLiteral("ws"));
        cppPackage(ws, "add_executable(worker src/worker.cpp src/scale.cpp)\n");
        writeFile(ws + "/src/cpp/src/scale.cpp",
                  "// r\xe9glage fin\nint twice(int x) { return 2 * x; }\n");
        const auto run = [&dir](const QString &root) {
            AnalysisCache cache(dir.filePath(QStringLiteral("cache")));
            StageControl control;
            control.cache = &cache;
            return recoverWorkspace(root, {}, control);
        };
        const Recovery cold = run(ws);
        const QStringList said = codes(cold, QStringLiteral("not-utf8"));
        QCOMPARE(said.size(), 1);
        QVERIFY2(said.first().startsWith(QLatin1String("src/cpp/src/scale.cpp")),
                 qPrintable(said.first()));
        QCOMPARE(classes(cold), QStringList{QStringLiteral("Worker")});
        writeFile(
            ws + "/src/cpp/src/worker.cpp",
            "// edited\n#include \"rclcpp/rclcpp.hpp\"\nclass Worker : public rclcpp::Node {\n"
            "public:\n  Worker() : Node(\"worker\") {}\n};\n");
        const Recovery warm = run(ws);
        QCOMPARE(codes(warm, QStringLiteral("not-utf8")), said);
        QCOMPARE(classes(warm), QStringList{QStringLiteral("Worker")});
    }

    void aLaunchFileTooLongToEvaluateSaysWhereItStopped()
    {
        // Before: the step budget ran out silently for what came after, and the diagnostic
        // named no line.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        QByteArray body;
        for (int i = 0; i < 150000; ++i)
            body += "    x" + QByteArray::number(i) + " = " + QByteArray::number(i) + "\n";
        writeFile(dir.path() + "/src/pkg/launch/long.launch.py",
                  "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
                  "def generate_launch_description():\n" +
                      body +
                      "    return LaunchDescription([Node(package='pkg', executable='good', "
                      "name='late')])\n");
        const Recovery r = recoverWorkspace(dir.path());
        QVERIFY(instances(r).isEmpty());
        const QStringList limit = codes(r, QStringLiteral("launch-evaluation-limit"));
        QCOMPARE(limit.size(), 1);
        QVERIFY2(limit.first().contains(QLatin1String("evaluation stopped at line ")),
                 qPrintable(limit.first()));
    }

    void aCallThatLeavesOutAParameter()
    {
        // A helper called with fewer arguments than it declares: the missing one is unknown,
        // never read from an unset syntax node (AddressSanitizer found that one).
        QTemporaryDir dir;
        healthyPackage(dir.path());
        writeFile(dir.path() + "/src/pkg/launch/helper.launch.py",
                  "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"
                  "def make(name, namespace, extra=None):\n"
                  "    return Node(package='pkg', executable='good', name=name)\n\n"
                  "def generate_launch_description():\n"
                  "    return LaunchDescription([make('helped')])\n");
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(instances(r), QStringList{QStringLiteral("helped")});
    }

    void aMissingIncludeIsSaid()
    {
        QTemporaryDir dir;
        healthyPackage(dir.path());
        writeFile(dir.path() + "/src/pkg/launch/main.launch.xml",
                  "<launch>\n  <include file=\"$(find-pkg-share pkg)/launch/gone.launch.xml\"/>\n"
                  "  <node pkg=\"pkg\" exec=\"good\" name=\"good\"/>\n</launch>\n");
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(instances(r), QStringList{QStringLiteral("good")});
        const QStringList missing = codes(r, QStringLiteral("no-such-launch-file"));
        QCOMPARE(missing.size(), 1);
        QVERIFY2(missing.first().startsWith(
                     QLatin1String("src/pkg/launch/main.launch.xml: The included launch file "
                                   "$(find-pkg-share pkg)/launch/gone.launch.xml was not found")),
                 qPrintable(missing.first()));
    }

    void anIncludeSiteReachedFromTwoSystemsIsOneFinding()
    {
        // Before: one finding per instance of the including file, identical rows in the Log.
        QTemporaryDir dir;
        healthyPackage(dir.path());
        writeFile(dir.path() + "/src/pkg/launch/shared.launch.xml",
                  "<launch>\n  <include file=\"$(find-pkg-share pkg)/launch/gone.launch.xml\"/>\n"
                  "  <include file=\"$(find-pkg-share nav2_bringup)/launch/rviz.launch.py\"/>\n"
                  "</launch>\n");
        for (const char *root : {"first", "second"})
            writeFile(dir.path() + "/src/pkg/launch/" + root + ".launch.xml",
                      "<launch>\n  <include file=\"$(find-pkg-share pkg)/launch/"
                      "shared.launch.xml\"/>\n</launch>\n");
        const Recovery r = recoverWorkspace(dir.path());
        for (const char *code : {"no-such-launch-file", "external-include"}) {
            QList<Diagnostic> found;
            for (const Diagnostic &d : r.launch.diagnostics)
                if (d.code == QLatin1String(code))
                    found.append(d);
            QCOMPARE(found.size(), 1);
            QCOMPARE(found.first().evidence.file,
                     QStringLiteral("src/pkg/launch/shared.launch.xml"));
            QStringList contexts = found.first().contexts;
            contexts.sort();
            // The two systems that reach it (the included file is no system of its own).
            QCOMPARE(contexts, (QStringList{QStringLiteral("src/pkg/launch/first.launch.xml"),
                                            QStringLiteral("src/pkg/launch/second.launch.xml")}));
        }
    }
};

QTEST_GUILESS_MAIN(TestBoundedInput)
#include "tst_boundedinput.moc"
