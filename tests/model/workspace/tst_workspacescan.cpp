// The workspace scan lists each folder once (the entry types from the listing, no stat per
// entry but for the files it keeps and for links): what it finds and what it says of links,
// ignore markers, skipped folders and special files.
#include "cache/analysiscache.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QTemporaryDir>
#include <QtTest>

#include <sys/stat.h>
#include <unistd.h>

using namespace rosarch;

namespace {

QStringList paths(const Workspace &ws)
{
    QStringList out;
    for (const SourceFile &f : ws.files)
        out << f.path;
    return out;
}

QStringList said(const Workspace &ws)
{
    QStringList out;
    for (const Diagnostic &d : ws.diagnostics)
        out << d.code + QLatin1Char(' ') + d.evidence.file;
    return out;
}

/// Everything a scan gives, as one comparable list.
QStringList everything(const Workspace &ws)
{
    QStringList out{ws.root};
    for (const RosPackage &p : ws.packages) {
        out << QStringLiteral("package %1 at %2").arg(p.name, p.path);
        for (const Executable &e : p.executables)
            out << QStringLiteral("  %1 %2 %3").arg(e.name, e.target, e.sources.join(u' '));
    }
    for (const SourceFile &f : ws.files)
        out << QStringLiteral("file %1 of %2 (%3 bytes, %4)")
                   .arg(f.path, f.package)
                   .arg(f.size)
                   .arg(int(f.language));
    for (const Diagnostic &d : ws.diagnostics)
        out << QStringLiteral("said %1 %2: %3").arg(d.code, d.evidence.file, d.message);
    return out;
}

void link(const QString &target, const QString &at)
{
    QVERIFY2(symlink(QFile::encodeName(target).constData(), QFile::encodeName(at).constData()) == 0,
             qPrintable(at));
}

} // namespace

