// The installed tool as a user runs it: `cmake --install` into a temporary prefix, that
// prefix moved to another folder (so only relative paths can work), and rosarch run from
// there. The recovery of the installed example must equal the build tree's, and must have
// run in the installed analysis worker.
#include "support/testsupport.h"

#include <QDirIterator>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

struct Result
{
    int exitCode = -1;
    QString out;
    QString err;
};

// The environment of the installed tool: nothing points it at the build tree's helpers.
QProcessEnvironment installedEnvironment()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"ROSARCH_STAGES", "ROSARCH_LAYOUT", "ROSARCH_PLANTUML_JAR",
                             "ROSARCH_PROMPT_DIR", "ROSARCH_LLM_ENDPOINT", "LD_LIBRARY_PATH"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("ROSARCH_NO_CACHE"), QStringLiteral("1"));
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    return env;
}

Result run(const QString &program, const QStringList &args, const QByteArray &input = {},
           int timeoutMs = 180000)
{
    QProcess p;
    p.setProcessEnvironment(installedEnvironment());
    p.start(program, args);
    Result r;
    if (!p.waitForStarted(10000))
        return r;
    if (!input.isEmpty())
        p.write(input);
    p.closeWriteChannel();
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QMap<QString, QByteArray> tree(const QString &dir)
{
    QMap<QString, QByteArray> files;
    QDirIterator it(dir, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        files.insert(QDir(dir).relativeFilePath(path), test::readFile(path));
    }
    return files;
}

} // namespace

