#include "yamllaunchreader.h"

namespace rosarch {

bool YamlLaunchReader::isLaunchFile(const QByteArray &content)
{
    Q_UNUSED(content);
    return false;
}

LaunchFileDescription YamlLaunchReader::read(const QByteArray &content, const QString &file)
{
    Q_UNUSED(content);
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Yaml;
    return d;
}

} // namespace rosarch
