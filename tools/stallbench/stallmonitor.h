#pragma once

#include <QApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QString>
#include <QTimer>

namespace rosarch {

/// Watches the UI thread of the stall benchmark: a 10 ms timer records every gap between its
/// ticks, and every event dispatch that takes long is recorded with its receiver, its event
/// type and the StallScopes that ran inside it (what was running).
class StallMonitor : public QApplication
{
public:
    struct Gap
    {
        qint64 ms = 0;    ///< from the tick before to the tick after
        qint64 endMs = 0; ///< when it ended, since the phase began
        QString phase;
        QString during; ///< the long dispatches that ended inside it
    };

    StallMonitor(int &argc, char **argv);

    /// Starts a phase: gaps are recorded under its name, times measured from now.
    void beginPhase(const QString &name);
    qint64 phaseElapsed() const { return m_phaseClock.elapsed(); }
    /// The gaps above `thresholdMs` recorded so far, longest first.
    QList<Gap> gaps(const QString &phase = {}) const;
    /// The longest gap of `phase` ("" = all phases).
    qint64 longestGap(const QString &phase = {}) const;
    /// When the last gap above `ms` of the current phase ended (0: none).
    qint64 lastGapEnd(qint64 ms) const;

    bool notify(QObject *receiver, QEvent *event) override;

private:
    void tick();
    static void scopeFinished(const char *name, qint64 nanoseconds, int depth);

    QTimer m_heartbeat;
    QElapsedTimer m_clock;
    QElapsedTimer m_phaseClock;
    qint64 m_lastTick = -1;
    QString m_phase;
    QList<Gap> m_gaps;                ///< those of 30 ms or more, with what ran in them
    QHash<QString, qint64> m_longest; ///< phase -> its longest gap
    QStringList m_dispatches;         ///< long dispatches since the last tick
    int m_depth = 0;
};

} // namespace rosarch
