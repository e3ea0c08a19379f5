#pragma once

// Screenshots of widgets under test, for a person to look at.
#include "support/testsupport.h"
#include <QWidget>

namespace rosarch::test {

/// Saves `w` as `name` into $ROSARCH_SCREENSHOT_DIR when that is set.
inline void saveScreenshot(QWidget &w, const QString &name)
{
    const QString dir = qEnvironmentVariable("ROSARCH_SCREENSHOT_DIR");
    if (dir.isEmpty())
        return;
    QTest::qWait(100); // let posted layout requests settle, as they would on screen
    w.grab().save(QDir(dir).filePath(name));
}

} // namespace rosarch::test
