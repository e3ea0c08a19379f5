#include "support/testsupport.h"
#include "workspace/buildfileparser.h"
#include "workspace/cmakelistsreader.h"
#include "workspace/workspacescanner.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using test::writeFile;

namespace {
QList<Executable> readCMake(const QHash<QString, QByteArray> &files, QList<Diagnostic> *diagnostics)
{
    CMakeListsReader reader([&](const QString &path, QByteArray *content) {
        if (!files.contains(path))
            return false;
        *content = files.value(path);
        return true;
    });
    return reader.read(QStringLiteral("pkg/CMakeLists.txt"), diagnostics);
}
/// Each scanned file as "path@package".
QStringList filesWithPackages(const Workspace &ws)
{
    QStringList out;
    for (const SourceFile &f : ws.files)
        out << f.path + QLatin1Char('@') + f.package;
    return out;
}

} // namespace

class TestBuildFiles : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cmakeTokenizer()
    {
        const auto commands =
            CMakeListsReader::tokenize("# comment (with parens)\n"
                                       "project(demo)\n"
                                       "add_executable(talker\n  src/talker.cpp # trailing "
                                       "comment\n  \"src/with space.cpp\")\n"
                                       "#[[ bracket\ncomment ]]\n"
                                       "if(FOO AND (BAR OR BAZ))\nendif()\n");
        QCOMPARE(commands.size(), 4);
        QCOMPARE(commands[0].name, QStringLiteral("project"));
        QCOMPARE(commands[0].line, 2);
        QCOMPARE(commands[1].args, (QStringList{"talker", "src/talker.cpp", "src/with space.cpp"}));
        QCOMPARE(commands[1].line, 3);
        QCOMPARE(commands[1].endLine, 5);
        QCOMPARE(commands[2].name, QStringLiteral("if"));
        QCOMPARE(commands[2].line, 8);
    }

    void cmakeExecutablesAndPlugins()
    {
        QList<Diagnostic> diagnostics;
        const auto exes = readCMake(
            {{"pkg/CMakeLists.txt",
              "project(my_pkg)\n"
              "set(exe_name ${PROJECT_NAME}_node)\n"
              "add_executable(${exe_name} src/main.cpp src/node.cpp)\n"
              "add_library(comp SHARED src/comp.cpp)\n"
              "rclcpp_components_register_node(comp PLUGIN \"my_pkg::Comp\" EXECUTABLE comp_node)\n"
              "rclcpp_components_register_nodes(comp \"my_pkg::A\" \"my_pkg::B\")\n"
              "add_subdirectory(tools)\n"},
             {"pkg/tools/CMakeLists.txt", "add_executable(tool tool.cpp)\n"}},
            &diagnostics);
        QVERIFY(diagnostics.isEmpty());
        QCOMPARE(exes.size(), 5);
        QCOMPARE(exes[0].kind, Executable::Kind::CMakeExecutable);
        QCOMPARE(exes[0].name, QStringLiteral("my_pkg_node"));
        QCOMPARE(exes[0].sources, (QStringList{"pkg/src/main.cpp", "pkg/src/node.cpp"}));
        QCOMPARE(exes[0].evidence.file, QStringLiteral("pkg/CMakeLists.txt"));
        QCOMPARE(exes[0].evidence.line, 3);
        QCOMPARE(exes[1].name, QStringLiteral("tool"));
        QCOMPARE(exes[1].sources, QStringList{"pkg/tools/tool.cpp"});
        QCOMPARE(exes[2].kind, Executable::Kind::ComponentPlugin);
        QCOMPARE(exes[2].plugin, QStringLiteral("my_pkg::Comp"));
        QCOMPARE(exes[2].name, QStringLiteral("comp_node"));
        QCOMPARE(exes[2].sources, QStringList{"pkg/src/comp.cpp"});
        QCOMPARE(exes[3].plugin, QStringLiteral("my_pkg::A"));
        QVERIFY(exes[3].name.isEmpty());
        QCOMPARE(exes[4].plugin, QStringLiteral("my_pkg::B"));
    }

    void cmakeFunctionsWithParsedArguments()
    {
        QList<Diagnostic> diagnostics;
        const auto exes =
            readCMake({{"pkg/CMakeLists.txt",
                        "function(custom_executable subfolder target)\n"
                        "  add_executable(${target} src/${subfolder}/${target}.cpp)\n"
                        "endfunction()\n"
                        "function(create_library plugin executable)\n"
                        "  cmake_parse_arguments(ARG \"\" \"\" \"FILES;DEPENDENCIES\" ${ARGN})\n"
                        "  set(library ${executable}_library)\n"
                        "  add_library(${library} SHARED ${ARG_FILES})\n"
                        "  rclcpp_components_register_node(${library} PLUGIN ${plugin} EXECUTABLE "
                        "${executable} EXECUTOR Single)\n"
                        "endfunction()\n"
                        "custom_executable(topics talker)\n"
                        "create_library(\"ns::Timer\" one_off_timer FILES src/timers/one_off.cpp "
                        "src/timers/util.cpp DEPENDENCIES rclcpp)\n"}},
                      &diagnostics);
        QCOMPARE(exes.size(), 2);
        QCOMPARE(exes[0].name, QStringLiteral("talker"));
        QCOMPARE(exes[0].sources, QStringList{"pkg/src/topics/talker.cpp"});
        QCOMPARE(exes[1].plugin, QStringLiteral("ns::Timer"));
        QCOMPARE(exes[1].name, QStringLiteral("one_off_timer"));
        QCOMPARE(exes[1].sources,
                 (QStringList{"pkg/src/timers/one_off.cpp", "pkg/src/timers/util.cpp"}));
    }

    void cmakeForeachLoops()
    {
        // A benchmark folder that builds one executable per name of a list: before, the
        // loop was not run and `add_executable(${name} ${name}.cpp)` made one named ".cpp".
        QList<Diagnostic> diagnostics;
        const auto exes = readCMake(
            {{"pkg/CMakeLists.txt",
              "set(TOOLS first_tool second_tool)\n"
              "foreach(name IN LISTS TOOLS)\n"
              "  add_executable(${name}\n    ${name}.cpp\n  )\n"
              "endforeach()\n"
              "foreach(kind IN ITEMS server client)\n"
              "  foreach(side left right)\n"
              "    add_executable(${kind}_${side} src/${kind}.cpp)\n"
              "  endforeach()\n"
              "endforeach()\n"
              "foreach(i RANGE 1 2)\n  add_executable(worker${i} worker.cpp)\nendforeach()\n"
              "foreach(i RANGE 100000)\n  set(last ${i})\nendforeach()\n"
              "add_executable(after ${name}after.cpp)\n"}},
            &diagnostics);
        QStringList names;
        for (const Executable &e : exes)
            names << e.name;
        QCOMPARE(names,
                 (QStringList{"first_tool", "second_tool", "server_left", "server_right",
                              "client_left", "client_right", "worker1", "worker2", "after"}));
        QCOMPARE(exes[0].sources, QStringList{"pkg/first_tool.cpp"});
        QCOMPARE(exes[3].sources, QStringList{"pkg/src/server.cpp"});
        // The loop variable is gone after the loop; the long range is cut, and said.
        QCOMPARE(exes.last().sources, QStringList{"pkg/after.cpp"});
        QCOMPARE(diagnostics.size(), 1);
        QVERIFY2(diagnostics.first().message.contains(QStringLiteral("only the first 256")),
                 qPrintable(diagnostics.first().message));
    }

    void cmakeLoopsAndCallsHaveABudget()
    {
        // Nested loops multiply: four levels of 200 items would run 1.6 billion bodies.
        QByteArray cmake = "set(L";
        for (int i = 0; i < 200; ++i)
            cmake += " i" + QByteArray::number(i);
        cmake += ")\n";
        for (const char *v : {"a", "b", "c", "d"})
            cmake += QByteArray("foreach(") + v + " IN LISTS L)\n";
        cmake += "add_executable(x_${a}_${b}_${c}_${d} x.cpp)\n";
        cmake += "endforeach()\nendforeach()\nendforeach()\nendforeach()\n";
        QList<Diagnostic> diagnostics;
        const auto exes = readCMake({{"pkg/CMakeLists.txt", cmake}}, &diagnostics);
        QVERIFY(!exes.isEmpty());
        QVERIFY(exes.size() < CMakeListsReader::kMaxBodyRuns);
        QCOMPARE(diagnostics.size(), 1);
        QVERIFY2(diagnostics.first().message.contains(QStringLiteral("were not followed")),
                 qPrintable(diagnostics.first().message));
    }

    void setupPyEntryPoints()
    {
        QList<Diagnostic> diagnostics;
        const auto exes =
            BuildFileParser::readSetupPy("from setuptools import setup\n"
                                         "package_name = 'demo_py'\n"
                                         "setup(name=package_name,\n"
                                         "  entry_points={'console_scripts': [\n"
                                         "    'talker = demo_py.talker:main',\n"
                                         "    f'listener = {package_name}.listener:main',\n"
                                         "    'server = ' + package_name + '.server:run',\n"
                                         "    'broken = ' + some_call(),\n"
                                         "  ]})\n",
                                         QStringLiteral("demo_py/setup.py"), &diagnostics);
        QCOMPARE(exes.size(), 3);
        QCOMPARE(exes[0].name, QStringLiteral("talker"));
        QCOMPARE(exes[0].target, QStringLiteral("demo_py.talker:main"));
        QCOMPARE(exes[0].evidence.line, 5);
        QCOMPARE(exes[1].target, QStringLiteral("demo_py.listener:main"));
        QCOMPARE(exes[2].name, QStringLiteral("server"));
        QCOMPARE(exes[2].target, QStringLiteral("demo_py.server:run"));
        QCOMPARE(diagnostics.size(), 1);
        QCOMPARE(diagnostics[0].code, QStringLiteral("unresolved-entry-point"));
        QCOMPARE(diagnostics[0].evidence.line, 8);
    }

    void setupCfgEntryPoints()
    {
        const auto exes = BuildFileParser::readSetupCfg(
            "[metadata]\nname = demo\n[options.entry_points]\nconsole_scripts =\n"
            "    talker = demo.talker:main\n    listener = demo.listener:main\n[other]\nx = y\n",
            QStringLiteral("demo/setup.cfg"));
        QCOMPARE(exes.size(), 2);
        QCOMPARE(exes[1].name, QStringLiteral("listener"));
        QCOMPARE(exes[1].target, QStringLiteral("demo.listener:main"));
        QCOMPARE(exes[1].evidence.line, 6);
    }

    void malformedPackageXml()
    {
        RosPackage pkg;
        QList<Diagnostic> diagnostics;
        BuildFileParser::readPackageXml(
            "<package><name>good_name</name><export><build_type>ament_python</build_type></export>",
            QStringLiteral("p/package.xml"), &pkg, &diagnostics);
        QCOMPARE(pkg.name, QStringLiteral("good_name"));
        QCOMPARE(pkg.buildType, QStringLiteral("ament_python"));
        QCOMPARE(diagnostics.size(), 1);
        QCOMPARE(diagnostics[0].code, QStringLiteral("malformed-xml"));
        QCOMPARE(diagnostics[0].severity, Diagnostic::Severity::Error);
    }

    void scannerFindsPackagesAndSkipsFolders()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString root = dir.path();
        writeFile(root + "/src/a/package.xml", "<package><name>pkg_a</name></package>");
        writeFile(root + "/src/a/CMakeLists.txt", "add_executable(a_exe src/a.cpp)\n");
        writeFile(root + "/src/a/src/a.cpp", "int main() {}\n");
        writeFile(root + "/src/a/nested/package.xml", "<package><name>pkg_nested</name></package>");
        writeFile(root + "/src/a/nested/n.py", "x = 1\n");
        writeFile(root + "/src/ignored/COLCON_IGNORE", "");
        writeFile(root + "/src/ignored/package.xml", "<package><name>ignored</name></package>");
        writeFile(root + "/build/pkg_a/generated.cpp", "int x;\n");
        writeFile(root + "/src/a/.hidden/h.py", "x = 1\n");
        writeFile(root + "/loose.py", "x = 1\n");
        const Workspace ws = WorkspaceScanner::scan(root);
        QCOMPARE(ws.packages.size(), 2);
        QCOMPARE(ws.packages[0].name, QStringLiteral("pkg_a"));
        QCOMPARE(ws.packages[0].buildType, QStringLiteral("ament_cmake"));
        QCOMPARE(ws.packages[0].path, QStringLiteral("src/a"));
        QCOMPARE(ws.packages[0].executables.size(), 1);
        QCOMPARE(ws.packages[0].executables[0].sources, QStringList{"src/a/src/a.cpp"});
        QCOMPARE(ws.packages[1].name, QStringLiteral("pkg_nested"));
        const QStringList paths = filesWithPackages(ws);
        QCOMPARE(paths,
                 (QStringList{"loose.py@", "src/a/CMakeLists.txt@pkg_a",
                              "src/a/nested/n.py@pkg_nested", "src/a/nested/package.xml@pkg_nested",
                              "src/a/package.xml@pkg_a", "src/a/src/a.cpp@pkg_a"}));
    }

    // A file belongs to the package of the nearest folder above it: the workspace's own
    // package.xml owns what no inner package does, and a folder named like the start of a
    // package's folder ("src/ab" next to "src/a") is not inside it.
    void scannerGivesEachFileTheNearestPackage()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QList<QPair<const char *, const char *>> files = {
            {"package.xml", "<package><name>outer</name></package>"},
            {"src/a/package.xml", "<package><name>pkg_a</name></package>"},
            {"top.py", ""},
            {"src/a/deep/er/a.py", ""},
            {"src/ab/b.py", ""},
        };
        for (const auto &[path, content] : files)
            writeFile(dir.filePath(QString::fromLatin1(path)), content);
        const Workspace ws = WorkspaceScanner::scan(dir.path());
        const QStringList paths = filesWithPackages(ws);
        QCOMPARE(paths,
                 (QStringList{"package.xml@outer", "src/a/deep/er/a.py@pkg_a",
                              "src/a/package.xml@pkg_a", "src/ab/b.py@outer", "top.py@outer"}));
    }

    void scannerReportsSymlinkLoops()
    {
        QTemporaryDir dir;
        const QString root = dir.path();
        writeFile(root + "/pkg/package.xml", "<package><name>pkg</name></package>");
        writeFile(root + "/pkg/code.py", "x = 1\n");
        QVERIFY(QFile::link(root + "/pkg", root + "/pkg/loop"));
        QVERIFY(QFile::link(root + "/does/not/exist", root + "/pkg/dangling"));
        const Workspace ws = WorkspaceScanner::scan(root);
        QCOMPARE(ws.packages.size(), 1);
        int loops = 0;
        for (const Diagnostic &d : ws.diagnostics)
            if (d.code == QLatin1String("symlink-loop") &&
                d.evidence.file == QLatin1String("pkg/loop"))
                ++loops;
        QCOMPARE(loops, 1);
        QCOMPARE(ws.files.size(), 2);
    }

    void scannerRejectsMissingFolder()
    {
        const Workspace ws = WorkspaceScanner::scan(QStringLiteral("/nonexistent/rosarch/ws"));
        QCOMPARE(ws.diagnostics.size(), 1);
        QCOMPARE(ws.diagnostics[0].code, QStringLiteral("no-workspace"));
        QCOMPARE(ws.diagnostics[0].severity, Diagnostic::Severity::Error);
    }
};

QTEST_GUILESS_MAIN(TestBuildFiles)
#include "tst_buildfiles.moc"
