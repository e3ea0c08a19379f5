#include "plantuml/plantumlrenderer.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>

namespace rosarch {

QString PlantUmlRenderer::findJar(const QString &configured)
{
    QStringList candidates{configured, qEnvironmentVariable("ROSARCH_PLANTUML_JAR")};
    if (QCoreApplication::instance()) {
        const QDir app(QCoreApplication::applicationDirPath());
        candidates << app.filePath(QStringLiteral("plantuml.jar"))
                   << app.filePath(QStringLiteral("../share/rosarch/plantuml.jar"))
                   // Debian's plantuml package, beside an installed /usr/bin/rosarch.
                   << app.filePath(QStringLiteral("../share/plantuml/plantuml.jar"));
    }
#ifdef ROSARCH_BUILD_PLANTUML_JAR
    candidates << QStringLiteral(ROSARCH_BUILD_PLANTUML_JAR);
#endif
    for (const QString &c : std::as_const(candidates))
        if (!c.isEmpty() && QFileInfo(c).isFile())
            return QFileInfo(c).absoluteFilePath();
    return {};
}

QString PlantUmlRenderer::findJava()
{
    const QString home = qEnvironmentVariable("JAVA_HOME");
    if (!home.isEmpty()) {
        const QString java = QDir(home).filePath(QStringLiteral("bin/java"));
        if (QFileInfo(java).isExecutable())
            return java;
    }
    return QStandardPaths::findExecutable(QStringLiteral("java"));
}

QStringList PlantUmlRenderer::arguments(const QString &jar, const QString &format,
                                        const QStringList &files)
{
    return QStringList{QStringLiteral("-Djava.awt.headless=true"),
                       QStringLiteral("-jar"),
                       jar,
                       QStringLiteral("-t") + format,
                       QStringLiteral("-nometadata"),
                       QStringLiteral("-charset"),
                       QStringLiteral("UTF-8")} +
           files;
}

QString PlantUmlRenderer::outputOf(const QString &pumlFile, const QString &format)
{
    const QFileInfo info(pumlFile);
    return info.dir().filePath(info.completeBaseName() + QLatin1Char('.') + format);
}

bool PlantUmlRenderer::render(const QStringList &files, const QString &format, const QString &jar,
                              const QString &java, QString *error, int timeoutMs)
{
    if (format != QLatin1String("svg") && format != QLatin1String("png")) {
        *error = QStringLiteral("PlantUML renders svg or png here, not '%1'.").arg(format);
        return false;
    }
    if (jar.isEmpty() || !QFileInfo(jar).isFile()) {
        *error = QStringLiteral("No PlantUML jar found. Set its path (--plantuml-jar, "
                                "$ROSARCH_PLANTUML_JAR, or Settings in the GUI); "
                                "scripts/fetch-plantuml.sh fetches one.");
        return false;
    }
    if (java.isEmpty()) {
        *error = QStringLiteral("No Java runtime found (install default-jre-headless, or set "
                                "$JAVA_HOME).");
        return false;
    }
    if (files.isEmpty())
        return true;
    QProcess plantuml;
    plantuml.setProcessChannelMode(QProcess::MergedChannels);
    plantuml.start(java, arguments(jar, format, files));
    if (!plantuml.waitForStarted(30000)) {
        *error = QStringLiteral("Java could not be started: %1").arg(plantuml.errorString());
        return false;
    }
    if (!plantuml.waitForFinished(timeoutMs)) {
        plantuml.kill();
        plantuml.waitForFinished(5000);
        *error =
            QStringLiteral("PlantUML did not finish within %1 s; stopped.").arg(timeoutMs / 1000);
        return false;
    }
    const QString output = QString::fromLocal8Bit(plantuml.readAll()).trimmed();
    if (plantuml.exitStatus() != QProcess::NormalExit || plantuml.exitCode() != 0) {
        *error = output.isEmpty()
                     ? QStringLiteral("PlantUML failed (exit code %1).").arg(plantuml.exitCode())
                     : output;
        return false;
    }
    return true;
}

} // namespace rosarch
