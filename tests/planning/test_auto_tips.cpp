// Tips chosen by the planner (`--tips auto`, docs/cmm.md "Tips chosen by the
// planner") on an analytic undercut: a top face z = 10 and a wall below its
// -x edge that leans out over its foot by 15 degrees (normal 15 degrees
// below horizontal, towards -x). On a head grid of A 0/45/90 and B
// -90/0/90/180 with --max-tilt 50, only A90B0 (the stylus pointing +x, its
// axis 15 degrees off the wall's normal) is within the tilt limit of the
// wall: A0 is 105 degrees off, A45B0 60, every other B at least 90. So the
// optimal tip set is known by construction: the vertical tip (forced: it
// measures the alignment, and takes the top face) and A90B0.
// Checked: with --tips auto every region holds its minimum with exactly
// those tips, A90B0 listed as new; with only A0B0 qualified the wall gets
// nothing; every planned point's tip is clear of the part by a brute-force
// sweep of the probe's capsules against dense samples of both faces
// (support/capsule_oracle.hpp, independent of the planner's sphere tracing).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/cmm/probe_head.hpp"
#include "plan_fixtures.hpp"
#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"
#include "planning/tip_grid.hpp"
#include "support/capsule_oracle.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kHeight = 10, kWidth = 20, kTopTo = 20;
const double kLean = std::tan(15 * 3.14159265358979323846 / 180);  // x per z of the overhang

Part undercut_part() { return test::undercut_part(kHeight, kWidth, kTopTo, 15); }

std::vector<Eigen::Vector3d> undercut_samples(double h) {
  std::vector<Eigen::Vector3d> s;
  const double top_x = -kHeight * kLean;
  const int ny = static_cast<int>(std::ceil(kWidth / h));
  const int nx = static_cast<int>(std::ceil((kTopTo - top_x) / h));
  const int nz = static_cast<int>(std::ceil(kHeight / std::cos(15 * 3.14159265358979323846 / 180) / h));
  for (int j = 0; j <= ny; ++j) {
    const double y = kWidth * j / ny;
    for (int i = 0; i <= nx; ++i) s.emplace_back(top_x + (kTopTo - top_x) * i / nx, y, kHeight);
    for (int k = 0; k <= nz; ++k) {
      const double z = kHeight * k / nz;
      s.emplace_back(-z * kLean, y, z);
    }
  }
  return s;
}

const char* kGrid = R"({
  "head": {"type": "test", "a": {"min": 0, "max": 90, "step": 45}, "b": {"min": -90, "max": 180, "step": 90},
           "length": 30, "diameter": 24},
  "stylus": {"length": 20, "ball_diameter": 2, "stem_diameter": 1},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": QUALIFIED
})";
const OracleHead kOracleHead{1, 0.5, 20, 25, 6.6, 30, 12};

ProbeHead head_with(const std::string& qualified) {
  std::string text = kGrid;
  text.replace(text.find("QUALIFIED"), 9, qualified);
  return parse_probe_head(text, "head.json");
}

PlannerOptions options(const std::string& qualified, TipChoice choice) {
  PlannerOptions o;
  use_head(o, head_with(qualified));
  o.tips = choice;
  o.max_tilt_degrees = 50;
  o.points = 40;
  o.min_per_region = 4;
  return o;
}

struct Fixture {
  Part part = undercut_part();
  RegionMap map = partition_of(part, 60, 60);
};
const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// Smallest sampled clearance of the assembly of every planned point along
// its touch and both vertical legs, with the tip it is planned for.
double brute_clearance(const PlanResult& r, const std::vector<Eigen::Vector3d>& samples) {
  double worst = std::numeric_limits<double>::infinity();
  for (const PlannedPoint& p : r.plan.points) {
    REQUIRE(p.tip);
    const std::vector<OracleCapsule> all = oracle_capsules(kOracleHead, p.tip->a, p.tip->b);
    const std::vector<OracleCapsule> rest(all.begin() + 1, all.end());
    const Eigen::Vector3d c = p.xyz + p.ijk;
    const Eigen::Vector3d out = p.xyz + (1 + std::max(r.approach, r.retract)) * p.ijk;
    worst = std::min(worst, swept_clearance(samples, rest, c, out));
    for (const Eigen::Vector3d& q : {p.approach, p.retract})
      worst = std::min(worst, swept_clearance(samples, all, q, Eigen::Vector3d(q.x(), q.y(), std::max(q.z(), r.clearance_z))));
  }
  return worst;
}

}  // namespace

