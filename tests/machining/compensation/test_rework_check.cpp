// The rework program's check (machining/compensation/rework_check.hpp) on
// straight passes over a flat floor, where the z-map heights are known
// exactly: a 3 mm ball cutting along x at height z leaves z at every node
// of its track, so a rework deeper than the full program by d exceeds it
// by d less the tolerance, and a rapid whose tip goes down to z_r over a
// floor at z_f cuts z_f - z_r into it.
#include <doctest/doctest.h>

#include <cmath>

#include "machining/compensation/rework_check.hpp"

using namespace furrow;

namespace {

constexpr double kTol = 1e-3;  // [mm]

Toolpath one_pass(double x0, double x1, double z, double clearance) {
  Toolpath path;
  ToolpathPass pass;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(x0, 0, clearance), Eigen::Vector3d(x0, 0, z),
                                   Eigen::Vector3d(x1, 0, z)}) {
    ToolpathPoint q;
    q.position = p;
    q.feed = 1000;
    pass.points.push_back(q);
  }
  path.passes.push_back(pass);
  return path;
}

RapidMove rapid(const Eigen::Vector3d& from, const Eigen::Vector3d& to, int line) {
  RapidMove r;
  r.known = true;
  r.from = from;
  r.to = to;
  r.line = line;
  return r;
}

}  // namespace

TEST_CASE("rework check: a rework on the full program's track passes, one deeper by 50 um fails by 50 um less the tolerance") {
  const Cutter ball("ball", 3, 3);
  const double clearance = 10;
  const Toolpath original = one_pass(0, 20, 0, clearance);
  const Toolpath full = one_pass(0, 20, -0.05, clearance);
  Toolpath rework = one_pass(5, 10, -0.05, clearance);
  rework.rapids.push_back(rapid({10, 0, -0.05}, {10, 0, clearance}, 7));
  const ReworkCheck ok = check_rework(ball, original, full, rework, clearance, kTol);
  CHECK(ok.nodes > 100);
  CHECK(ok.deeper == 0);
  CHECK(ok.rapids == 1);
  CHECK(ok.rapid_nodes_cut == 0);  // the retract rises from a cut the rework made
  CHECK(ok.safe());

  const Toolpath deeper = one_pass(5, 10, -0.1, clearance);
  const ReworkCheck bad = check_rework(ball, original, full, deeper, clearance, kTol);
  CHECK(bad.deeper > 0);
  CHECK(!bad.safe());
  CHECK(std::abs(bad.worst_excess - (0.05 - kTol)) < 1e-9);
}

TEST_CASE("rework check: a rapid into the machined floor or below the clearance over uncut ground is found, with its depth and line") {
  const Cutter ball("ball", 3, 3);
  const double clearance = 10;
  const Toolpath original = one_pass(0, 20, 0, clearance);
  const Toolpath full = one_pass(0, 20, -0.05, clearance);
  Toolpath rework = one_pass(5, 10, -0.05, clearance);
  // Down to z = -1 at x = 15, where the floor is the original's (0).
  rework.rapids.push_back(rapid({10, 0, clearance}, {15, 0, -1}, 12));
  const ReworkCheck into_floor = check_rework(ball, original, full, rework, clearance, kTol);
  CHECK(into_floor.rapid_nodes_cut > 0);
  CHECK(!into_floor.safe());
  CHECK(into_floor.worst_rapid_line == 12);
  CHECK(std::abs(into_floor.worst_rapid_depth - (1 - kTol)) < 1e-9);

  // Over ground no program cut, 5 mm below the clearance: judged against it.
  rework.rapids.back() = rapid({40, 30, 5}, {60, 30, 5}, 13);
  const ReworkCheck uncut = check_rework(ball, original, full, rework, clearance, kTol);
  CHECK(uncut.rapid_nodes_cut > 0);
  CHECK(std::abs(uncut.worst_rapid_depth - (5 - kTol)) < 1e-9);
  // At the clearance height: nothing.
  rework.rapids.back() = rapid({40, 30, clearance}, {60, 30, clearance}, 13);
  CHECK(check_rework(ball, original, full, rework, clearance, kTol).safe());
  // From an unknown position: counted, not judged.
  rework.rapids.back().known = false;
  const ReworkCheck unknown = check_rework(ball, original, full, rework, clearance, kTol);
  CHECK(unknown.rapids_unchecked == 1);
  CHECK(unknown.safe());
}
