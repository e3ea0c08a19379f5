#include "app/navigationhistory.h"

namespace rosarch {

NavigationHistory::NavigationHistory(QObject *parent) : QObject(parent) {}

void NavigationHistory::visit(const NavigationPlace &place)
{
    if (const NavigationPlace *now = current(); now && now->samePlace(place)) {
        updateCurrent(place);
        return;
    }
    m_places.resize(m_index + 1); // the places ahead are dropped
    m_places.append(place);
    if (m_places.size() > kCapacity)
        m_places.removeFirst();
    m_index = int(m_places.size()) - 1;
    Q_EMIT changed();
}

void NavigationHistory::updateCurrent(const NavigationPlace &place)
{
    if (m_index < 0)
        return;
    NavigationPlace &now = m_places[m_index];
    now.sourceFile = place.sourceFile;
    now.sourceLine = place.sourceLine;
    now.sourceFirstLine = place.sourceFirstLine;
}

const NavigationPlace *NavigationHistory::back()
{
    if (!canGoBack())
        return nullptr;
    --m_index;
    Q_EMIT changed();
    return &m_places.at(m_index);
}

const NavigationPlace *NavigationHistory::forward()
{
    if (!canGoForward())
        return nullptr;
    ++m_index;
    Q_EMIT changed();
    return &m_places.at(m_index);
}

const NavigationPlace *NavigationHistory::current() const
{
    return m_index >= 0 ? &m_places.at(m_index) : nullptr;
}

void NavigationHistory::clear()
{
    m_places.clear();
    m_index = -1;
    Q_EMIT changed();
}

} // namespace rosarch
