#include "launch/xmlyaml/yamlsupport.h"

#include <QStringList>

namespace rosarch {

QString yamlValueText(const YAML::Node &n, YamlBudget *budget, int maxDepth, int depth)
{
    if (depth > maxDepth || !budget->spend())
        return {};
    if (n.IsScalar())
        return QString::fromStdString(n.Scalar());
    if (n.IsSequence()) {
        QStringList items;
        for (const YAML::Node &item : n) {
            if (budget->exhausted)
                break;
            items << yamlValueText(item, budget, maxDepth, depth + 1);
        }
        return QLatin1Char('[') + items.join(QStringLiteral(", ")) + QLatin1Char(']');
    }
    return {};
}

YAML::Node loadYaml(const QByteArray &content, const QString &file, Diagnostic *error)
{
    try {
        return YAML::Load(content.toStdString());
    } catch (const YAML::Exception &ex) {
        error->severity = Diagnostic::Severity::Error;
        error->code = QStringLiteral("malformed-yaml");
        error->evidence.file = file;
        error->evidence.line = error->evidence.endLine = ex.mark.is_null() ? 1 : ex.mark.line + 1;
        error->evidence.column = error->evidence.endColumn =
            ex.mark.is_null() ? 1 : ex.mark.column + 1;
        error->message = QStringLiteral("Malformed YAML at line %1, column %2: %3.")
                             .arg(error->evidence.line)
                             .arg(error->evidence.column)
                             .arg(QString::fromStdString(ex.msg));
    }
    // Keep what was read: the lines before the error, if they parse on their own.
    qsizetype cut = 0;
    for (int line = 1; line < error->evidence.line && cut >= 0; ++line) {
        cut = content.indexOf('\n', cut);
        if (cut >= 0)
            ++cut;
    }
    try {
        return cut > 0 ? YAML::Load(content.left(cut).toStdString()) : YAML::Node();
    } catch (const YAML::Exception &) {
        return {};
    }
}

} // namespace rosarch
