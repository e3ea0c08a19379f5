#pragma once

#include "site/sitehtml.h"
#include "site/sitemodel.h"

namespace rosarch {

/// The page of one system (an entry point): its composed diagram, its launch tree with the
/// arguments, and the nodes and channels it runs.
class SystemPage
{
public:
    static SiteFile write(const SiteContext &context, const SiteSystem &system);
};

} // namespace rosarch
