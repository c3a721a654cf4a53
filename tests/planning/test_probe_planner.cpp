// The planner end to end (library): every point on the surface, in its
// region and trim, clear of the region's edges, accessible; counts per
// region as allocated; the same seed the same plan byte for byte; the groove
// narrower than the ball; predicted risk and gouge sites; refused options.
#include <doctest/doctest.h>

#include <cmath>
#include <map>

#include "base/error.hpp"
#include "io/plan_file.hpp"
#include "planning/prediction_risk.hpp"
#include "planning/probe_planner.hpp"
#include "plan_fixtures.hpp"
#include "prediction_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

class SiteRisk : public RiskMap {
 public:
  SiteRisk(Eigen::Vector2d centre, double width, std::vector<RiskSite> sites)
      : centre_(centre), width_(width), sites_(std::move(sites)) {}
  double error_magnitude(int, const Eigen::Vector2d& uv) const override {
    return 0.04 * std::exp(-(uv - centre_).squaredNorm() / (width_ * width_));
  }
  const std::vector<RiskSite>& gouge_sites() const override { return sites_; }

 private:
  Eigen::Vector2d centre_;
  double width_;
  std::vector<RiskSite> sites_;
};

const Part& mould_part() {
  static const Part part = mould();
  return part;
}

const RegionMap& mould_map() {
  static const RegionMap map = partition_of(mould_part(), 200, 160);
  return map;
}

}  // namespace

TEST_CASE("mould plan: every point on the surface, in its region and trim, clear of the edges, accessible") {
  const Part& part = mould_part();
  const RegionMap& map = mould_map();
  PlannerOptions o;
  o.points = 300;
  const PlanResult r = plan_probe_points(part, map, o);
  const ClosestPointFinder finder(part);
  REQUIRE(r.plan.points.size() == 300);  // nothing dropped on the mould with a 2 mm probe
  CHECK(r.border == doctest::Approx(2.0));
  std::map<int, int> per_region;
  for (std::size_t k = 0; k < r.plan.points.size(); ++k) {
    const PlannedPoint& p = r.plan.points[k];
    const Face& face = part.faces[p.face_index];
    CHECK(p.order == static_cast<int>(k) + 1);
    CHECK((face.surface().point(p.uv.x(), p.uv.y()) - p.xyz).norm() <= 1e-9);
    CHECK(face.contains(p.uv.x(), p.uv.y()));
    REQUIRE(p.region.has_value());
    CHECK(map.region_at(static_cast<int>(p.face_index), p.uv.x(), p.uv.y()) == p.region);
    CHECK(brute_edge_distance(part, map, *p.region, p.xyz) >= r.border);
    const Eigen::Vector3d n = face.geometry(p.uv.x(), p.uv.y()).normal;
    CHECK((p.ijk - n).norm() <= 1e-12);
    CHECK((p.approach - (p.xyz + (1 + 3) * n)).norm() <= 1e-12);
    CHECK((p.retract - (p.xyz + (1 + 3) * n)).norm() <= 1e-12);
    CHECK(check_access(finder, p.xyz, p.ijk, r.probe, [&] {
            AccessOptions a;
            a.clearance_z = r.clearance_z;
            return a;
          }()).ok());
    ++per_region[*p.region];
  }
  long total = 0;
  for (const RegionPlanSummary& s : r.regions) {
    CHECK(per_region[s.region] == s.planned);
    CHECK(s.planned == s.allocated - s.dropped);
    CHECK(s.allocated >= o.min_per_region);
    total += s.allocated;
  }
  CHECK(total == 300);
  check_plan_against_part(r.plan, part, "plan", 1e-9);
}

