#pragma once

#include "core/launchaction.h"

#include <QByteArray>

#include <optional>

namespace rosarch {

/// The binary form, in the analysis cache, of what reading one file as a launch file gives
/// (none when it is no launch file).
class LaunchFileCodec
{
public:
    static QByteArray encode(const std::optional<LaunchFileDescription> &read);
    /// False when `bytes` are not a whole, well-formed entry.
    static bool decode(const QByteArray &bytes, std::optional<LaunchFileDescription> *read);
};

} // namespace rosarch
