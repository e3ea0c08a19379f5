#pragma once

#include <QString>

namespace rosarch {

/// Where an element of the model comes from (blueprint §5): analysis, an accepted suggestion,
/// or a person's correction. Exports write it as `provenance` when it is not `recovered`.
enum class Provenance
{
    Recovered,
    Suggested,
    Corrected
};

/// "recovered", "suggested", "corrected".
QString provenanceName(Provenance provenance);

/// What a person's review left on an element: where it comes from and whether it was checked.
struct Marks
{
    Provenance provenance = Provenance::Recovered;
    bool reviewed = false;
    bool isDefault() const { return provenance == Provenance::Recovered && !reviewed; }
    bool operator==(const Marks &) const = default;
};

} // namespace rosarch
