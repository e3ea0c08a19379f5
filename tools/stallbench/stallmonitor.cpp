#include "stallmonitor.h"
#include "jobs/stallprobe.h"

#include <QEvent>
#include <QMetaEnum>
#include <QThread>

#include <algorithm>
#include <map>

namespace rosarch {

namespace {

constexpr qint64 kRecordGapMs = 30;            ///< gaps recorded
constexpr qint64 kRecordDispatchNs = 15000000; ///< dispatches and scopes named in a gap

/// Scopes finished inside the current top-level dispatch: name → total time, outermost only
/// for nesting depth 0 and 1.
std::map<QString, qint64> &scopeTimes()
{
    static std::map<QString, qint64> times;
    return times;
}

QString eventName(QEvent::Type type)
{
    const char *name = QMetaEnum::fromType<QEvent::Type>().valueToKey(type);
    return name ? QString::fromLatin1(name) : QString::number(int(type));
}

} // namespace

StallMonitor::StallMonitor(int &argc, char **argv) : QApplication(argc, argv)
{
    m_clock.start();
    m_phaseClock.start();
    m_heartbeat.setTimerType(Qt::PreciseTimer);
    m_heartbeat.setInterval(10);
    QObject::connect(&m_heartbeat, &QTimer::timeout, [this] { tick(); });
    m_heartbeat.start();
    StallProbe::setSink(&StallMonitor::scopeFinished);
}

void StallMonitor::scopeFinished(const char *name, qint64 nanoseconds, int depth)
{
    if (QThread::currentThread() != qApp->thread() || depth > 4)
        return;
    QString key = QString::fromLatin1(name);
    if (depth > 0)
        key.prepend(QString(depth * 2, QLatin1Char(' ')));
    scopeTimes()[key] += nanoseconds;
}

void StallMonitor::beginPhase(const QString &name)
{
    m_phase = name;
    m_phaseClock.restart();
}

void StallMonitor::tick()
{
    const qint64 now = m_clock.elapsed();
    if (m_lastTick >= 0) { // every gap counts for the longest, recorded or not
        qint64 &longest = m_longest[m_phase];
        longest = std::max(longest, now - m_lastTick);
    }
    if (m_lastTick >= 0 && now - m_lastTick >= kRecordGapMs)
        m_gaps.append({now - m_lastTick, m_phaseClock.elapsed(), m_phase,
                       m_dispatches.join(QLatin1String("\n"))});
    m_dispatches.clear();
    m_lastTick = now;
}

bool StallMonitor::notify(QObject *receiver, QEvent *event)
{
    if (QThread::currentThread() != thread())
        return QApplication::notify(receiver, event);
    if (m_depth > 0) {
        // an event sent inside the dispatch (a widget's paint inside the window's repaint, a
        // layout): named like a scope, one level deep only
        if (m_depth > 1) {
            ++m_depth;
            const bool result = QApplication::notify(receiver, event);
            --m_depth;
            return result;
        }
        QString name = QString::fromLatin1(receiver->metaObject()->className());
        if (receiver->parent() && name == QLatin1String("QWidget")) { // a scroll area's viewport
            // named by the panel it is in: the item views are plain QTreeViews
            const QObject *view = receiver->parent();
            const QObject *panel = view->parent();
            while (panel && panel->metaObject()->className()[0] == 'Q')
                panel = panel->parent();
            name = QString::fromLatin1(view->metaObject()->className()) +
                   QLatin1String(" viewport") +
                   (panel ? QStringLiteral(" in %1").arg(
                                QString::fromLatin1(panel->metaObject()->className()))
                          : QString());
        }
        const QString what = QStringLiteral("  %1 %2").arg(name, eventName(event->type()));
        QElapsedTimer timer;
        timer.start();
        ++m_depth;
        const bool result = QApplication::notify(receiver, event);
        --m_depth;
        scopeTimes()[what] += timer.nsecsElapsed();
        return result;
    }
    ++m_depth;
    scopeTimes().clear();
    QElapsedTimer timer;
    timer.start();
    // what the receiver is, captured before: the event may delete it
    const QString what = QStringLiteral("%1 %2").arg(
        QString::fromLatin1(receiver->metaObject()->className()), eventName(event->type()));
    const bool result = QApplication::notify(receiver, event);
    const qint64 ns = timer.nsecsElapsed();
    --m_depth;
    if (ns >= kRecordDispatchNs) {
        QString line = QStringLiteral("    %1 ms: %2").arg(ns / 1000000).arg(what);
        std::vector<std::pair<qint64, QString>> scopes;
        for (const auto &[name, time] : scopeTimes())
            if (time >= kRecordDispatchNs / 10)
                scopes.emplace_back(time, name);
        std::sort(scopes.begin(), scopes.end(), std::greater<>());
        for (const auto &[time, name] : scopes)
            line += QStringLiteral("\n      %1 ms %2").arg(time / 1000000, 5).arg(name);
        m_dispatches << line;
    }
    return result;
}

QList<StallMonitor::Gap> StallMonitor::gaps(const QString &phase) const
{
    QList<Gap> out;
    for (const Gap &g : m_gaps)
        if (phase.isEmpty() || g.phase == phase)
            out << g;
    std::sort(out.begin(), out.end(), [](const Gap &a, const Gap &b) { return a.ms > b.ms; });
    return out;
}

qint64 StallMonitor::longestGap(const QString &phase) const
{
    if (!phase.isEmpty())
        return m_longest.value(phase);
    qint64 longest = 0;
    for (const qint64 ms : m_longest)
        longest = std::max(longest, ms);
    return longest;
}

qint64 StallMonitor::lastGapEnd(qint64 ms) const
{
    qint64 end = 0;
    for (const Gap &g : m_gaps)
        if (g.phase == m_phase && g.ms > ms)
            end = std::max(end, g.endMs);
    return end;
}

} // namespace rosarch
