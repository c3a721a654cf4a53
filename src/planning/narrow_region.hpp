#pragma once
// Regions too narrow for the border clearance: the contact rule
// (docs/cmm.md "Narrow regions").
//
// A region where no point is `border` mm (default: the ball's radius + 1) from
// its edges — a fillet, a chamfer-like strip, a small face — is not skipped
// for that alone. Its points are taken where the probe ball really measures
// them: the domain keeps no fixed clearance and tests every point with
// check_ball_contact (ball_contact.hpp): the contact is the closest point of
// the part from the ball's centre, on the point itself, nothing else
// touched, and it stays on the face and in the region with the centre off by
// the contact shift. A region where no point passes is reported with the
// largest ball that would measure it.
//
// Units: mm. Thread safety: the domain's check is a pure function of the
// finder, the part and the map, which must outlive it.
#include "geometry/closest_point.hpp"
#include "partition/region_map.hpp"
#include "planning/ball_contact.hpp"
#include "planning/region_domain.hpp"

namespace furrow {

// The region's domain under the contact rule: `options.border` is replaced
// by 0 (the contact check keeps the margin) and the check of a ball of
// `radius` is set.
RegionDomain contact_rule_domain(const Part& part, const RegionMap& map, int region_id, RegionDomainOptions options,
                                 const RiskMap* risk, const ClosestPointFinder& finder, double radius,
                                 const BallContactOptions& contact);

// The largest ball radius that measures some point of the region under the
// contact rule (largest_fitting_ball over the region's inside sample cells,
// at most `max_candidates` of them, evenly picked); 0 when none does.
double largest_ball_in_region(const RegionDomain& domain, const RegionMap& map, const ClosestPointFinder& finder,
                              double radius, const BallContactOptions& contact, std::size_t max_candidates = 256);

}  // namespace furrow
