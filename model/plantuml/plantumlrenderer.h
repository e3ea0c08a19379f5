#pragma once

#include <QString>
#include <QStringList>

namespace rosarch {

/// Renders PlantUML files to SVG or PNG with the real PlantUML (a jar run by Java), the same
/// pictures the published pipeline gets. One JVM renders all files; each picture is written
/// next to its .puml. Without a jar or Java, says where it looked.
class PlantUmlRenderer
{
public:
    /// The PlantUML jar: `configured` when it is a file (the GUI's setting, --plantuml-jar),
    /// else $ROSARCH_PLANTUML_JAR, else plantuml.jar next to the executable or in
    /// ../share/rosarch, else the jar of the build tree. "" when none exists.
    static QString findJar(const QString &configured = {});
    /// Java: $JAVA_HOME/bin/java, else `java` on the PATH; "" when there is none.
    static QString findJava();

    /// The Java arguments that render `files` as `format` ("svg" or "png").
    static QStringList arguments(const QString &jar, const QString &format,
                                 const QStringList &files);
    /// Renders `files` and waits (at most `timeoutMs`). False, with PlantUML's own messages
    /// (the file and line of a syntax error) or the reason it could not run, in `error`.
    static bool render(const QStringList &files, const QString &format, const QString &jar,
                       const QString &java, QString *error, int timeoutMs = 600000);
    /// The picture PlantUML writes for `pumlFile` in `format`.
    static QString outputOf(const QString &pumlFile, const QString &format);
};

} // namespace rosarch
