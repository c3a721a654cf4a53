#pragma once
// The measurements of several setups compared as one part (docs/cmm.md
// "Setups", docs/verification.md): `furrow compare --measurements A
// --measurements B --plan setup1/plan.json --plan setup2/plan.json`.
//
// Each setup's program measures that setup's part alignment first, so the
// points a CMM reports for it are in the setup frame (plan.json `setup`:
// x_setup = R x_part + t). Taken back to the part frame with the inverse
// motion, the files of all setups are one point set of one part, fitted
// and judged together: one comparison, one verdict. A file measured without
// the setup's alignment (raw machine coordinates) cannot be merged this way;
// compare it alone with its own plan.
//
// Errors: InputError naming the plan (probes that differ, an id in two
// plans).
#include <string>
#include <vector>

#include "io/cmm/measurement_file.hpp"
#include "io/plan_file.hpp"

namespace furrow {

// The set with every position and direction (measured, nominal) taken from
// the setup frame to the part frame; unchanged without a setup (setup 1).
MeasurementSet measurements_in_part_frame(MeasurementSet set, const std::optional<PlanSetupRecord>& setup);

// The plans of the setups as one plan in the part frame: their points in
// the order given (orders renumbered 1..n), ids unique over all (else
// InputError naming both plans), one probe (diameters must agree); no
// alignment, tips or setup (each setup's are in its own frame); a region
// listed short by a plan stays listed only when the merged plan holds fewer
// than its minimum of points there (a later setup may have measured it).
// `names[k]` names plans[k] in messages.
InspectionPlan merge_setup_plans(const std::vector<InspectionPlan>& plans, const std::vector<std::string>& names);

}  // namespace furrow
