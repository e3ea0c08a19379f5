#pragma once

#include <QIODevice>
#include <QTextStream>

#include <cstdio>

namespace rosarch {

/// A QTextStream to stdout or stderr that never lets a control character through: every
/// one but newline and tab is written as a visible escape ("\x1b"), as visibleText() does.
/// Messages quote file names, names and values from the workspace, and a crafted repository
/// must not be able to clear the screen, rewrite earlier lines or set the terminal's title of
/// whoever runs rosarch on it. A diagnostic line escapes its own newlines (visibleText()); this
/// stream is the guard for every other message.
class TerminalStream : public QTextStream
{
public:
    explicit TerminalStream(FILE *file);
    ~TerminalStream() override;
    TerminalStream(const TerminalStream &) = delete;
    TerminalStream &operator=(const TerminalStream &) = delete;

private:
    /// The UTF-8 bytes QTextStream writes, escaped on their way to the file.
    class EscapingDevice : public QIODevice
    {
    public:
        explicit EscapingDevice(FILE *file);

    protected:
        qint64 readData(char *, qint64) override { return -1; }
        qint64 writeData(const char *data, qint64 size) override;

    private:
        FILE *m_file;
        bool m_lead = false; ///< the last byte written was 0xC2, which may begin a C1 control
    };
    EscapingDevice m_device;
};

} // namespace rosarch