TEST_CASE("straight moves keep the clearance, the others go over the clearance plane") {
  PlannerOptions o;
  o.points = 120;
  const PlanResult r = plan_probe_points(mould_part(), mould_map(), o);
  const ClosestPointFinder finder(mould_part());
  for (std::size_t k = 1; k < r.moves.size(); ++k) {
    const Move& m = r.moves[k];
    const Eigen::Vector3d a = r.plan.points[k - 1].retract, b = r.plan.points[k].approach;
    CHECK(m.waypoints.back() == b);
    if (!m.straight) {
      CHECK(m.waypoints[0].z() >= r.clearance_z);
      continue;
    }
    // Brute force: 200 samples along the segment keep ball + clearance free.
    for (int s = 0; s <= 200; ++s) {
      const Eigen::Vector3d q = a + (b - a) * (s / 200.0);
      CHECK(finder.project(q).distance >= r.probe.ball_radius + o.clearance - 1e-6);
    }
  }
}

TEST_CASE("the same seed gives the same plan byte for byte, another seed another plan") {
  PlannerOptions o;
  o.points = 150;
  o.seed = 42;
  const std::string a = plan_to_json_text(plan_probe_points(mould_part(), mould_map(), o).plan);
  const std::string b = plan_to_json_text(plan_probe_points(mould_part(), mould_map(), o).plan);
  CHECK(a == b);
  o.seed = 43;
  CHECK(plan_to_json_text(plan_probe_points(mould_part(), mould_map(), o).plan) != a);
}

TEST_CASE("points at the bottom of a groove narrower than the ball are dropped with the reason") {
  const Part part = groove_part(1.0);  // groove radius 1 mm
  const RegionMap map = partition_of(part, 60, 60);
  PlannerOptions o;
  o.probe_diameter = 4;  // ball radius 2 > groove radius
  o.stylus_diameter = 2;
  o.border = 0.2;
  o.min_per_region = 5;
  o.points = 60;
  const PlanResult r = plan_probe_points(part, map, o);
  int groove_dropped = 0;
  for (const PlanIssue& i : r.issues) {
    if (i.kind != PlanIssue::Kind::dropped) continue;
    CHECK(!i.reason.empty());
    if (map.regions[static_cast<std::size_t>(i.region)].face == 1) {
      ++groove_dropped;
      CHECK((i.problem == AccessProblem::ball || i.problem == AccessProblem::tilt));
      CHECK(i.reason.find(i.problem == AccessProblem::ball ? "ball" : "tilt") != std::string::npos);
    }
  }
  CHECK(groove_dropped >= 5);
  for (const PlannedPoint& p : r.plan.points) CHECK(p.face_index != 1);  // no point left in the groove
  // A ball that fits (radius 0.5 < 1) measures the groove's bottom.
  o.probe_diameter = 1;
  o.stylus_diameter = 0.5;
  const PlanResult fits = plan_probe_points(part, map, o);
  int in_groove = 0;
  for (const PlannedPoint& p : fits.plan.points) in_groove += p.face_index == 1 && p.ijk.z() > 0.9;
  CHECK(in_groove >= 1);
}

TEST_CASE("predicted risk draws points to a region, every gouge site gets points on it") {
  const Part& part = mould_part();
  const RegionMap& map = mould_map();
  PlannerOptions o;
  o.points = 200;
  const PlanResult plain = plan_probe_points(part, map, o);
  // Risk around the planar corner region 4's interior point; a gouge site in region 2.
  const Region& corner = map.regions[4];
  const Region& dome = map.regions[2];
  RiskSite site;
  site.id = "G1";
  site.face = 0;
  site.uv_centre = dome.interior_uv;
  site.uv_box = Eigen::AlignedBox2d(dome.interior_uv - Eigen::Vector2d(0.02, 0.02), dome.interior_uv + Eigen::Vector2d(0.02, 0.02));
  site.depth = 0.03;
  const SiteRisk risk(corner.interior_uv, 0.08, {site});
  o.gouge_points = 3;
  const PlanResult risky = plan_probe_points(part, map, o, &risk);
  CHECK(risky.regions[4].allocated > plain.regions[4].allocated);
  CHECK(risky.regions[2].gouge_points == 3);
  int on_site = 0;
  for (std::size_t k = 0; k < risky.plan.points.size(); ++k)
    if (risky.point_sites[k] == "G1") {
      ++on_site;
      CHECK(site.uv_box.contains(risky.plan.points[k].uv));
    }
  CHECK(on_site == 3);
  for (const PlanIssue& i : risky.issues) CHECK(i.kind != PlanIssue::Kind::gouge_site);
  // The risk strategy needs a risk map.
  o.strategy = SamplingStrategy::risk;
  CHECK_THROWS_AS(plan_probe_points(part, map, o), InputError);
  CHECK(plan_probe_points(part, map, o, &risk).plan.points.size() == 200);
}

