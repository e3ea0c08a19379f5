#pragma once

#include "core/composition.h"

#include <QCoreApplication>
#include <QHash>
#include <QString>

namespace rosarch {

/// The words of the composed diagram: tooltips that say what an element is and where it
/// comes from, and the reference-comparison banner.
class DiagramText
{
    Q_DECLARE_TR_FUNCTIONS(rosarch::DiagramText)
public:
    /// Tooltips for every element of `composite`, by element key (DiagramBuilder's keys).
    static QHash<QString, QString> toolTips(const Composite &composite);
    /// "3 elements of the reference are missing: part talker, topic /chatter, …"
    static QString missingBanner(const QStringList &missing);
    /// "demo" and "launch file src/demo/launch/demo.launch.py" for the frame.
    static QString frameDetail(const Composite &composite);
};

} // namespace rosarch
