#include "app/commands/terminalstream.h"

namespace rosarch {

TerminalStream::EscapingDevice::EscapingDevice(FILE *file) : m_file(file)
{
    open(QIODevice::WriteOnly | QIODevice::Unbuffered);
}

qint64 TerminalStream::EscapingDevice::writeData(const char *data, qint64 size)
{
    QByteArray out;
    out.reserve(size + 8);
    auto escape = [&out](uchar b) {
        static const char digits[] = "0123456789abcdef";
        out += "\\x";
        out += digits[b >> 4];
        out += digits[b & 15];
    };
    for (qint64 i = 0; i < size; ++i) {
        const auto b = uchar(data[i]);
        if (m_lead) { // 0xC2 0x80..0x9F is a C1 control in UTF-8 (0x9B is a terminal's CSI)
            m_lead = false;
            if (b >= 0x80 && b <= 0x9f) {
                escape(b);
                continue;
            }
            out += char(0xc2);
        }
        if (b == 0xc2)
            m_lead = true;
        else if ((b < 0x20 && b != '\n' && b != '\t') || b == 0x7f)
            escape(b);
        else
            out += char(b);
    }
    // A lone 0xC2 at the end waits for the next write, which QTextStream's encoder makes.
    if (!out.isEmpty() &&
        std::fwrite(out.constData(), 1, size_t(out.size()), m_file) != size_t(out.size()))
        return -1;
    std::fflush(m_file);
    return size;
}

TerminalStream::TerminalStream(FILE *file) : m_device(file)
{
    setDevice(&m_device);
}

TerminalStream::~TerminalStream()
{
    flush();
    setDevice(nullptr); // the device goes before the base class would flush into it
}

} // namespace rosarch
