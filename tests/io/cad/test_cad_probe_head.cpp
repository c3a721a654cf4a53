// Planning with an indexable head on a part built with OpenCASCADE: a block
// with vertical side faces and two blind bores, imported from STEP. The
// vertical stylus cannot take the side faces and bore walls (their normals
// are 90 degrees from it); with the head every region gets its minimum, each
// point with a qualified tip, and no part of the probe assembly comes into
// the part along the touch, the vertical legs or the moves between points
// (dense samples of the part, built analytically from the same dimensions,
// against the swept capsules: support/capsule_oracle.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "io/cad/cad_import.hpp"
#include "io/cad/cad_reference.hpp"
#include "partition/partition.hpp"
#include "planning/plan_coverage.hpp"
#include "planning/probe_planner.hpp"
#include "support/capsule_oracle.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kBoxX = 60, kBoxY = 40, kBoxZ = 20;
struct Bore {
  double x, y, r, depth;
};
constexpr Bore kBores[] = {{18, 20, 9, 8}, {44, 20, 7, 6}};

TopoDS_Shape block_with_bores() {
  TopoDS_Shape block = BRepPrimAPI_MakeBox(kBoxX, kBoxY, kBoxZ).Shape();
  for (const Bore& b : kBores)
    block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(b.x, b.y, kBoxZ - b.depth), gp::DZ()), b.r,
                                                            b.depth + 5)
                                       .Shape())
                .Shape();
  return block;
}

// The part as the planner sees it: without the face it stands on (z = 0,
// facing down: no probe reaches it on the table).
Part imported_part() {
  const std::string path = scratch_dir("probe-head-block") + "/block.step";
  write_step(block_with_bores(), path);
  Part part = import_cad(path).part;
  part.faces.erase(std::remove_if(part.faces.begin(), part.faces.end(),
                                  [](const Face& f) {
                                    const ParameterDomain& d = f.domain();
                                    const DifferentialGeometry g = f.geometry((d.u0 + d.u1) / 2, (d.v0 + d.v1) / 2);
                                    return g.normal.z() < -0.99 && std::abs(g.point.z()) < 1e-6;
                                  }),
                   part.faces.end());
  return part;
}

// Samples of the whole solid's surface (bottom included) every ~h mm.
std::vector<Eigen::Vector3d> block_samples(double h) {
  std::vector<Eigen::Vector3d> s;
  auto in_bore = [](double x, double y) {
    for (const Bore& b : kBores)
      if (std::hypot(x - b.x, y - b.y) < b.r) return true;
    return false;
  };
  const int nx = static_cast<int>(std::ceil(kBoxX / h)), ny = static_cast<int>(std::ceil(kBoxY / h)),
            nz = static_cast<int>(std::ceil(kBoxZ / h));
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      const double x = kBoxX * i / nx, y = kBoxY * j / ny;
      s.emplace_back(x, y, 0);
      if (!in_bore(x, y)) s.emplace_back(x, y, kBoxZ);
      for (const Bore& b : kBores)
        if (std::hypot(x - b.x, y - b.y) <= b.r) s.emplace_back(x, y, kBoxZ - b.depth);
    }
  for (int k = 0; k <= nz; ++k) {
    const double z = kBoxZ * k / nz;
    for (int i = 0; i <= nx; ++i) {
      s.emplace_back(kBoxX * i / nx, 0, z);
      s.emplace_back(kBoxX * i / nx, kBoxY, z);
    }
    for (int j = 0; j <= ny; ++j) {
      s.emplace_back(0, kBoxY * j / ny, z);
      s.emplace_back(kBoxX, kBoxY * j / ny, z);
    }
  }
  const double pi = 3.14159265358979323846;
  for (const Bore& b : kBores) {
    const int na = static_cast<int>(std::ceil(2 * pi * b.r / h)), nd = static_cast<int>(std::ceil(b.depth / h));
    for (int a = 0; a < na; ++a)
      for (int d = 0; d <= nd; ++d) {
        const double t = 2 * pi * a / na;
        s.emplace_back(b.x + b.r * std::cos(t), b.y + b.r * std::sin(t), kBoxZ - b.depth * d / nd);
      }
  }
  return s;
}

