#pragma once
// Brute-force collision oracle for a planned setup with the vertical stylus
// (docs/cmm.md "Setups"): the ball and shaft built here from the planner's
// options, swept along each point's touch and both vertical legs, against
// dense samples of the part's surface given in the part frame and taken to
// the setup's frame with plan.json's own transform. Independent of the
// planner's sphere tracing: it only uses the exact distance from a sample
// to a capsule's swept axis (capsule_oracle.hpp).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <doctest/doctest.h>

#include "stage/plan_stage.hpp"
#include "support/capsule_oracle.hpp"

namespace furrow::test {

// The smallest sampled clearance of the stylus from the part over every
// point's moves (negative: a sample inside the ball or shaft), and the
// lowest point the ball reaches over those moves (setup frame, z up).
struct SetupClearance {
  double part = std::numeric_limits<double>::infinity();
  double lowest = std::numeric_limits<double>::infinity();
};

inline SetupClearance vertical_stylus_clearance(const SetupPlan& s, const PlannerOptions& o,
                                                std::vector<Eigen::Vector3d> samples) {
  REQUIRE(s.result.plan.setup);
  const PlanSetupRecord& rec = *s.result.plan.setup;
  for (Eigen::Vector3d& q : samples) q = rec.rotation * q + rec.translation;
  const double r = o.probe_diameter / 2, rs = o.stylus_diameter / 2;
  const double leave = std::sqrt(r * r - rs * rs);  // where the shaft leaves the ball
  const std::vector<OracleCapsule> stylus = {{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), r},
                                             {Eigen::Vector3d(0, 0, leave), Eigen::Vector3d(0, 0, o.stylus_length), rs}};
  const std::vector<OracleCapsule> ball_only(stylus.begin(), stylus.begin() + 1);
  const std::vector<OracleCapsule> shaft(stylus.begin() + 1, stylus.end());
  const double clearance_z = s.result.clearance_z;
  SetupClearance c;
  for (const PlannedPoint& p : s.result.plan.points) {
    const Eigen::Vector3d centre = p.xyz + r * p.ijk;
    // The ball touches at p: along the touch the ball is checked from
    // 0.01 mm off the contact, the shaft all the way.
    const Eigen::Vector3d out = p.xyz + (r + std::max(s.result.approach, s.result.retract)) * p.ijk;
    c.part = std::min(c.part, swept_clearance(samples, ball_only, centre + 0.01 * p.ijk, out));
    c.part = std::min(c.part, swept_clearance(samples, shaft, centre, out));
    for (const Eigen::Vector3d& q : {p.approach, p.retract}) {
      const Eigen::Vector3d top(q.x(), q.y(), std::max(q.z(), clearance_z));
      c.part = std::min(c.part, swept_clearance(samples, stylus, q, top));
      c.lowest = std::min({c.lowest, q.z() - r, centre.z() - r});
    }
  }
  return c;
}

}  // namespace furrow::test
