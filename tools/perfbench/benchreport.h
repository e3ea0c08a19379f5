#pragma once

#include "benchsteps.h"

#include <QList>
#include <QString>

namespace rosarch::perfbench {

/// One measured case: the runs of one kind of recovery.
struct Case
{
    QString name; ///< "cold", "warm", "edit", "cold-no-cache"
    Path path = Path::Worker;
    QList<qint64> ms; ///< every run
    qint64 peakRssKb = 0;
    QString target; ///< the issue's target for this case ("" = none)
    double targetRatio = 0;
    qint64 targetMs = 0; ///< an absolute bound besides the ratio (0 = none)

    qint64 median() const;
    bool met(const ParseBaseline &baseline) const;
};

struct Report
{
    QString workspace;
    int cores = 0;
    QString editedFile;
    ParseBaseline baseline;
    QList<Case> cases;
    qint64 peakRssKb = 0; ///< the largest of every run's
    qint64 memoryTargetKb = 300 * 1024;
};

/// The report as a table for people.
QString reportText(const Report &report);
/// The report as JSON (`--json`).
QByteArray reportJson(const Report &report);

} // namespace rosarch::perfbench
