#include "cache/evidenceshift.h"

#include <algorithm>
#include <compare>
#include <tuple>

namespace rosarch {

void EvidenceShift::add(const Evidence &before, const Evidence &after)
{
    if (before.file != after.file) {
        m_conflict = true;
        return;
    }
    const auto it = m_moves.constFind(Key{before});
    if (it == m_moves.cend())
        m_moves.insert(Key{before}, after);
    else if (!(*it == after))
        m_conflict = true; // one old location, two new ones
    if (!(before == after))
        m_moved.insert(before.file);
}

bool EvidenceShift::settle()
{
    m_files.clear();
    if (m_conflict)
        return false;
    // Per file, the locations in their old order must keep it, and keep which of them share
    // a line or a start: stages sort and merge by these (composer, architecture checks).
    QHash<QString, QList<std::pair<Evidence, Evidence>>> byFile;
    for (auto it = m_moves.cbegin(); it != m_moves.cend(); ++it)
        if (m_moved.contains(it.key().e.file))
            byFile[it.key().e.file].append({it.key().e, it.value()});
    const auto full = [](const Evidence &e) {
        return std::tuple(e.line, e.column, e.endLine, e.endColumn);
    };
    for (auto it = byFile.begin(); it != byFile.end(); ++it) {
        QList<std::pair<Evidence, Evidence>> &moves = *it;
        std::sort(moves.begin(), moves.end(),
                  [&](const auto &a, const auto &b) { return full(a.first) < full(b.first); });
        for (qsizetype i = 1; i < moves.size(); ++i) {
            const Evidence &a = moves.at(i - 1).first, &b = moves.at(i).first;
            const Evidence &na = moves.at(i - 1).second, &nb = moves.at(i).second;
            if ((a.line <=> b.line) != (na.line <=> nb.line) ||
                (std::tie(a.line, a.column) <=> std::tie(b.line, b.column)) !=
                    (std::tie(na.line, na.column) <=> std::tie(nb.line, nb.column)) ||
                (full(a) <=> full(b)) != (full(na) <=> full(nb)))
                return false;
        }
    }
    m_files = QList<QString>(m_moved.cbegin(), m_moved.cend());
    std::sort(m_files.begin(), m_files.end());
    return true;
}

} // namespace rosarch