class TestWorkspaceScan : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void findsWhatTheBuildWouldRead()
    {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        const QString root = temp.filePath(QStringLiteral("ws"));
        const QString outside = temp.filePath(QStringLiteral("outside"));
        test::writeFile(outside + QStringLiteral("/far.cpp"), "int far;\n");
        test::writeFile(root + QStringLiteral("/pkg/package.xml"),
                        "<package format=\"3\"><name>pkg</name></package>\n");
        test::writeFile(root + QStringLiteral("/pkg/src/a.cpp"), "int a;\n");
        test::writeFile(root + QStringLiteral("/pkg/src/b.py"), "b = 1\n");
        test::writeFile(root + QStringLiteral("/pkg/src/notes.txt"), "not a source\n");
        test::writeFile(root + QStringLiteral("/pkg/.hidden/h.cpp"), "int h;\n");
        test::writeFile(root + QStringLiteral("/pkg/build/generated.cpp"), "int g;\n");
        test::writeFile(root + QStringLiteral("/pkg/launch/x.launch.xml"), "<launch/>\n");
        link(root + QStringLiteral("/pkg/src"), root + QStringLiteral("/pkg/alias"));
        link(outside + QStringLiteral("/far.cpp"), root + QStringLiteral("/pkg/far.cpp"));
        link(outside, root + QStringLiteral("/pkg/elsewhere"));
        link(root + QStringLiteral("/pkg/none.cpp"), root + QStringLiteral("/pkg/dangling.cpp"));
        link(QStringLiteral("src/a.cpp"), root + QStringLiteral("/pkg/same.hpp"));
        QCOMPARE(mkfifo(QFile::encodeName(root + QStringLiteral("/pkg/pipe.py")).constData(), 0600),
                 0);
        // Ignore markers: a file, a link to a file, and a dangling link (no marker).
        test::writeFile(root + QStringLiteral("/marked/COLCON_IGNORE"), "");
        test::writeFile(root + QStringLiteral("/marked/m.cpp"), "int m;\n");
        test::writeFile(root + QStringLiteral("/linked/l.cpp"), "int l;\n");
        link(root + QStringLiteral("/marked/m.cpp"), root + QStringLiteral("/linked/AMENT_IGNORE"));
        test::writeFile(root + QStringLiteral("/broken/kept.cpp"), "int kept;\n");
        link(root + QStringLiteral("/none"), root + QStringLiteral("/broken/COLCON_IGNORE"));

        const Workspace ws = WorkspaceScanner::scan(root);
        QCOMPARE(paths(ws),
                 QStringList({QStringLiteral("broken/kept.cpp"), QStringLiteral("pkg/alias/a.cpp"),
                              QStringLiteral("pkg/alias/b.py"),
                              QStringLiteral("pkg/launch/x.launch.xml"),
                              QStringLiteral("pkg/package.xml"), QStringLiteral("pkg/same.hpp")}));
        // The link to src/ is walked first (by name); src/ itself is then the duplicate. The
        // dangling link and the pipe named as sources are said, never opened.
        QCOMPARE(said(ws), QStringList({QStringLiteral("special-file pkg/dangling.cpp"),
                                        QStringLiteral("symlink-outside pkg/elsewhere"),
                                        QStringLiteral("symlink-outside pkg/far.cpp"),
                                        QStringLiteral("special-file pkg/pipe.py"),
                                        QStringLiteral("symlink-loop pkg/src")}));
        for (const SourceFile &f : ws.files) {
            QCOMPARE(f.size, QFileInfo(root + QLatin1Char('/') + f.path).size());
            QCOMPARE(f.package,
                     f.path.startsWith(QLatin1String("pkg/")) ? QStringLiteral("pkg") : QString());
        }
        QCOMPARE(ws.files.at(5).language, SourceFile::Language::Cpp);
        QCOMPARE(ws.files.at(4).language, SourceFile::Language::PackageXml);
    }

    void seesAddedRemovedAndRenamedFiles()
    {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        const QString root = temp.path();
        test::writeFile(root + QStringLiteral("/p/package.xml"),
                        "<package format=\"3\"><name>p</name></package>\n");
        test::writeFile(root + QStringLiteral("/p/src/one.cpp"), "int one;\n");
        QCOMPARE(paths(WorkspaceScanner::scan(root)),
                 QStringList({QStringLiteral("p/package.xml"), QStringLiteral("p/src/one.cpp")}));
        test::writeFile(root + QStringLiteral("/p/src/two.cpp"), "int two;\n");
        QVERIFY(QFile::rename(root + QStringLiteral("/p/src/one.cpp"),
                              root + QStringLiteral("/p/src/uno.cpp")));
        test::writeFile(root + QStringLiteral("/q/package.xml"),
                        "<package format=\"3\"><name>q</name></package>\n");
        const Workspace ws = WorkspaceScanner::scan(root);
        QCOMPARE(paths(ws),
                 QStringList({QStringLiteral("p/package.xml"), QStringLiteral("p/src/two.cpp"),
                              QStringLiteral("p/src/uno.cpp"), QStringLiteral("q/package.xml")}));
        QCOMPARE(ws.packages.size(), 2);
        QVERIFY(QFile::remove(root + QStringLiteral("/p/src/two.cpp")));
        test::writeFile(root + QStringLiteral("/q/COLCON_IGNORE"), "");
        const Workspace after = WorkspaceScanner::scan(root);
        QCOMPARE(paths(after),
                 QStringList({QStringLiteral("p/package.xml"), QStringLiteral("p/src/uno.cpp")}));
        QCOMPARE(after.packages.size(), 1);
    }

    // In a long-lived process a scan keeps what it read past the walk; the next scan uses it only
    // when the walk finds the same files and no build file it looked at changed.
    void keptScanSeesChangedBuildFiles()
    {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        const QString root = temp.filePath(QStringLiteral("ws"));
        AnalysisCache cache(temp.filePath(QStringLiteral("cache")), AnalysisCache::kDefaultMaxBytes,
                            0);
        StageControl control;
        control.cache = &cache;
        test::writeFile(root + QStringLiteral("/p/package.xml"),
                        "<package format=\"3\"><name>p</name></package>\n");
        test::writeFile(root + QStringLiteral("/p/CMakeLists.txt"),
                        "project(p)\nadd_executable(one src/one.cpp)\nadd_subdirectory(extra)\n");
        test::writeFile(root + QStringLiteral("/p/extra/CMakeLists.txt"),
                        "add_executable(three ../src/one.cpp)\n");
        test::writeFile(root + QStringLiteral("/p/src/one.cpp"), "int one;\n");
        const auto kept = [&] { return everything(WorkspaceScanner::scan(root, control)); };
        const auto fresh = [&] {
            AnalysisCache off{QString()};
            StageControl plain = control;
            plain.cache = &off;
            return everything(WorkspaceScanner::scan(root, plain));
        };
        const QStringList first = kept();
        QCOMPARE(first, fresh());
        QVERIFY(first.contains(QStringLiteral("  three  ../src/one.cpp")) ||
                first.join(u'\n').contains(QLatin1String("three")));
        QVERIFY(cache.recent(QStringLiteral("scan"), QByteArrayLiteral("last")));
        QCOMPARE(kept(), first);

        // A file's content changed: only its size differs.
        test::writeFile(root + QStringLiteral("/p/src/one.cpp"), "int one = 1;\n");
        QCOMPARE(kept(), fresh());
        QVERIFY(kept() != first);
        test::writeFile(root + QStringLiteral("/p/CMakeLists.txt"),
                        "project(p)\nadd_executable(one src/one.cpp)\n"
                        "add_executable(two src/one.cpp)\nadd_subdirectory(extra)\n");
        QVERIFY(kept().join(u'\n').contains(QLatin1String("two")));
        QCOMPARE(kept(), fresh());
        test::writeFile(root + QStringLiteral("/p/extra/CMakeLists.txt"),
                        "add_executable(four ../src/one.cpp)\n");
        QVERIFY(kept().join(u'\n').contains(QLatin1String("four")));
        QCOMPARE(kept(), fresh());
        test::writeFile(root + QStringLiteral("/p/package.xml"),
                        "<package format=\"3\"><name>renamed</name></package>\n");
        QVERIFY(kept().contains(QStringLiteral("package renamed at p")));
        QCOMPARE(kept(), fresh());
        // A setup.cfg appears: a file of the walk, so the walk differs.
        test::writeFile(root + QStringLiteral("/p/setup.cfg"),
                        "[options.entry_points]\nconsole_scripts =\n    tool = p.tool:main\n");
        QCOMPARE(kept(), fresh());
        // What the control skips is part of it too.
        control.skipped.insert(QStringLiteral("p/CMakeLists.txt"), QStringLiteral("crashed"));
        QVERIFY(kept().join(u'\n').contains(QLatin1String("file-skipped")));
        QCOMPARE(kept(), fresh());
        control.skipped.clear();
        QCOMPARE(kept(), fresh());
        QVERIFY(!kept().join(u'\n').contains(QLatin1String("file-skipped")));
    }
};

QTEST_GUILESS_MAIN(TestWorkspaceScan)
#include "tst_workspacescan.moc"
