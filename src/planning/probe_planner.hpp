#pragma once
// Probe planning for a part: the planner's entry point (// docs/cmm.md). From a part, its curvature partition and optionally a
// machining risk map, it decides how many points each region gets, where
// they go, which of them a vertical stylus can take, in which order, and
// how the probe travels between them.
//
//   1. regions: the admissible set of every region (region_domain.hpp:
//      inside the region and its face's trim, `border` mm from its edges);
//      a region too narrow for the default border takes the ball-contact
//      rule instead (narrow_region.hpp); a region that cannot hold a single
//      point is skipped and reported (with the largest ball that would fit);
//   2. allocation (allocation.hpp): budget from `points` or `density`,
//      weights from area, curvature spread and predicted risk, a floor of
//      `min_per_region` plus `gouge_points` per predicted gouge site;
//   3. sampling (sampling_strategy.hpp) in every region with its own seed;
//      gouge sites get their points on the site first (clear of the face's
//      edges, not necessarily of the borders between curvature regions);
//   4. accessibility (accessibility.hpp) of every point; a point that fails
//      is moved to the nearest accessible admissible point within
//      `max_move_fraction` of the region's point spacing (rings around it
//      in its tangent plane), or dropped; both are reported with the reason.
//      With an indexable head (`head`, docs/cmm.md "Indexable heads") every
//      qualified tip is checked instead; in sampling order, a point keeps
//      the tip of the point before it when that tip reaches it, else takes
//      the reaching tip whose stylus lies closest to its normal; a point no
//      tip reaches is dropped (no relocation) with the reason for the tip
//      nearest its normal;
//   5. ordering (tour.hpp) and moves (moves.hpp), cycle time. With a head,
//      one run of points per tip (tip_groups.hpp) and every tip change over
//      the clearance plane, raised so that the head can turn there.
//
// Deterministic: the same inputs and options give the same plan bit for bit
// (per-point work runs in parallel into fixed slots; every sum runs in
// order). Bad options throw InputError naming the option; a plan that ends
// up with no point throws InputError saying why. Numerical caps (sampling
// candidates, tour passes, march steps) are in the option structs and their
// effects are reported in the result.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "io/plan_file.hpp"
#include "io/cmm/probe_head.hpp"
#include "io/cmm/probe_program.hpp"
#include "partition/region_map.hpp"
#include "planning/accessibility.hpp"
#include "planning/allocation.hpp"
#include "planning/ball_contact.hpp"
#include "planning/datum_selection.hpp"
#include "planning/moves.hpp"
#include "planning/region_domain.hpp"
#include "planning/risk_map.hpp"
#include "planning/sampling_strategy.hpp"
#include "planning/tip_cover.hpp"
#include "planning/tour.hpp"