class TestInstall : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_prefix;

    QString installed(const char *folder, const QString &name = {}) const
    {
        const QString path = QDir(m_prefix).filePath(QString::fromUtf8(folder));
        return name.isEmpty() ? path : QDir(path).filePath(name);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        const QString staged = m_dir.filePath(QStringLiteral("staged"));
        const Result install = run(QStringLiteral(ROSARCH_CMAKE),
                                   {QStringLiteral("--install"), QStringLiteral(ROSARCH_BUILD_DIR),
                                    QStringLiteral("--prefix"), staged},
                                   {}, 300000);
        QVERIFY2(install.exitCode == 0, qPrintable(install.out + install.err));
        // Moved after installing: a path compiled in at install time no longer leads anywhere.
        m_prefix = m_dir.filePath(QStringLiteral("moved/usr"));
        QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("moved"))));
        QVERIFY(QDir().rename(staged, m_prefix));
    }

    void installsTheLayout()
    {
        const QStringList executables{
            installed(ROSARCH_INSTALL_BINDIR, QStringLiteral("rosarch")),
            installed(ROSARCH_INSTALL_HELPERDIR, QStringLiteral("rosarch-stages")),
            installed(ROSARCH_INSTALL_HELPERDIR, QStringLiteral("rosarch-layout"))};
        for (const QString &program : executables)
            QVERIFY2(QFileInfo(program).isExecutable(), qPrintable(program));
        // Only the application is on the PATH; the helpers are rosarch's own business.
        QCOMPARE(QDir(installed(ROSARCH_INSTALL_BINDIR)).entryList(QDir::Files),
                 QStringList{QStringLiteral("rosarch")});
        if (ROSARCH_INSTALLS_LIBRARIES)
            QVERIFY(QFileInfo::exists(
                installed(ROSARCH_INSTALL_LIBDIR, QStringLiteral("librosarch_core.so"))));
        QVERIFY(QFileInfo::exists(
            installed(ROSARCH_INSTALL_DATADIR, QStringLiteral("example_ws/src"))));
        const QByteArray desktop = test::readFile(
            installed(ROSARCH_INSTALL_SHAREDIR, QStringLiteral("applications/rosarch.desktop")));
        QVERIFY(desktop.contains("\nExec=rosarch %f\n"));
        QVERIFY(desktop.contains("\nIcon=rosarch\n"));
        QVERIFY(QFileInfo::exists(installed(
            ROSARCH_INSTALL_SHAREDIR, QStringLiteral("icons/hicolor/scalable/apps/rosarch.svg"))));
        const Result gunzip =
            run(QStringLiteral("gzip"),
                {QStringLiteral("-dc"),
                 installed(ROSARCH_INSTALL_MANDIR, QStringLiteral("man1/rosarch.1.gz"))});
        QVERIFY2(gunzip.exitCode == 0, qPrintable(gunzip.err));
        const QByteArray man = gunzip.out.toUtf8();
        QVERIFY(man.startsWith(".TH ROSARCH 1 \"\" \"rosarch " ROSARCH_VERSION "\""));
        QVERIFY(man.contains("\n.SS recover\n"));
        QVERIFY(man.contains("Usage: rosarch [options] recover workspace"));
        QVERIFY(!man.contains(ROSARCH_BUILD_DIR));
    }

    // Every library the installed programs load comes from the prefix (or the system), never
    // from the build tree.
    void loadsNothingFromTheBuildTree()
    {
        for (const QString &program :
             {installed(ROSARCH_INSTALL_BINDIR, QStringLiteral("rosarch")),
              installed(ROSARCH_INSTALL_HELPERDIR, QStringLiteral("rosarch-stages")),
              installed(ROSARCH_INSTALL_HELPERDIR, QStringLiteral("rosarch-layout"))}) {
            const Result ldd = run(QStringLiteral("ldd"), {program});
            QVERIFY2(ldd.exitCode == 0, qPrintable(ldd.err));
            QVERIFY2(!ldd.out.contains(QLatin1String("not found")), qPrintable(ldd.out));
            QVERIFY2(!ldd.out.contains(QLatin1String(ROSARCH_BUILD_DIR)), qPrintable(ldd.out));
            if (ROSARCH_INSTALLS_LIBRARIES && program.endsWith(QLatin1String("/rosarch")))
                QVERIFY2(ldd.out.contains(QStringLiteral("librosarch_app.so => ") + m_prefix),
                         qPrintable(ldd.out));
        }
    }

    void printsItsVersion()
    {
        const Result version = run(installed(ROSARCH_INSTALL_BINDIR, QStringLiteral("rosarch")),
                                   {QStringLiteral("--version")});
        QVERIFY2(version.exitCode == 0, qPrintable(version.err));
        QCOMPARE(version.out.trimmed(), QStringLiteral("rosarch " ROSARCH_VERSION));
    }

    // The installed example, recovered by the installed program in its installed worker,
    // gives the build tree's artifacts byte for byte.
    void recoversTheExample()
    {
        const QString workspace = installed(ROSARCH_INSTALL_DATADIR, QStringLiteral("example_ws"));
        const QString out = m_dir.filePath(QStringLiteral("installed"));
        const Result recovered =
            run(installed(ROSARCH_INSTALL_BINDIR, QStringLiteral("rosarch")),
                {QStringLiteral("recover"), workspace, QStringLiteral("--out"), out,
                 QStringLiteral("--no-decisions"), QStringLiteral("--quiet")});
        QVERIFY2(recovered.exitCode == 0, qPrintable(recovered.out + recovered.err));
        const QByteArray diagnostics =
            test::readFile(QDir(out).filePath(QStringLiteral("diagnostics.json")));
        QVERIFY2(!diagnostics.contains("worker-missing"), diagnostics.constData());

        const QString reference = m_dir.filePath(QStringLiteral("reference"));
        const Result built =
            run(QStringLiteral(ROSARCH_BINARY),
                {QStringLiteral("recover"), workspace, QStringLiteral("--out"), reference,
                 QStringLiteral("--no-decisions"), QStringLiteral("--quiet")});
        QVERIFY2(built.exitCode == 0, qPrintable(built.out + built.err));
        const QMap<QString, QByteArray> mine = tree(out);
        const QMap<QString, QByteArray> theirs = tree(reference);
        QVERIFY(mine.contains(QStringLiteral("architecture.json")));
        QCOMPARE(mine.keys(), theirs.keys());
        for (auto it = mine.cbegin(); it != mine.cend(); ++it)
            QVERIFY2(it.value() == theirs.value(it.key()), qPrintable(it.key()));
    }

    // The window, started without a workspace and without settings, opens the installed
    // example (and records it as the last workspace, which is what can be seen from outside).
    void windowOpensTheInstalledExample()
    {
        const QString home = m_dir.filePath(QStringLiteral("home"));
        QProcessEnvironment env = installedEnvironment();
        for (const char *name : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"})
            env.insert(QString::fromLatin1(name),
                       QDir(home).filePath(QString::fromLatin1(name).toLower()));
        QProcess window;
        window.setProcessEnvironment(env);
        window.start(installed(ROSARCH_INSTALL_BINDIR, QStringLiteral("rosarch")), {});
        QVERIFY(window.waitForStarted(10000));
        const QByteArray example =
            installed(ROSARCH_INSTALL_DATADIR, QStringLiteral("example_ws")).toUtf8();
        const auto recorded = [&] {
            QDirIterator it(home, QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext())
                if (test::readFile(it.next()).contains(example))
                    return true;
            return false;
        };
        const bool opened = QTest::qWaitFor(
            [&] { return recorded() || window.state() == QProcess::NotRunning; }, 120000);
        const bool crashed = window.state() == QProcess::NotRunning;
        window.kill();
        window.waitForFinished();
        QVERIFY2(opened && !crashed && recorded(), window.readAllStandardError().constData());
    }

    // The installed layout helper runs (it loads Graphviz's layout plugin through its RPATH).
    void laysOutWithTheInstalledHelper()
    {
        const Result layout =
            run(installed(ROSARCH_INSTALL_HELPERDIR, QStringLiteral("rosarch-layout")), {},
                "digraph g { rankdir=LR; a; b; a -> b; }\n");
        QVERIFY2(layout.exitCode == 0, qPrintable(layout.err));
        QVERIFY2(layout.out.contains(QLatin1String("\"a\"")) &&
                     layout.out.contains(QLatin1String("\"b\"")),
                 qPrintable(layout.out));
    }
};

QTEST_GUILESS_MAIN(TestInstall)
#include "tst_install.moc"
