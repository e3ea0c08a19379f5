#include "app/appsettings.h"
#include "app/commands/commandline.h"
#include "app/mainwindow.h"
#include "core/helperprogram.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace {
void describeApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("rosarch"));
    QCoreApplication::setApplicationName(QStringLiteral("rosarch"));
    QCoreApplication::setApplicationVersion(QStringLiteral(ROSARCH_VERSION));
}

// Installed, the example is in the data folder; run from the build tree, it is the source's.
QString exampleWorkspace()
{
    const QString installed = rosarch::findInstalledData(QStringLiteral("example_ws"));
    return installed.isEmpty() ? QStringLiteral(ROSARCH_EXAMPLE_WORKSPACE) : installed;
}
} // namespace

int main(int argc, char **argv)
{
    if (rosarch::CommandLine::isHeadless(argc, argv)) {
        QCoreApplication app(argc, argv);
        describeApplication();
        return rosarch::CommandLine::run(app.arguments());
    }
    QApplication app(argc, argv);
    describeApplication();
    QTranslator translator;
    if (translator.load(QLocale(), QStringLiteral("rosarch"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(&translator);

    rosarch::MainWindow window;
    window.show();
    const QStringList args = app.arguments();
    // A path on the command line, else the last session's workspace, else the example.
    QString workspace = args.size() > 1 ? args.at(1) : rosarch::AppSettings().lastWorkspace();
    if (args.size() <= 1 && (workspace.isEmpty() || !QDir(workspace).exists()))
        workspace = exampleWorkspace();
    window.openWorkspace(QDir(workspace).absolutePath());
    return app.exec();
}
