#pragma once
// The re-measure plan of an INCONCLUSIVE comparison (`furrow remeasure`,
// docs/verification.md "Re-measuring"): the probe points that answer the
// verdict's open questions, as a plan in the part frame of the original one,
// so that its DMIS / I++ DME programs run on the same alignment and
// `furrow compare --measurements first.csv --measurements again.csv` merges
// the results by id.
//
// Per reason of the verdict (comparison.hpp):
//   suspected_blunder P   the point's nominal again, same id (a re-measure
//                         replaces it), plus `ring_points` neighbours on a
//                         circle of `radius` mm around it in the tangent
//                         plane, each projected onto the part (closest
//                         point; its foot and normal are the nominal), ids
//                         P_R1..P_Rn. The nominal is the original plan's
//                         point of that id when a plan is given, else the
//                         comparison's foot point of P. One point cannot
//                         tell dirt from a dent, its neighbours can: the
//                         outlier rule makes a large deviation real when
//                         three of its six nearest agree (docs/
//                         registration.md). 1.5 mm is inside the smallest
//                         dent a probe grid misses (6 mm across: a ring at
//                         3 mm would sit on its rim and see nothing),
//                         beyond the ball radius of usual styli (a contact
//                         of its own) and beyond a speck of dirt.
//   point_not_checked P   the ring around P alone (P was measured well;
//                         the best fit followed it for want of neighbours,
//                         comparison.hpp kCheckedRedundancy): their
//                         deviations show where P's could not.
//   point_not_measured P  P itself, as the original plan has it (the CMM
//                         answered it with an error or not at all); needs
//                         the plan.
//   gouge_not_measured S  the site's uv-box centre (id S_C) and
//                         `ring_points` points on the ellipse at half the
//                         box's half-extents (S_R1..): all inside the
//                         predicted extent, where gouge confirmation counts
//                         them (gouge_confirmation.hpp "on a site").
//   region_below_minimum  every point the original plan put into the region
//                         that the comparison did not evaluate, same ids;
//                         needs the plan.
// Other reasons (the alignment) are not answered by more of the same
// points; they are listed as not covered.
//
// A candidate is kept when its foot lies inside its face (not on a domain
// or trim edge: the probe would touch the edge) and a vertical stylus
// reaches it (accessibility.hpp); otherwise it is dropped with the reason.
// Ring ids use '_' because ids are DMIS labels. Points are probed in the
// order of the reasons, each centre before its ring; the moves are the
// planner's (moves.hpp). Deterministic.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "io/plan_file.hpp"
#include "planning/probe_planner.hpp"

namespace furrow {

struct RemeasureOptions {
  double radius = 1.5;  // ring radius around a suspect point [mm], > 0
  int ring_points = 6;  // neighbours per suspect point and per site, 0..24
  // Probe and moves: as `furrow plan` (PlannerOptions); probe_diameter is
  // the original plan's unless set.
  PlannerOptions planner;
};

// Throws InputError naming the option.
void validate(const RemeasureOptions& options);

struct RemeasureTarget {
  std::string kind;      // the verdict reason's kind
  std::string subject;   // its subject (point id, site id, "region N")
  std::vector<std::string> points;   // ids planned for it
  std::vector<std::string> dropped;  // "id: why" of candidates not planned
};

struct RemeasurePlan {
  PlanResult result;  // plan (probe, points in order), moves: for make_probe_program
  std::vector<RemeasureTarget> targets;
  std::vector<std::string> not_covered;  // reasons this command cannot answer, as text
};

// `comparison` must belong to `part` (check_comparison_against_part) and
// `plan`, if not null, too. Throws InputError when a reason names a point or
// site the comparison does not hold.
RemeasurePlan plan_remeasure(const Part& part, const ComparisonDocument& comparison, const InspectionPlan* plan,
                             const RemeasureOptions& options);

// InputError naming `name` when a comparison point's face index or name
// does not match the part.
void check_comparison_against_part(const ComparisonDocument& comparison, const Part& part, const std::string& name);

}  // namespace furrow