namespace furrow {

// Which tips of an indexable head the plan may use: the head file's
// qualified list as it is, or any orientation of the head's index grid,
// chosen by the planner (docs/cmm.md "Tips chosen by the planner").
enum class TipChoice { qualified, automatic };
const char* to_string(TipChoice choice);  // "qualified", "auto"
// Throws InputError naming `where` for another word.
TipChoice parse_tip_choice(const std::string& text, const std::string& where);

constexpr double kDefaultDensity = 1.0;  // points per cm^2 when neither points nor density is given

struct PlannerOptions {
  std::optional<long> points;      // total budget (>= 1); excludes density
  std::optional<double> density;   // points per cm^2 (> 0); default kDefaultDensity
  int min_per_region = 5;          // >= 0
  SamplingStrategy strategy = kDefaultSamplingStrategy;
  std::uint64_t seed = 1;
  std::optional<double> border;    // clearance from region edges on the surface [mm]; default r + 1
  // Regions too narrow for the default border take the contact rule
  // (narrow_region.hpp, docs/cmm.md "Narrow regions"); a `border` given
  // explicitly holds for every region.
  BallContactOptions contact;
  std::string probe_name = "Probe1";
  double probe_diameter = 2;       // [mm]
  double stylus_diameter = 1;      // [mm], <= probe_diameter
  double stylus_length = 20;       // ball centre to probe body [mm], > probe radius
  double approach = 3;             // [mm]
  double retract = 3;              // [mm]
  std::optional<double> search;    // past the nominal point [mm]; default = approach
  double clearance = 2;            // ball to part on straight moves [mm]
  double max_tilt_degrees = 75;    // (0, 180]
  MotionModel motion;
  int gouge_points = 1;            // points per predicted gouge site (with a risk map)
  AllocationWeights weights;
  double max_move_fraction = 0.5;  // relocation radius / region point spacing
  int relocation_rings = 6;
  int relocation_directions = 12;
  SamplingOptions sampling;
  TourOptions tour;
  RegionDomainOptions domain;      // `border` is set from the option above
  AccessOptions access;            // distances and clearance_z are set from the options above
  std::string part_name;           // recorded in plan.json (informative)
  ProgramSettings program;         // header, head length, tolerance of the CMM programs
  DatumChoice datums;              // part alignment (stage/plan_stage.hpp, datum_selection.hpp)
  // Indexable head (set with use_head); none: the fixed vertical stylus.
  // The part alignment is measured with its vertical tip A0B0.
  std::optional<ProbeHead> head;
  // With a head: use the qualified tips only, or choose among the grid's
  // orientations (then the head file's qualified list may be empty).
  TipChoice tips = TipChoice::qualified;
  TipCoverOptions tip_cover;       // limits of the exact tip choice
  // Setups (stage/plan_setups.hpp, docs/cmm.md "Setups"): how many, and the
  // faces (part face indices) the part rests on in setups 2, 3, ...; empty:
  // chosen among the largest stable planar faces. Read by the plan stage;
  // plan_probe_points plans one setup.
  int setups = 1;
  std::vector<int> setup_faces;
  // Per region id: measured in another setup, so left out of this one (no
  // points, not in its coverage). Empty: every region is planned.
  std::vector<char> planned_elsewhere;
};

// Plans with `head`: also sets the ball, stem and stylus length from it.
void use_head(PlannerOptions& options, const ProbeHead& head);

// The probe with an indexable head's assembly (sections, housing), axis +z;
// the vertical stylus of the options without one.
ProbeGeometry planner_probe(const PlannerOptions& options);

// Throws InputError naming the option for an invalid value.
void validate(const PlannerOptions& options);

// Setups: at most this many (the six faces of a box).
constexpr int kMaxSetups = 6;
// The setups a plan makes: --setups, raised to hold the named faces.
int setup_count(const PlannerOptions& options);
// "3,7" -> {3, 7}; throws InputError naming `where` for anything else (a
// negative or repeated index, an empty item).
std::vector<int> parse_face_list(const std::string& text, const std::string& where);
std::string face_list_text(const std::vector<int>& faces);

// Resolved defaults.
double border_clearance(const PlannerOptions& options);
double search_distance(const PlannerOptions& options);

struct RegionPlanSummary {
  int region = 0;
  int face = 0;
  CurvatureClass curvature_class = CurvatureClass::planar;
  double area = 0;               // regions.json [mm^2]
  double curvature_spread = 0;   // [1/mm]
  double mean_risk = 0;          // [mm]
  double weight = 0;
  bool samplable = true;
  bool contact_rule = false;     // too narrow for the border: points by the ball-contact rule
  bool elsewhere = false;        // measured in another setup (PlannerOptions::planned_elsewhere): not planned
  int allocated = 0;             // by the allocation rule
  int gouge_points = 0;          // of which reserved for gouge sites
  int sampled = 0;               // admissible points found
  int moved = 0, dropped = 0;
  int planned = 0;               // in the plan
};

struct PlanIssue {
  enum class Kind { moved, dropped, region_short, region_skipped, gouge_site, budget_raised, face_facing_down };
  Kind kind = Kind::moved;
  std::string point;            // point id (moved) or "" when the point is not in the plan
  int region = -1;
  int face = -1;                // face_facing_down: the part's face index
  std::string gouge_site;       // for points and issues of a gouge site
  AccessProblem problem = AccessProblem::none;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();  // the (original) point [mm]
  double distance = 0;          // moved by [mm]
  // region_skipped under the contact rule: the diameter of the largest ball
  // that would measure the region [mm] (0: none, or the rule was not tried).
  double largest_ball_diameter = 0;
  std::string reason;           // one sentence for people
};
const char* to_string(PlanIssue::Kind kind);

// How the tips were chosen (`--tips auto`; tip_cover.hpp).
struct TipChoiceSummary {
  bool automatic = false;
  int orientations = 0;         // distinct orientations of the head's grid
  long pairs = 0;               // point-orientation pairs within --max-tilt
  TipCover cover;               // `known` cleared
};

struct PlanTiming {
  double regions_seconds = 0, sampling_seconds = 0, access_seconds = 0, tour_seconds = 0, moves_seconds = 0;
};

struct PlanResult {
  InspectionPlan plan;             // points in execution order (order 1..n)
  // Per plan point: the id of the gouge site it was placed on, or "". Such
  // points keep the border clearance from the face's edges only
  // (RegionDomain::admissible_on_site).
  std::vector<std::string> point_sites;
  std::vector<Move> moves;         // moves[k]: into plan.points[k] (moves[0]: down from `start`)
  std::vector<Eigen::Vector3d> final_moves;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // above the first approach point, on the clearance plane
  double clearance_z = 0;
  double border = 0, search = 0;   // resolved
  double approach = 0, retract = 0;
  ProbeGeometry probe;
  std::vector<RegionPlanSummary> regions;
  std::vector<PlanIssue> issues;
  Allocation allocation;
  TourResult tour;
  int tip_changes = 0;             // with a head: tip changes between consecutive points
  // With a head: the vertical tip, which measures the part alignment (the
  // qualified one with A = 0, or the grid's when the planner chooses).
  std::optional<TipAngles> vertical_tip;
  TipChoiceSummary tip_choice;
  CycleEstimate cycle;
  PlanTiming timing;               // wall clock, not part of any output file
};

// Progress: (stage name, done, total). Calls never overlap, but during the
// parallel access checks they may come from a worker thread.
using PlanProgress = std::function<void(const char* stage, std::size_t done, std::size_t total)>;

// Precondition: `map` belongs to `part` (RegionMap::check_belongs_to).
// `risk` may be null (no prediction).
PlanResult plan_probe_points(const Part& part, const RegionMap& map, const PlannerOptions& options,
                             const RiskMap* risk = nullptr, const PlanProgress& progress = {});

// The measuring program of a plan (DMIS / I++ DME writers): the options give
// the stylus and head lengths, the speeds (motion.move_speed, touch_speed)
// and the header and tolerance (options.program). With a head: one sensor
// per tip used (the vertical one first when there is an alignment) and the
// head-to-ball length from the head.
ProbeProgram make_probe_program(const PlanResult& result, const std::string& name, const PlannerOptions& options);

// With a head: the tips a plan uses in the order the program selects them
// (the vertical one first when the plan has an alignment, else the first
// point's; then in order of first use), each marked qualified when the head
// file lists it; the operator qualifies the others before running. Empty
// without a head.
std::vector<PlanTip> tips_in_use(const PlanResult& result, const PlannerOptions& options);

}  // namespace furrow
