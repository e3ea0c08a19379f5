#include "core/stagecontrol.h"

namespace rosarch {

StageControl StageControl::forStage(int stage) const
{
    StageControl c = *this;
    if (stageProgressed)
        c.progressed = [stageProgressed = stageProgressed, stage](int done, int total,
                                                                  const QString &what) {
            stageProgressed(stage, done, total, what);
        };
    return c;
}

StageControl StageControl::part(int before, int all) const
{
    StageControl c = *this;
    if (progressed)
        c.progressed = [progressed = progressed, before, all](int done, int, const QString &what) {
            progressed(before + done, all, what);
        };
    return c;
}

FileWork::FileWork(const StageControl &control, const QString &file, Start start)
    : m_control(control), m_file(file)
{
    if (start == Start::Now)
        this->start();
}

void FileWork::start()
{
    if (m_reported || !m_control.fileWork || m_control.skipped.contains(m_file))
        return; // a skipped file is not worked on
    m_reported = true;
    m_control.fileWork(m_file, true);
}

FileWork::~FileWork()
{
    if (m_reported)
        m_control.fileWork(m_file, false);
}

bool FileWork::skip(QList<Diagnostic> *diagnostics) const
{
    const auto it = m_control.skipped.constFind(m_file);
    if (it == m_control.skipped.cend())
        return false;
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.code = QStringLiteral("file-skipped");
    d.message = QStringLiteral("%1 was not analysed: %2").arg(m_file, it.value());
    d.evidence = Evidence::startOf(m_file);
    diagnostics->append(d);
    return true;
}

} // namespace rosarch