TEST_CASE("tip grid: each direction once, qualified names kept, the vertical one first") {
  const ProbeHead h = head_with(R"([{"a": 90, "b": -90}, {"a": 0, "b": 90}])");
  const std::vector<TipAngles> grid = tip_grid(h);
  // A0 (one direction for every B), A45 and A90 at four B each.
  REQUIRE(grid.size() == 9);
  CHECK(tip_grid_size(h) == 12);
  CHECK((grid[0] == TipAngles{0, 90}));  // the qualified name of the vertical tip
  REQUIRE(vertical_orientation(grid));
  CHECK(*vertical_orientation(grid) == 0);
  std::set<std::string> names;
  for (const TipAngles& t : grid) names.insert(tip_name(t));
  CHECK(names.size() == 9);
  CHECK(names.count("A90BM90"));
  // B -180 and 180 are one direction: a full-turn B grid gives 4, not 5.
  ProbeHead turn = h;
  turn.b = {-180, 180, 90};
  CHECK(tip_grid(turn).size() == 1 + 2 * 4);
}

TEST_CASE("tips auto: the undercut is covered with A90B0 added, and not with only A0B0 qualified") {
  const Fixture& f = fixture();
  const PlannerOptions fixed = options(R"([{"a": 0, "b": 0}])", TipChoice::qualified);
  const PlannerOptions chosen = options(R"([{"a": 0, "b": 0}])", TipChoice::automatic);
  const PlanResult q = plan_probe_points(f.part, f.map, fixed);
  const PlanResult a = plan_probe_points(f.part, f.map, chosen);
  const PlanCoverage cq = plan_coverage(q, fixed.min_per_region);
  const PlanCoverage ca = plan_coverage(a, chosen.min_per_region);

  // Which regions lie on the overhang.
  std::set<int> wall_regions;
  for (const Region& r : f.map.regions)
    if (r.face == 1) wall_regions.insert(r.id);
  REQUIRE(!wall_regions.empty());
  for (const RegionCoverage& r : cq.regions) {
    CAPTURE(r.region);
    if (wall_regions.count(r.region)) CHECK(r.planned == 0);
  }
  CHECK(!cq.complete());
  for (const RegionCoverage& r : ca.regions) {
    CAPTURE(r.region);
    CAPTURE(r.reason);
    CHECK(r.planned >= chosen.min_per_region);
  }
  CHECK(ca.complete());

  // The known optimum: the vertical tip (qualified) and A90B0 (new), in
  // the order used; the wall's points all with A90B0.
  REQUIRE(a.plan.tips.size() == 2);
  CHECK((a.plan.tips[0] == PlanTip{{0, 0}, true}));
  CHECK((a.plan.tips[1] == PlanTip{{90, 0}, false}));
  for (const PlannedPoint& p : a.plan.points) {
    REQUIRE(p.tip);
    if (p.face_index == 1) CHECK((*p.tip == TipAngles{90, 0}));
  }
  CHECK(a.tip_changes == 1);
  const TipChoiceSummary& t = a.tip_choice;
  CHECK(t.automatic);
  CHECK(t.orientations == 9);
  CHECK(t.cover.fresh == 1);
  // A small instance: every pair within the tilt limit checked, exact search.
  CHECK(t.cover.exact);
  CHECK(t.cover.optimal);
  CHECK(t.cover.tests == t.pairs);

  // Brute force: every planned point clear with its tip.
  const double h = 0.25;
  const double worst = brute_clearance(a, undercut_samples(h));
  CHECK(worst >= -(h * h / 2 + 1e-6));
  MESSAGE("tips auto on the undercut: " << a.plan.points.size() << " points, " << t.pairs << " pairs, smallest sampled clearance "
                                         << worst << " mm");
}

TEST_CASE("tips auto: an empty qualified list works, and the greedy path gives the same tips") {
  const Fixture& f = fixture();
  PlannerOptions o = options("[]", TipChoice::automatic);
  const PlanResult exact = plan_probe_points(f.part, f.map, o);
  o.tip_cover.exact_max_pairs = 0;  // force the greedy
  const PlanResult greedy = plan_probe_points(f.part, f.map, o);
  CHECK(!greedy.tip_choice.cover.exact);
  CHECK(greedy.tip_choice.cover.tests <= greedy.tip_choice.pairs);
  for (const PlanResult* r : {&exact, &greedy}) {
    REQUIRE(r->plan.tips.size() == 2);
    CHECK((r->plan.tips[0] == PlanTip{{0, 0}, false}));  // nothing is qualified: both new
    CHECK((r->plan.tips[1] == PlanTip{{90, 0}, false}));
    CHECK(plan_coverage(*r, o.min_per_region).complete());
  }
  // Without --tips auto an empty list is refused.
  PlannerOptions refused = options("[]", TipChoice::qualified);
  CHECK_THROWS_WITH_AS(validate(refused), doctest::Contains("--tips auto"), InputError);
}

