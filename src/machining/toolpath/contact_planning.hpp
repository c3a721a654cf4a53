#pragma once
// Contact-point planning for a finishing path (docs/architecture.md "Machining error
// between contact points"): passes laid side by side with side steps from a
// target scallop height, contact points along each pass with forward steps
// from a tolerance (forward_step.hpp).
//
// Directions:
//   along_u / along_v  iso-parametric passes on every face: v (or u) fixed
//                      per pass, from one side of the parameter rectangle
//                      to the other;
//   plane              iso-planar passes: sections by vertical planes at an
//                      angle (degrees from +x, counter-clockwise seen from
//                      above), offset across the whole part (crossing faces).
// Side steps (iso-scallop): each next pass is placed from the previous one.
// Along the current pass the surface is sampled; at each sample the side step
// w whose scallop equals the target is computed for the cross-section there
// (cross_section_scallop.hpp: curvature across the pass, tilt of the normal;
// exact for the ball; the pair of contacts starting at the sample, so that a
// flat-bottomed cutter crossing the crest of a convex part is seen touching
// on both sides of its bottom) and converted into the pass parameter (v, u, or plane
// offset) by the surface's rate across the pass; the smallest wins, and is
// checked again from the candidate next pass (whose curvature may be
// tighter), so the scallop stays at or below the target everywhere up to the
// circle model's accuracy (the z-map of `furrow predict` tells the truth).
// Where a concave section is tighter than the cutter there is no scallop,
// the cutter gouges: the flat-surface side step is used there.
// Passes are split where the surface leaves the face's trim, the part (plane
// direction) or becomes too steep for a 3-axis tool (n_z < min_normal_z);
// each piece is planned separately. Forward steps run in parallel over
// passes; the plan is deterministic.
#include <functional>
#include <string>
#include <vector>

#include "machining/prediction/cross_section_scallop.hpp"
#include "machining/toolpath/forward_step.hpp"

namespace furrow {

enum class PassDirection { along_u, along_v, plane };

struct PassDirectionSpec {
  PassDirection kind = PassDirection::along_u;
  double angle_deg = 0;  // plane only
};
// "u", "v" or "plane:ANGLE"; throws InputError naming `where` otherwise.
PassDirectionSpec parse_pass_direction(const std::string& text, const std::string& where);
std::string to_string(const PassDirectionSpec& direction);

struct ContactPlanOptions {
  ForwardStepOptions forward;    // tolerance, rule, predictor
  double scallop = 0.005;        // [mm] target scallop height between passes
  double min_normal_z = 0.05;    // contacts steeper than acos(0.05) = 87 deg are left out
  double sample_spacing = 1.0;   // [mm] along a pass: side-step samples and split search
  int max_passes = 5000;         // a cap, checked on an estimate first (InputError beyond;
                                 // docs/formats.md "Limits")
  long max_points = 5'000'000;   // contact points of the whole path (InputError beyond)
  long max_pass_samples = 50'000'000;  // passes x samples along a pass (InputError beyond)
  CrossSectionOptions cross_section;
};

struct PlannedContact {
  SurfacePoint at;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
};

struct PlannedPass {
  int face = -1;        // iso-parametric: the face; plane: -1
  double level = 0;     // fixed v (along u), u (along v), or plane offset [mm]
  std::vector<PlannedContact> points;
};

struct ContactPlan {
  PassDirectionSpec direction;
  std::vector<PlannedPass> passes;
  std::size_t points = 0;
  int capped_searches = 0;     // forward-step searches that hit their cap
  int evaluations = 0;         // step-error evaluations
};

// Throws InputError for non-positive tolerance or scallop, a part with no
// machinable area in that direction, or more passes than max_passes.
// `progress(done, total)` counts passes planned.
ContactPlan plan_contact_points(const Part& part, const Cutter& cutter, const PassDirectionSpec& direction,
                                const ContactPlanOptions& options = {},
                                const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace furrow
