#include "benchreport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace rosarch::perfbench {

qint64 Case::median() const
{
    if (ms.isEmpty())
        return 0;
    QList<qint64> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    return sorted.at(sorted.size() / 2);
}

bool Case::met(const ParseBaseline &baseline) const
{
    if (targetRatio <= 0)
        return true;
    const bool ratio = double(median()) <= targetRatio * double(std::max<qint64>(baseline.ms, 1));
    return ratio && (targetMs <= 0 || median() < targetMs);
}

namespace {

QString ratio(qint64 ms, qint64 baseline)
{
    return QString::number(double(ms) / double(std::max<qint64>(baseline, 1)), 'f', 2) +
           QLatin1Char('x');
}

QString pathName(Path p)
{
    switch (p) {
    case Path::Worker:
        return QStringLiteral("worker");
    case Path::InProcess:
        return QStringLiteral("in-process");
    case Path::Session:
        return QStringLiteral("gui-session");
    case Path::Command:
        return QStringLiteral("recover-command");
    }
    return {};
}

} // namespace

QString reportText(const Report &r)
{
    QString out;
    out += QStringLiteral("workspace  %1\ncores      %2\n").arg(r.workspace).arg(r.cores);
    out += QStringLiteral("baseline   %1 ms: single-core tree-sitter parse of %2 Python and %3 "
                          "C++ files (%4 KB)\n")
               .arg(r.baseline.ms)
               .arg(r.baseline.pythonFiles)
               .arg(r.baseline.cppFiles)
               .arg(r.baseline.bytes / 1024);
    if (!r.editedFile.isEmpty())
        out += QStringLiteral("edited     %1\n").arg(r.editedFile);
    out += QStringLiteral("\n%1 %2 %3 %4 %5 %6  %7\n")
               .arg(QStringLiteral("case"), -14)
               .arg(QStringLiteral("path"), -11)
               .arg(QStringLiteral("median ms"), 10)
               .arg(QStringLiteral("ratio"), 7)
               .arg(QStringLiteral("peak MB"), 8)
               .arg(QStringLiteral("target"), -18)
               .arg(QStringLiteral("runs (ms)"));
    for (const Case &c : r.cases) {
        QStringList runs;
        for (qint64 ms : c.ms)
            runs << QString::number(ms);
        const QString target = c.target.isEmpty()
                                   ? QString()
                                   : c.target + (c.met(r.baseline) ? QStringLiteral(" met")
                                                                   : QStringLiteral(" MISSED"));
        out += QStringLiteral("%1 %2 %3 %4 %5 %6  %7\n")
                   .arg(c.name, -14)
                   .arg(pathName(c.path), -11)
                   .arg(c.median(), 10)
                   .arg(ratio(c.median(), r.baseline.ms), 7)
                   .arg(QString::number(double(c.peakRssKb) / 1024.0, 'f', 0), 8)
                   .arg(target, -18)
                   .arg(runs.join(QLatin1Char(' ')));
    }
    out += QStringLiteral("\npeak memory %1 MB (target <= %2 MB: %3)\n")
               .arg(QString::number(double(r.peakRssKb) / 1024.0, 'f', 0))
               .arg(r.memoryTargetKb / 1024)
               .arg(r.peakRssKb <= r.memoryTargetKb ? QStringLiteral("met")
                                                    : QStringLiteral("MISSED"));
    return out;
}

QByteArray reportJson(const Report &r)
{
    QJsonArray cases;
    for (const Case &c : r.cases) {
        QJsonArray runs;
        for (qint64 ms : c.ms)
            runs.append(ms);
        cases.append(QJsonObject{
            {QStringLiteral("case"), c.name},
            {QStringLiteral("path"), pathName(c.path)},
            {QStringLiteral("median_ms"), c.median()},
            {QStringLiteral("ratio"),
             double(c.median()) / double(std::max<qint64>(r.baseline.ms, 1))},
            {QStringLiteral("peak_rss_kb"), c.peakRssKb},
            {QStringLiteral("target"), c.target},
            {QStringLiteral("target_met"), c.met(r.baseline)},
            {QStringLiteral("runs_ms"), runs},
        });
    }
    const QJsonObject root{
        {QStringLiteral("workspace"), r.workspace},
        {QStringLiteral("cores"), r.cores},
        {QStringLiteral("edited_file"), r.editedFile},
        {QStringLiteral("baseline"),
         QJsonObject{{QStringLiteral("ms"), r.baseline.ms},
                     {QStringLiteral("python_files"), r.baseline.pythonFiles},
                     {QStringLiteral("cpp_files"), r.baseline.cppFiles},
                     {QStringLiteral("bytes"), r.baseline.bytes}}},
        {QStringLiteral("cases"), cases},
        {QStringLiteral("peak_rss_kb"), r.peakRssKb},
        {QStringLiteral("memory_target_met"), r.peakRssKb <= r.memoryTargetKb},
    };
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

} // namespace rosarch::perfbench