const char* kHead = R"({
  "head": {"type": "PH10M", "a": {"min": 0, "max": 105, "step": 7.5}, "b": {"min": -180, "max": 180, "step": 7.5},
           "length": 30, "diameter": 24},
  "stylus": {"length": 20, "ball_diameter": 2, "stem_diameter": 1},
  "probe_body": {"length": 25, "diameter": 13.2},
  "qualified": [{"a": 0, "b": 0},
                {"a": 90, "b": 0}, {"a": 90, "b": 90}, {"a": 90, "b": 180}, {"a": 90, "b": -90},
                {"a": 45, "b": 0}, {"a": 45, "b": 90}, {"a": 45, "b": 180}, {"a": 45, "b": -90}]
})";
const OracleHead kOracleHead{1, 0.5, 20, 25, 6.6, 30, 12};

PlannerOptions options() {
  PlannerOptions o;
  o.points = 90;
  o.min_per_region = 3;
  return o;
}

struct Planned {
  Part part;
  RegionMap map;
};

const Planned& planned() {
  static const Planned p = [] {
    Planned out;
    out.part = imported_part();
    PartitionOptions po;
    po.grid = GridSize{60, 60};
    out.map = partition_part(out.part, po).map;
    return out;
  }();
  return p;
}

}  // namespace

TEST_CASE("indexable head: walls and bores the vertical stylus cannot take get their points, collision-free") {
  silence_occt();
  const Planned& in = planned();
  PlannerOptions vertical = options();
  PlannerOptions head = options();
  use_head(head, parse_probe_head(kHead, "head.json"));
  const PlanResult v = plan_probe_points(in.part, in.map, vertical);
  const PlanResult h = plan_probe_points(in.part, in.map, head);
  const PlanCoverage cv = plan_coverage(v, vertical.min_per_region);
  const PlanCoverage ch = plan_coverage(h, head.min_per_region);

  // The difference: the vertical stylus leaves the side faces and the bore
  // walls uncovered (tilt), the head covers every region.
  int steep_regions = 0;
  for (const RegionCoverage& r : cv.regions) {
    CAPTURE(r.region);
    CAPTURE(r.reason);
    const Face& f = in.part.faces[static_cast<std::size_t>(r.face)];
    const ParameterDomain& d = f.domain();
    const bool steep = std::abs(f.geometry((d.u0 + d.u1) / 2, (d.v0 + d.v1) / 2).normal.z()) < 0.5;
    steep_regions += steep;
    if (steep) CHECK(!r.covered);
  }
  CHECK(steep_regions >= 6);  // four side faces and two bore walls at least
  CHECK(!cv.complete());
  for (const RegionCoverage& r : ch.regions) {
    CAPTURE(r.region);
    CAPTURE(r.reason);
    CHECK(r.planned >= head.min_per_region);
  }
  CHECK(ch.complete());

  // Every point has a qualified tip; points are grouped by tip (as few
  // changes as tips used), and tilted tips are used.
  const ProbeHead& ph = *head.head;
  std::set<std::string> used;
  bool tilted = false;
  for (const PlannedPoint& p : h.plan.points) {
    REQUIRE(p.tip);
    CHECK(std::find(ph.qualified.begin(), ph.qualified.end(), *p.tip) != ph.qualified.end());
    used.insert(tip_name(*p.tip));
    tilted = tilted || p.tip->a > 0;
  }
  CHECK(tilted);
  CHECK(h.tip_changes == static_cast<int>(used.size()) - 1);

  // Brute force: the assembly along the touch and the vertical legs of
  // every point, and along every move between points with the tip it
  // carries there (a tip change happens after the rise to the plane).
  const double sample_h = 0.25;
  const std::vector<Eigen::Vector3d> samples = block_samples(sample_h);
  // A sampled face overestimates a distance of d >= 0.5 (the stem) by at
  // most (h/sqrt2)^2 / (2 d).
  const double tolerance = sample_h * sample_h / 2 + 1e-6;
  auto caps = [&](const TipAngles& t) { return oracle_capsules(kOracleHead, t.a, t.b); };
  double worst = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < h.plan.points.size(); ++k) {
    const PlannedPoint& p = h.plan.points[k];
    const std::vector<OracleCapsule> all = caps(*p.tip);
    const std::vector<OracleCapsule> rest(all.begin() + 1, all.end());
    const Eigen::Vector3d c = p.xyz + p.ijk;
    const Eigen::Vector3d out = p.xyz + (1 + std::max(h.approach, h.retract)) * p.ijk;
    CAPTURE(p.id);
    CAPTURE(tip_name(*p.tip));
    const double touch = swept_clearance(samples, rest, c, out);
    CHECK(touch >= -tolerance);
    worst = std::min(worst, touch);
    for (const Eigen::Vector3d& q : {p.approach, p.retract}) {
      const double leg = swept_clearance(samples, all, q, Eigen::Vector3d(q.x(), q.y(), std::max(q.z(), h.clearance_z)));
      CHECK(leg >= -tolerance);
      worst = std::min(worst, leg);
    }
    if (k == 0) continue;
    const PlannedPoint& prev = h.plan.points[k - 1];
    Eigen::Vector3d at = prev.retract;
    for (std::size_t w = 0; w < h.moves[k].waypoints.size(); ++w) {
      const TipAngles& t = (w == 0 && *prev.tip != *p.tip) ? *prev.tip : *p.tip;
      const double leg = swept_clearance(samples, caps(t), at, h.moves[k].waypoints[w]);
      CAPTURE(w);
      CHECK(leg >= -tolerance);
      worst = std::min(worst, leg);
      at = h.moves[k].waypoints[w];
    }
  }
  MESSAGE("indexable head plan: " << h.plan.points.size() << " points, " << used.size() << " tips, "
                                  << h.tip_changes << " changes, smallest sampled clearance " << worst << " mm");
}

