#include "suggestions/suggestionreport.h"

namespace rosarch {

int SuggestionReport::discardedTotal() const
{
    int n = 0;
    for (int c : discarded)
        n += c;
    return n;
}

void SuggestionReport::discard(const QString &reason, const QString &detail)
{
    ++discarded[reason];
    discardedDetails << reason + QStringLiteral(": ") + detail;
}

} // namespace rosarch