TEST_CASE("tips auto: the split access checks agree with check_access on every grid tip") {
  const Fixture& f = fixture();
  const ClosestPointFinder finder(f.part);
  const ProbeHead h = head_with("[]");
  PlannerOptions o = options("[]", TipChoice::automatic);
  AccessOptions access;
  access.max_tilt = 50 * 3.14159265358979323846 / 180;
  access.clearance_z = 60;
  const ProbeGeometry base = planner_probe(o);
  int agree = 0, reach = 0;
  for (double z : {1.0, 4.0, 7.0, 9.5}) {
    for (const double side : {0.0, 1.0}) {
      Eigen::Vector3d p, n;
      if (side == 0) {
        p = {-z * kLean, 10, z};
        n = Eigen::Vector3d(-1, 0, -kLean).normalized();
      } else {
        p = {z, 10, kHeight};
        n = Eigen::Vector3d::UnitZ();
      }
      for (const TipAngles& t : tip_grid(h)) {
        ProbeGeometry g = base;
        g.axis = -tip_direction(t);
        const bool whole = check_access(finder, p, n, g, access).ok();
        const bool split = check_point_access(finder, p, n, g, access).ok() && check_axis_access(finder, p, n, g, access).ok();
        CAPTURE(tip_name(t));
        CHECK(whole == split);
        agree += whole == split;
        reach += whole;
      }
    }
  }
  CHECK(reach > 0);
  MESSAGE(agree << " pairs agree, " << reach << " reachable");
}

