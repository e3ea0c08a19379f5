#include "xmllaunchreader.h"

namespace rosarch {

bool XmlLaunchReader::isLaunchFile(const QByteArray &content)
{
    Q_UNUSED(content);
    return false;
}

LaunchFileDescription XmlLaunchReader::read(const QByteArray &content, const QString &file)
{
    Q_UNUSED(content);
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Xml;
    return d;
}

} // namespace rosarch
