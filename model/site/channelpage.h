#pragma once

#include "site/sitehtml.h"
#include "site/sitemodel.h"

namespace rosarch {

/// The page of one topic, service or action: its type, and per system who publishes and who
/// subscribes (who serves, who calls), by resolved name, with the remaps that lead there.
class ChannelPage
{
public:
    static SiteFile write(const SiteContext &context, const QString &key,
                          const SiteChannel &channel);
};

} // namespace rosarch
