#pragma once

#include <QList>
#include <QString>

#include <functional>

class QLineEdit;

namespace rosarch {

class MainWindow;

/// One filter box of the window the stall benchmark types into.
struct FilterBox
{
    QString panel;   ///< "launch tree", "findings", ...
    QLineEdit *edit; ///< where the keys go
    /// Puts the panel in front and gives it something to filter (a node class with the most
    /// parameters for the Parameters panel); runs before the measured phase.
    std::function<void()> prepare;
    /// What the panel shows now ("29 rows", "3 of 12 matches"), for the report.
    std::function<QString()> shown;
};

/// Every filter box of `window`: node list, launch tree, findings, parameters, diagram find.
QList<FilterBox> filterBoxes(MainWindow &window);

} // namespace rosarch
