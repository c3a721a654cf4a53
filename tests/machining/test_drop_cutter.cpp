// The interference search of contact_from_tip.hpp with its bounded drop
// cutter (drop_cutter.hpp) against a brute-force drop cutter written here:
// every face sampled on a dense (u, v) grid, each sample under the cutter's
// disc giving the tip height z - envelope(rho), the maximum taken.
//
// What the brute force proves (S a sample, F the found contact point):
//   - its samples are part points, so the true rest height is at least
//     brute; the search must find at least brute - height_tolerance;
//   - the found height is that of a real part point (recomputed here), so it
//     is at most the true rest height;
//   - for a non-rational face the grid node S nearest F in (u, v) differs
//     from F by at most du/2, dv/2 in the parameters, hence in z by at most
//     Zu du/2 + Zv dv/2 and in xy by at most d = Xu du/2 + Xv dv/2, with Zu,
//     Zv, Xu, Xv bounds of |S_u.z|, |S_v.z|, |S_u.xy|, |S_v.xy| from the
//     hodograph control points (a B-spline's derivative lies in their hull);
//     the envelope is convex, so it rises by at most slope(rho_F + d) d. So
//     found <= brute + Zu du/2 + Zv dv/2 + slope(rho_F + d) d (when
//     rho_F + d stays inside the shank radius; otherwise only the two
//     checks above).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "io/part_file.hpp"
#include "machining/cutter/contact_from_tip.hpp"
#include "machining/gouge/contact_sites.hpp"
#include "support/random_surface.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

// Lower envelope of the end mill, from docs/architecture.md: flat to R - r,
// then the corner quarter circle, nothing beyond R.
double envelope(double R, double r, double rho) {
  const double d = rho - (R - r);
  if (d <= 0) return 0;
  return r - std::sqrt(std::max(0.0, r * r - d * d));
}
double envelope_slope(double R, double r, double rho) {
  const double d = rho - (R - r);
  if (d <= 0) return 0;
  return d >= r ? INFINITY : d / std::sqrt(r * r - d * d);
}

// One face sampled on an n x n grid of its parameter rectangle.
struct SampledFace {
  std::vector<Eigen::Vector3d> points;
  double du = 0, dv = 0;
  double zu = 0, zv = 0, xu = 0, xv = 0;  // hodograph bounds (non-rational only)
  bool bounded = false;
};

// max |component| of the u- (dir 0) or v-hodograph control points.
void hodograph_bounds(const NurbsSurface& s, int dir, double& z, double& xy) {
  const int p = dir == 0 ? s.degree_u() : s.degree_v();
  const std::vector<double>& U = dir == 0 ? s.knots_u() : s.knots_v();
  const int n = dir == 0 ? s.num_u() : s.num_v(), m = dir == 0 ? s.num_v() : s.num_u();
  z = xy = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double span = U[i + p + 1] - U[i + 1];
      if (!(span > 0)) continue;
      const Eigen::Vector3d a = dir == 0 ? s.control_point(i, j) : s.control_point(j, i);
      const Eigen::Vector3d b = dir == 0 ? s.control_point(i + 1, j) : s.control_point(j, i + 1);
      const Eigen::Vector3d q = p * (b - a) / span;
      z = std::max(z, std::abs(q.z()));
      xy = std::max(xy, q.head<2>().norm());
    }
}

SampledFace sample(const Face& face, int n) {
  SampledFace out;
  const ParameterDomain& d = face.domain();
  out.du = d.width_u() / (n - 1);
  out.dv = d.width_v() / (n - 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = d.u0 + d.width_u() * i / (n - 1), v = d.v0 + d.width_v() * j / (n - 1);
      if (face.contains(u, v)) out.points.push_back(face.surface().point(u, v));
    }
  if (!face.surface().is_rational()) {
    hodograph_bounds(face.surface(), 0, out.zu, out.xu);
    hodograph_bounds(face.surface(), 1, out.zv, out.xv);
    out.bounded = true;
  }
  return out;
}

// Brute-force rest height at xy; points within `graze` of the radius do not
// hold the cutter (drop_cutter.hpp). -infinity when nothing is under it.
double brute_drop(const std::vector<SampledFace>& faces, double R, double r, const Eigen::Vector2d& xy,
                  double graze) {
  double best = -INFINITY;
  const double hold2 = (R - graze) * (R - graze);
  for (const SampledFace& f : faces)
    for (const Eigen::Vector3d& p : f.points) {
      const double rho2 = (p.head<2>() - xy).squaredNorm();
      if (rho2 < hold2) best = std::max(best, p.z() - envelope(R, r, std::sqrt(rho2)));
    }
  return best;
}

