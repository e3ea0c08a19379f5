#pragma once
// A real JSON-schema validator for the tests: tests/support/validate-json-schema.cjs run by
// node over the json-schema package that scripts/fetch-sarif-schema.sh puts in the build tree.
// The test needs ROSARCH_SOURCE_DIR, ROSARCH_SARIF_DIR and ROSARCH_NODE defined.
#include <QDir>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace rosarch::test {

/// `relative` in the source tree (`schemas/x.schema.json`).
inline QString sourceFile(const QString &relative)
{
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR)).filePath(relative);
}

/// Validates `files` against the schema file `schema`: the validator's exit code (0: all
/// valid, 1: one is invalid; -1: it did not finish, -2: it crashed) and its output.
inline int validateJsonSchema(const QString &schema, const QStringList &files, QString *output)
{
    QProcess node;
    node.start(
        QStringLiteral(ROSARCH_NODE),
        QStringList{QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                        .filePath(QStringLiteral("tests/support/validate-json-schema.cjs")),
                    QDir(QStringLiteral(ROSARCH_SARIF_DIR)).filePath(QStringLiteral("json-schema")),
                    schema} +
            files);
    if (!node.waitForFinished(60000))
        return -1;
    *output = QString::fromUtf8(node.readAllStandardOutput() + node.readAllStandardError());
    return node.exitStatus() == QProcess::NormalExit ? node.exitCode() : -2;
}

} // namespace rosarch::test
