#pragma once
// CMM inspection plans: plan.json (docs/architecture.md "Files", docs/formats.md "Plan").
//
// A plan is what the probe planner decided and what every later step refers
// back to: for each point its id (also the DMIS label), execution order,
// face, (u,v), nominal contact point xyz and unit normal ijk (out of the
// material; the probe touches moving along -ijk), the probe-centre positions
// where the touch move starts (approach) and where the probe backs off to
// (retract), and the region of the partition it samples. The probe is part
// of the plan because centres and contacts differ by its radius.
//
// Lengths are millimetres inside; a file may say "units": "inch" (xyz,
// approach, retract, probe diameter are converted; u, v, ijk are unit-free).
// The writer always writes millimetres with shortest exact numbers, so
// read(write(plan)) reproduces the plan bit for bit.
//
// Errors: InputError naming the file and field ("plan.json: points[4].ijk:
// zero length"), duplicate ids or orders, and - when checked against a part -
// a face index or name that does not match the part.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/part.hpp"
#include "io/plan_alignment.hpp"
#include "io/plan_point.hpp"

namespace furrow {

// A region of the partition the planner could not give its minimum number
// of points (docs/cmm.md "Coverage"). Kept in the plan so that a comparison
// made with it cannot call the part good over a region nobody measured.
struct UncoveredRegion {
  int region = 0;
  std::size_t face_index = 0;
  int planned = 0;   // points the plan holds in the region
  int required = 0;  // the plan's minimum per region, > planned
  std::string reason;
};

// The setup a plan is for (docs/cmm.md "Setups"): setup 1 is the part as
// imported; in a further one the part rests on `resting_face`, and every
// position in the plan (points, approach, retract, alignment) and in its
// CMM programs is in the setup frame: x_setup = rotation x_part + translation.
struct PlanSetupRecord {
  int index = 1;                           // >= 1
  std::optional<std::size_t> resting_face;  // face index; none in setup 1
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // proper rotation
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   // [mm]
  // A part-frame position of a setup-frame one.
  Eigen::Vector3d to_part(const Eigen::Vector3d& x) const { return rotation.transpose() * (x - translation); }
};

struct InspectionPlan {
  std::string part;  // part file the plan was made for (informative, may be empty)
  ProbeDefinition probe;
  std::vector<PlannedPoint> points;
  std::vector<UncoveredRegion> uncovered_regions;  // optional in plan.json
  // How the part is aligned before the points are measured; absent in plans
  // of older versions and in re-measuring plans (run on the first one's
  // alignment).
  std::optional<PartAlignment> alignment;
  // With an indexable head: the tips in the order the program selects them
  // (optional in plan.json; empty for the vertical stylus).
  std::vector<PlanTip> tips;
  // Plans of `furrow plan --setups`: which setup (optional in plan.json).
  std::optional<PlanSetupRecord> setup;

  // Index of the point with that id, or nullopt (linear search).
  std::optional<std::size_t> find(const std::string& id) const;
  // id -> index of every point, for matching many ids.
  std::unordered_map<std::string, std::size_t> index_by_id() const;
};

InspectionPlan read_plan(const std::string& path);
// `name` stands for the source in messages.
InspectionPlan parse_plan(const std::string& text, const std::string& name);
std::string plan_to_json_text(const InspectionPlan& plan);
void write_plan(const InspectionPlan& plan, const std::string& path);

// Throws InputError (naming `name` and the point) when a point's face index
// is out of range or its face name differs from the part's face, or when its
// xyz is farther than `tolerance` [mm] from the face point at (u,v): a plan
// made for another part, or an edited one. A plan of a further setup is
// checked with its positions taken back to the part frame.
void check_plan_against_part(const InspectionPlan& plan, const Part& part, const std::string& name,
                             double tolerance = 1e-6);

}  // namespace furrow
