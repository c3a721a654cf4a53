#pragma once
// comparison.json "fit_options" of a scan: the registration options the
// fit subset was registered with (dof, robust loss and its scale, outlier
// rules, iteration caps), written so that the report of the scan states
// them as the probe-point report does (docs/formats.md "comparison.json of
// a scan"). Read back into the members of ComparisonDocument::Options they
// fill; a scan's points are contact points (no probe radius).
//
// This header exposes nlohmann::json; include it only from .cpp files.
#include "base/json_cursor.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/registration.hpp"

namespace furrow {

json_fields::json scan_fit_options_json(const RegistrationOptions& r);

// Fills dof, loss, loss_scale, outlier_*, edge_tolerance, confirm_neighbours,
// neighbour_radius, max_* and motion_tolerance; the rest of `o` is left.
void read_scan_fit_options(const JsonCursor& c, ComparisonDocument::Options& o);

}  // namespace furrow