TEST_CASE("indexable head: furrow plan --head writes the tip per point and per program, bad head files exit 2") {
  silence_occt();
  const std::string dir = scratch_dir("probe-head-cli");
  write_step(block_with_bores(), dir + "/block.step");
  write_text(dir + "/head.json", kHead);
  REQUIRE(run_furrow({"import", dir + "/block.step", "--out", dir + "/block.json"}).status == 0);
  REQUIRE(run_furrow({"partition", dir + "/block.json", "--out", dir + "/regions.json"}).status == 0);
  const auto r = run_furrow({"plan", dir + "/block.json", "--regions", dir + "/regions.json", "--out", dir + "/plan",
                             "--head", dir + "/head.json", "--points", "60", "--min-per-region", "2",
                             "--allow-uncovered"});
  CAPTURE(r.err);
  REQUIRE(r.status == 0);
  const std::string plan = slurp(dir + "/plan/plan.json");
  CHECK(plan.find("\"tip\"") != std::string::npos);
  CHECK(slurp(dir + "/plan/plan.csv").find(",tip_a,tip_b,feature\n") != std::string::npos);
  const std::string dmis = slurp(dir + "/plan/plan.dmi");
  CHECK(dmis.find("S(PROBE1_A0B0)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,45.000000,2.000000") != std::string::npos);
  CHECK(slurp(dir + "/plan/plan.prg").find("ChangeTool(\"Probe1_A0B0\")") != std::string::npos);
  const std::string report = slurp(dir + "/plan/report.json");
  CHECK(report.find("\"tip_changes\"") != std::string::npos);
  CHECK(report.find("\"A45BM90\"") != std::string::npos);

  const std::string good = kHead, tip = "\"a\": 45, \"b\": 0";
  write_text(dir + "/bad.json", std::string(good).replace(good.find(tip), tip.size(), "\"a\": 44, \"b\": 0"));
  const auto bad = run_furrow({"plan", dir + "/block.json", "--regions", dir + "/regions.json", "--out", dir + "/bad",
                               "--head", dir + "/bad.json"});
  CAPTURE(bad.err);
  CHECK(bad.status == 2);
  CHECK(bad.err.find("bad.json.qualified[5].a: 44 is not on the head's A grid") != std::string::npos);
  const auto both = run_furrow({"plan", dir + "/block.json", "--regions", dir + "/regions.json", "--out", dir + "/both",
                                "--head", dir + "/head.json", "--probe-diameter", "3"});
  CHECK(both.status == 2);
}