TEST_CASE("refused options and impossible plans") {
  const Part& part = mould_part();
  const RegionMap& map = mould_map();
  auto refused = [&](PlannerOptions o) { CHECK_THROWS_AS(plan_probe_points(part, map, o), InputError); };
  PlannerOptions o;
  o.points = 0;
  refused(o);
  o = {};
  o.probe_diameter = -2;
  refused(o);
  o = {};
  o.stylus_diameter = 3;  // thicker than the 2 mm ball
  refused(o);
  o = {};
  o.points = 10;
  o.density = 1;
  refused(o);
  o = {};
  o.max_tilt_degrees = 0;
  refused(o);
  o = {};
  o.border = 60;  // no region is 120 mm wide
  try {
    plan_probe_points(part, map, o);
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("--border") != std::string::npos);
  }
}

TEST_CASE("a prediction's gouge sites all get a point, even next to a region border") {
  const Part& part = mould_part();
  const RegionMap& map = mould_map();
  // Sites: inside the dome, on the dome's border with the saddle band, and
  // right at the face's edge (v = 0.005: within the border clearance of the
  // part's boundary, so it cannot be measured and must be reported).
  const Region& dome = map.regions[2];
  Eigen::Vector2d on_border = dome.border[0].uv[0];
  const Prediction p = synthetic_prediction(part, dome.interior_uv, {dome.interior_uv, on_border, {0.5, 0.005}});
  const PredictionRiskMap risk(p, part, "p.json", "mould.json");
  PlannerOptions o;
  o.points = 100;
  const PlanResult r = plan_probe_points(part, map, o, &risk);
  std::map<std::string, int> points_on;
  for (std::size_t k = 0; k < r.plan.points.size(); ++k) {
    const PlannedPoint& pt = r.plan.points[k];
    if (r.point_sites[k].empty()) {
      CHECK(brute_edge_distance(part, map, *pt.region, pt.xyz) >= r.border);
      continue;
    }
    ++points_on[r.point_sites[k]];
    const RiskSite& s = risk.gouge_sites()[static_cast<std::size_t>(std::stoi(r.point_sites[k].substr(1)) - 1)];
    CHECK(s.uv_box.contains(pt.uv));
    CHECK(map.region_at(0, pt.uv.x(), pt.uv.y()) == pt.region);
    // Clear of the face's own edges (the boundary of the parameter square).
    double edge = 1e300;
    for (int k2 = 0; k2 <= 400; ++k2) {
      const double t = k2 / 400.0;
      for (const Eigen::Vector2d& uv : {Eigen::Vector2d(t, 0), Eigen::Vector2d(t, 1), Eigen::Vector2d(0, t), Eigen::Vector2d(1, t)})
        edge = std::min(edge, (part.faces[0].surface().point(uv.x(), uv.y()) - pt.xyz).norm());
    }
    CHECK(edge >= r.border);
  }
  CHECK(points_on["G1"] == 1);
  CHECK(points_on["G2"] == 1);
  CHECK(points_on.count("G3") == 0);
  int reported = 0;
  for (const PlanIssue& i : r.issues) reported += i.kind == PlanIssue::Kind::gouge_site && i.gouge_site == "G3";
  CHECK(reported == 1);
}
