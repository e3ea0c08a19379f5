#pragma once

#include "site/sitehtml.h"
#include "site/sitemodel.h"

namespace rosarch {

/// The page of one node class (or pluginlib plugin): its description, ports, parameters and
/// the instances the systems launch, each with its resolved names and parameters in effect.
class NodePage
{
public:
    static SiteFile write(const SiteContext &context, const AtomicNode &node);
};

} // namespace rosarch