// Random tips over the part's box: the checks of the header for each.
void compare_with_brute_force(const Part& part, const std::vector<Cutter>& cutters, int queries,
                              unsigned seed, int grid) {
  std::vector<SampledFace> faces;
  for (const Face& f : part.faces) faces.push_back(sample(f, grid));
  // Tips over the sampled points' box (an unclamped net reaches well beyond its surface).
  Eigen::AlignedBox3d box;
  for (const SampledFace& f : faces)
    for (const Eigen::Vector3d& p : f.points) box.extend(p);
  std::mt19937 rng(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
  for (const Cutter& cutter : cutters) {
    const TipContactFinder finder(part, cutter);
    const DropCutterOptions& opt = TipContactOptions{}.bound;
    const DropCutter drop(part, cutter, opt);
    const double R = cutter.radius(), r = cutter.corner_radius();
    int resting = 0, incomplete = 0;
    long cells = 0;
    for (int k = 0; k < queries; ++k) {
      const Eigen::Vector2d xy(uniform(box.min().x(), box.max().x()), uniform(box.min().y(), box.max().y()));
      const Eigen::Vector3d tip(xy.x(), xy.y(), box.max().z());
      const TipContactResult res = finder.find(tip);
      const double brute = brute_drop(faces, R, r, xy, opt.radial_tolerance);
      CAPTURE(cutter.name());
      CAPTURE(k);
      CAPTURE(brute);
      cells += res.cells;
      if (!res.complete) {
        // The cap was hit: the bound it reports still holds.
        ++incomplete;
        CHECK(res.unresolved >= brute - 1e-9);
        continue;
      }
      if (!std::isfinite(brute)) {
        // No sample under the cutter: a contact found must be a real point near the rim.
        if (res.status == TipContactStatus::found)
          CHECK((res.contacts[0].point.head<2>() - xy).norm() > R - 0.5);
        continue;
      }
      REQUIRE(res.status == TipContactStatus::found);
      const TipContact& top = res.contacts[0];
      CAPTURE(top.tip_z);
      ++resting;
      // At least what the samples show (less the search's tolerance).
      CHECK(top.tip_z >= brute - opt.height_tolerance - 1e-9);
      // A real part point under the cutter, at the height it implies.
      const Eigen::Vector3d on = part.faces[top.face].surface().point(top.uv.x(), top.uv.y());
      CHECK((on - top.point).norm() < 1e-9);
      const double rho = (top.point.head<2>() - xy).norm();
      CHECK(rho <= R + 1e-9);
      if (top.kind != ContactKind::corner || rho < R - 1e-6)
        CHECK(top.tip_z <= top.point.z() - envelope(R, r, rho) + 1e-9);
      // No more than the sampling error above the samples (non-rational faces).
      const SampledFace& f = faces[top.face];
      if (!f.bounded) continue;
      const double d = f.xu * f.du / 2 + f.xv * f.dv / 2;
      if (rho + d >= R - opt.radial_tolerance) continue;
      const double err = f.zu * f.du / 2 + f.zv * f.dv / 2 + envelope_slope(R, r, rho + d) * d;
      CAPTURE(err);
      CHECK(top.tip_z <= brute + err + 1e-9);
      // The decision form: asked about a height the samples beat, it proves
      // it with a real point; asked about one above the sampling error, it
      // finds none (or reports a bound from its cap that admits the rest).
      const DropCutterResult below = drop.rests_above(xy, brute - 1e-3);
      CHECK(below.tip_z > brute - 1e-3);
      CHECK(below.any);
      const Eigen::Vector3d held = part.faces[below.face].surface().point(below.uv.x(), below.uv.y());
      CHECK((held - below.point).norm() < 1e-9);
      CHECK(below.tip_z <= held.z() - envelope(R, r, (held.head<2>() - xy).norm()) + 1e-9);
      const double clear_height = brute + err + 1e-3;
      const DropCutterResult above = drop.rests_above(xy, clear_height);
      CHECK_FALSE(above.tip_z > clear_height);
      if (!above.complete) CHECK(above.unresolved > clear_height);
    }
    MESSAGE(cutter.name() << " cells " << cells << " incomplete " << incomplete);
    CHECK(resting > queries / 2);
  }
}

}  // namespace

TEST_CASE("drop cutter: the mould site where the seeded search called BULL-D12-R2 clear") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const std::vector<ContactSite> sites = grid_sites(part, 100);
  REQUIRE(sites.size() > 7441);
  const ContactSite& site = sites[7441];
  CHECK(site.uv.x() == doctest::Approx(0.747475).epsilon(1e-6));
  CHECK(site.uv.y() == doctest::Approx(0.414141).epsilon(1e-6));
  const Face& face = part.faces[site.face];
  const DifferentialGeometry g = face.geometry(site.uv.x(), site.uv.y());
  const Cutter bull("BULL-D12-R2", 6, 2);
  const CutterLocation loc = cutter_location(bull, g.point, g.normal);
  REQUIRE(loc.reachable);
  const std::vector<SampledFace> faces{sample(face, 1601)};
  const double brute = brute_drop(faces, 6, 2, loc.tip.head<2>(), TipContactOptions{}.bound.radial_tolerance);
  CHECK(brute - loc.tip.z() > 0.15);  // cuts about 0.157 mm into the part
  const TipContactFinder finder(part, bull);
  const TipContactResult res = finder.find(loc.tip);
  REQUIRE(res.status == TipContactStatus::found);
  CHECK(res.complete);
  CHECK(-res.gap >= brute - loc.tip.z() - TipContactOptions{}.bound.height_tolerance);
}

TEST_CASE("drop cutter: random tips over the mould, ball, flat and bull-nose, against brute force") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  compare_with_brute_force(part, {Cutter("ball", 5, 5), Cutter("flat", 4, 0), Cutter("bull", 6, 2)}, 40,
                           7, 1601);
}

TEST_CASE("drop cutter: random tips over steep random NURBS parts, against brute force") {
  std::mt19937 rng(11);
  // Non-rational, unclamped (sampling error bound applies) and rational, clamped.
  const NurbsSurface steep = test::random_surface(rng, 3, 2, false, false);
  const NurbsSurface rational = test::random_surface(rng, 2, 3, true, true);
  for (const NurbsSurface& s : {steep, rational}) {
    Part part;
    part.faces.emplace_back("random", s);
    compare_with_brute_force(part, {Cutter("ball", 4, 4), Cutter("flat", 5, 0), Cutter("bull", 6, 1.5)},
                             25, 3, 1201);
  }
}
