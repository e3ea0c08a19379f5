#pragma once

#include "site/sitehtml.h"
#include "site/sitemodel.h"

namespace rosarch {

/// The findings page: every diagnostic and architecture check, filterable (by the site's
/// script) by severity, kind, package and system, with each kind's explanation and fix; the
/// findings a project accepted or hid are marked so.
class FindingsPage
{
public:
    static SiteFile write(const SiteContext &context);
};

} // namespace rosarch
