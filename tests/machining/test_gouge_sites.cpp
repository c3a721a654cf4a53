#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/gouge_sites.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

// Analytic oracle for a ball path: the cut is the union of capsules (ball
// centres on the segments between consecutive centres, radius R). The
// overcut at a surface point is how far below it, along -n, the union
// reaches: scan down while inside any capsule (point-segment distances),
// then bisect the exit.
struct CapsuleUnion {
  std::vector<Eigen::Vector3d> centres;  // consecutive ball centres of one pass
  double radius;

  bool inside(const Eigen::Vector3d& p) const {
    for (std::size_t k = 0; k + 1 < centres.size(); ++k) {
      const Eigen::Vector3d a = centres[k], d = centres[k + 1] - centres[k];
      const double s = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      if ((p - (a + s * d)).norm() < radius) return true;
    }
    return false;
  }
  double overcut(const Eigen::Vector3d& q, const Eigen::Vector3d& n) const {
    if (!inside(q)) return 0;
    double t = 0;
    while (inside(q - (t + 0.01) * n)) t += 0.01;
    double lo = t, hi = t + 0.01;  // inside at lo, outside at hi
    for (int k = 0; k < 45; ++k) {
      const double mid = 0.5 * (lo + hi);
      (inside(q - mid * n) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

}  // namespace

TEST_CASE("a 20 mm ball across the mould's dimple gouges: site depths match the analytic overcut") {
  const Part part = read_part(example("mould.json"));
  const VerticalProjector projector(part);
  const Cutter ball("ball20", 10, 10);
  // One pass along y = 30 through the dimple (tightest concave radius about
  // 9 mm < 10 mm), contact points every 0.5 mm.
  std::vector<ZMapMove> moves;
  CapsuleUnion oracle{{}, 10};
  Eigen::Vector3d previous;
  for (int k = 0; k <= 40; ++k) {
    const SurfacePoint s = projector.project(62 + 0.5 * k, 30);
    REQUIRE(s.valid);
    const CutterLocation loc = cutter_location(ball, s.point, s.normal);
    REQUIRE(loc.reachable);
    if (k > 0) moves.push_back({previous, loc.tip, 0, k - 1});
    previous = loc.tip;
    oracle.centres.push_back(loc.tip + Eigen::Vector3d(0, 0, 10));
  }
  ZMap zmap(Eigen::AlignedBox2d(Eigen::Vector2d(48, 16), Eigen::Vector2d(96, 44)), 0.05);
  zmap.cut(ball, moves);
  ErrorMapOptions map_options;
  map_options.sample_spacing = 0.1;
  const ErrorMap map = compute_error_map(part, zmap, map_options);
  // The ball is only slightly too big (radius 10 against about 9.3 at the
  // bottom): the gouge is a few micrometres deep, so a fine threshold.
  GougeSiteOptions site_options;
  site_options.threshold = 0.001;
  const std::vector<GougeSite> sites = find_gouge_sites(part, zmap, map, site_options, map_options);
  REQUIRE(!sites.empty());

  // The deepest overcut anywhere, by the oracle on a 0.25 mm grid then a
  // local 0.005 mm grid around the worst point.
  auto oracle_at = [&](const Eigen::Vector2d& uv) {
    const SurfacePoint p = surface_point(part, 0, uv);
    return oracle.overcut(p.point, p.normal);
  };
  Eigen::Vector2d worst_uv(0, 0);
  double worst = 0;
  for (double x = 56; x <= 88; x += 0.25)
    for (double y = 20; y <= 40; y += 0.25) {
      const Eigen::Vector2d uv(x / 100, y / 80);  // the mould's x(u), y(v) are linear
      const double o = oracle_at(uv);
      if (o > worst) worst = o, worst_uv = uv;
    }
  REQUIRE(worst > 0.005);
  auto local_max = [&](Eigen::Vector2d centre, double half_mm) {
    double best = 0;
    for (int round = 0; round < 3; ++round, half_mm /= 10) {
      Eigen::Vector2d best_uv = centre;
      for (int i = -20; i <= 20; ++i)
        for (int j = -20; j <= 20; ++j) {
          const Eigen::Vector2d uv = centre + Eigen::Vector2d(i * half_mm / 20 / 100, j * half_mm / 20 / 80);
          const double o = oracle_at(uv);
          if (o > best) best = o, best_uv = uv;
        }
      centre = best_uv;
    }
    return best;
  };
  const double analytic = local_max(worst_uv, 0.25);

  double deepest_site = 0;
  for (const GougeSite& s : sites) {
    CAPTURE(s.id);
    CHECK(s.depth > site_options.threshold);
    CHECK(s.area > 0);
    CHECK(s.uv_box.contains(s.centroid_uv));
    CHECK(s.box.min().x() >= 48);
    CHECK(s.box.max().x() <= 96);
    // Each site's depth is the oracle's local maximum at its deepest point.
    const double local = local_max(s.deepest.uv, 0.2);
    CHECK(std::fabs(s.depth - local) < 2e-6);
    deepest_site = std::max(deepest_site, s.depth);
  }
  // ... and the deepest site is the deepest overcut of the whole cut.
  CHECK(std::fabs(deepest_site - analytic) < 2e-6);
  // Site ids are 1..N in order.
  for (std::size_t k = 0; k < sites.size(); ++k) CHECK(sites[k].id == static_cast<int>(k) + 1);
}

TEST_CASE("gouge sites: two separate overcut patches are two sites with their own areas") {
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {40, 0, 0}, {0, 20, 0}));
  const Cutter flat("flat", 1.0, 0);
  // Two level flat-end-mill moves 0.02 mm below the plane, far apart: each
  // cuts a stadium of width 2 and length 5 + 2 = 2 x 5 + pi area.
  ZMap zmap(part_xy_extent(part), 0.02);
  zmap.cut(flat, {{{5, 5, -0.02}, {10, 5, -0.02}, 0, 0}, {{25, 15, -0.03}, {30, 15, -0.03}, 1, 0}});
  ErrorMapOptions options;
  options.sample_spacing = 0.02;
  const ErrorMap map = compute_error_map(part, zmap, options);
  const std::vector<GougeSite> sites = find_gouge_sites(part, zmap, map, {0.01}, options);
  REQUIRE(sites.size() == 2);
  CHECK(sites[0].depth == doctest::Approx(0.02).epsilon(1e-9));
  CHECK(sites[1].depth == doctest::Approx(0.03).epsilon(1e-9));
  const double stadium = 2 * 5 + M_PI;
  for (const GougeSite& s : sites) {
    CHECK(s.area == doctest::Approx(stadium).epsilon(0.02));  // pixelised boundary
    CHECK(s.box.sizes().x() == doctest::Approx(7).epsilon(0.01));
    CHECK(s.box.sizes().y() == doctest::Approx(2).epsilon(0.03));
  }
  CHECK(sites[0].centroid.x() == doctest::Approx(7.5).epsilon(1e-3));
  CHECK(sites[1].centroid.y() == doctest::Approx(15).epsilon(1e-3));
}
