#include "pythonlaunchreader.h"

namespace rosarch {

bool PythonLaunchReader::isLaunchFile(const QByteArray &content)
{
    Q_UNUSED(content);
    return false;
}

LaunchFileDescription PythonLaunchReader::read(const QByteArray &content, const QString &file)
{
    Q_UNUSED(content);
    LaunchFileDescription d;
    d.file = file;
    d.format = LaunchFileDescription::Format::Python;
    return d;
}

} // namespace rosarch