TEST_CASE("tips auto: the cover over the split checks picks what the plain greedy over check_access picks") {
  // A floor and a wall facing -x (plan_fixtures.hpp); points on the floor
  // and up the wall, the lowest ones where the probe body of every tip
  // within 20 degrees of the wall's normal hits the floor: no orientation
  // reaches them. The fast path, as choose_auto_tips runs it: the ball
  // checks once per point, then the axis checks per orientation within the
  // tilt limit, tested by the greedy in batches, most tilted first, with
  // early stops. Oracle: check_access on every point and every orientation
  // of the grid, and the plain greedy over that relation (written here).
  const Part part = floor_and_wall(-40, 15, 25);
  const ClosestPointFinder finder(part);
  ProbeHead h = head_with("[]");
  h.a = {0, 90, 15};
  h.b = {-180, 180, 45};
  PlannerOptions o = options("[]", TipChoice::automatic);
  use_head(o, h);
  ProbeGeometry base = planner_probe(o);
  AccessOptions access;
  access.max_tilt = 20 * 3.14159265358979323846 / 180;
  access.clearance_z = 60;
  std::vector<Eigen::Vector3d> points, normals;
  for (double y : {-6.0, 0.0, 6.0}) {
    for (double x : {-30.0, -15.0, -4.0, 2.0}) points.emplace_back(x, y, 0), normals.emplace_back(Eigen::Vector3d::UnitZ());
    for (double z : {1.2, 1.6, 3.0, 6.0, 10.0, 15.0, 20.0})
      points.emplace_back(5, y, z), normals.emplace_back(-Eigen::Vector3d::UnitX());
  }
  const std::vector<TipAngles> grid = tip_grid(h);
  std::vector<ProbeGeometry> probes(grid.size(), base);
  for (std::size_t t = 0; t < grid.size(); ++t) probes[t].axis = -tip_direction(grid[t]);
  const int n = static_cast<int>(points.size()), sets = static_cast<int>(grid.size());

  // The oracle relation and cover.
  std::vector<std::set<int>> covers(grid.size());
  for (int t = 0; t < sets; ++t)
    for (int k = 0; k < n; ++k)
      if (check_access(finder, points[static_cast<std::size_t>(k)], normals[static_cast<std::size_t>(k)],
                       probes[static_cast<std::size_t>(t)], access).ok())
        covers[static_cast<std::size_t>(t)].insert(k);
  std::set<int> coverable;
  for (const std::set<int>& c : covers) coverable.insert(c.begin(), c.end());
  const std::size_t vertical = *vertical_orientation(grid);
  std::vector<char> covered(static_cast<std::size_t>(n), 0);
  std::vector<int> oracle = {static_cast<int>(vertical)};
  for (int k : covers[vertical]) covered[static_cast<std::size_t>(k)] = 1;
  for (;;) {
    int best = -1, best_gain = 0;
    for (int t = 0; t < sets; ++t) {
      int g = 0;
      for (int k : covers[static_cast<std::size_t>(t)]) g += !covered[static_cast<std::size_t>(k)];
      if (g > best_gain) best = t, best_gain = g;
    }
    if (best < 0) break;
    oracle.push_back(best);
    for (int k : covers[static_cast<std::size_t>(best)]) covered[static_cast<std::size_t>(k)] = 1;
  }
  for (std::size_t j = oracle.size(); j-- > 1;) {
    std::set<int> others;
    for (std::size_t i = 0; i < oracle.size(); ++i)
      if (i != j) others.insert(covers[static_cast<std::size_t>(oracle[i])].begin(), covers[static_cast<std::size_t>(oracle[i])].end());
    bool needed = false;
    for (int k : covers[static_cast<std::size_t>(oracle[j])]) needed = needed || !others.count(k);
    if (!needed) oracle.erase(oracle.begin() + static_cast<long>(j));
  }
  std::sort(oracle.begin(), oracle.end());

  // The fast path.
  TipCoverProblem problem;
  problem.elements = n;
  problem.maybe.resize(grid.size());
  for (int t = 0; t < sets; ++t) {
    problem.kinds.push_back(static_cast<std::size_t>(t) == vertical ? TipKind::forced : TipKind::fresh);
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d& p = points[static_cast<std::size_t>(k)];
      const Eigen::Vector3d& nk = normals[static_cast<std::size_t>(k)];
      const double tilt = std::acos(std::clamp(nk.dot(probes[static_cast<std::size_t>(t)].axis), -1.0, 1.0));
      if (tilt <= access.max_tilt && check_point_access(finder, p, nk, base, access).ok())
        problem.maybe[static_cast<std::size_t>(t)].push_back(k);
    }
    const std::vector<int>& m = problem.maybe[static_cast<std::size_t>(t)];
    std::vector<int> order(m.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      const Eigen::Vector3d& axis = probes[static_cast<std::size_t>(t)].axis;
      return normals[static_cast<std::size_t>(m[static_cast<std::size_t>(a)])].dot(axis) <
             normals[static_cast<std::size_t>(m[static_cast<std::size_t>(b)])].dot(axis);
    });
    problem.test_order.push_back(order);
  }
  problem.test = [&](int t, const std::vector<int>& list) {
    std::vector<char> out;
    for (int k : list)
      out.push_back(check_axis_access(finder, points[static_cast<std::size_t>(k)], normals[static_cast<std::size_t>(k)],
                                      probes[static_cast<std::size_t>(t)], access).ok());
    return out;
  };
  TipCoverOptions greedy_only;
  greedy_only.exact_max_pairs = -1;
  greedy_only.test_batch = 2;
  const TipCover cover = solve_tip_cover(problem, greedy_only);
  CHECK(cover.chosen == oracle);
  std::vector<int> unreachable;
  for (int k = 0; k < n; ++k)
    if (!coverable.count(k)) unreachable.push_back(k);
  CHECK(cover.uncoverable == unreachable);
  REQUIRE(!unreachable.empty());                             // some points no orientation reaches
  REQUIRE(unreachable.size() < static_cast<std::size_t>(n));  // and some it does
  // Every pair the fast path tested agrees with the whole check.
  long pairs = 0;
  for (int t = 0; t < sets; ++t) {
    const std::vector<int>& m = problem.maybe[static_cast<std::size_t>(t)];
    pairs += static_cast<long>(m.size());
    for (std::size_t i = 0; i < m.size(); ++i)
      if (cover.known[static_cast<std::size_t>(t)][i] >= 0)
        CHECK((cover.known[static_cast<std::size_t>(t)][i] == 1) == (covers[static_cast<std::size_t>(t)].count(m[i]) == 1));
  }
  MESSAGE(n << " points, " << unreachable.size() << " unreachable, " << oracle.size() << " tips; " << cover.tests << " of "
            << pairs << " pairs tested");
}
