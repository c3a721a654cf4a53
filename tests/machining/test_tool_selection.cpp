#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/gouge/tool_selection.hpp"
#include "cutter_reference.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The part as an analytic height field z(x, y), NaN where there is none.
using HeightField = std::function<double(double, double)>;

// Brute-force drop cutter over a height field: the tip height at which the
// cutter lowered at (x, y) touches.
double drop_cutter(const HeightField& z, double R, double r, double x, double y) {
  const Cutter c("c", R, r);
  return test::maximize_over_disc(R, [&](double rho, double phi) {
    const double h = z(x + rho * std::cos(phi), y + rho * std::sin(phi));
    return std::isnan(h) ? -1e300 : h - c.height_at(rho);
  });
}

// The library's pick by the rules written out: local comparison for a part
// with equal-or-known principal curvatures (given as a function of the tool
// and the contact angle), interference by the brute-force drop cutter with
// the tip from docs/architecture.md's formula.
struct Oracle {
  HeightField z;
  // Local gouge for (R, r, theta0) by the analytic rule for this part.
  std::function<bool(double, double, double)> local_gouge;
};

// 1: clear, 0: gouges, -1: too close to call (skip the site).
int oracle_clear(const Oracle& o, const Cutter& c, const Eigen::Vector3d& P, const Eigen::Vector3d& n) {
  const double theta0 = std::acos(std::min(1.0, n.z()));
  if (o.local_gouge(c.radius(), c.corner_radius(), theta0)) return 0;
  const double R = c.radius(), r = c.corner_radius();
  const double nxy = std::hypot(n.x(), n.y());
  const Eigen::Vector3d e = nxy > 1e-9 ? Eigen::Vector3d(n.x() / nxy, n.y() / nxy, 0) : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d T = P + r * n + (R - r) * e - r * Eigen::Vector3d::UnitZ();
  const double rest = drop_cutter(o.z, R, r, T.x(), T.y());
  if (std::abs(rest - T.z()) < 1e-5) return rest - T.z() > 1e-6 ? -1 : 1;
  return rest > T.z() ? 0 : 1;
}

void check_against_oracle(const Part& part, const Oracle& oracle, int grid, const std::string& expected_whole) {
  std::vector<Cutter> library;
  for (const ToolSpec& t : read_tool_library(test::source_path("examples/tools/library.json"))) library.emplace_back(t);
  const std::vector<ContactSite> sites = grid_sites(part, grid);
  const ToolSelection sel = select_tools(part, library, sites);
  REQUIRE(sel.library.size() == library.size());
  // The order: largest R first, then largest r.
  for (std::size_t t = 1; t < sel.library.size(); ++t) {
    const Cutter &a = sel.library[t - 1], &b = sel.library[t];
    CHECK((a.radius() > b.radius() || (a.radius() == b.radius() && a.corner_radius() >= b.corner_radius())));
  }
  std::vector<bool> clear_everywhere(sel.library.size(), true);
  int compared = 0;
  for (const SiteSelection& s : sel.sites) {
    REQUIRE(s.machinable);
    int expected = -1;
    bool ambiguous = false;
    for (std::size_t t = 0; t < sel.library.size(); ++t) {
      const int c = oracle_clear(oracle, sel.library[t], s.point, s.normal);
      if (c < 0) ambiguous = true;
      if (c == 0) clear_everywhere[t] = false;
      if (c == 1 && expected < 0 && !ambiguous) expected = static_cast<int>(t);
    }
    if (ambiguous) continue;
    ++compared;
    CAPTURE(s.point);
    CHECK(s.tool == expected);
  }
  CHECK(compared > static_cast<int>(sites.size()) * 3 / 4);
  REQUIRE(sel.whole_surface >= 0);
  CHECK(sel.library[sel.whole_surface].name() == expected_whole);
  for (std::size_t t = 0; t < static_cast<std::size_t>(sel.whole_surface); ++t) CHECK_FALSE(clear_everywhere[t]);
  CHECK(clear_everywhere[sel.whole_surface]);
}

}  // namespace

TEST_CASE("tool selection on a concave cylinder (trough of radius 9): the largest ball that fits, per site the oracle's pick") {
  const double rho = 9, a0 = M_PI + 0.3;
  Part part;
  part.faces.emplace_back("trough", make_cylinder(rho, 30, a0, 2 * M_PI - 0.3));
  Oracle oracle;
  const double half_width = rho * std::cos(0.3);
  oracle.z = [=](double x, double y) {
    if (std::abs(x) > half_width || y < 0 || y > 30) return kNan;
    return -std::sqrt(rho * rho - x * x);
  };
  const double tol = GougeOptions().curvature_tolerance;
  oracle.local_gouge = [=](double R, double r, double theta0) {
    if (theta0 < 1e-9 && R > r) return 1 / rho > tol;  // the flat bottom on the trough's floor
    if (r == 0) return false;                          // rim along the straight axis direction
    return 1 / rho - 1 / r > tol;                      // cross direction = the meridian
  };
  // Only balls of R <= 9 pass at the floor (odd grid: u = 0.5 is the floor line).
  check_against_oracle(part, oracle, 9, "BALL-D16");
}

TEST_CASE("tool selection in a spherical bowl of radius 20: per site the oracle's pick, whole surface the largest ball") {
  const double rho = 20, lon0 = -0.8, lon1 = 0.8, lat0 = -1.35, lat1 = -0.3;
  Part part;
  part.faces.emplace_back("bowl", make_sphere(rho, lon0, lon1, lat0, lat1), Trim{}, true);
  Oracle oracle;
  oracle.z = [=](double x, double y) {
    const double h = std::hypot(x, y);
    if (h >= rho) return kNan;
    const double lon = std::atan2(y, x), lat = -std::acos(h / rho);
    if (lon < lon0 || lon > lon1 || lat < lat0 || lat > lat1) return kNan;
    return -std::sqrt(rho * rho - h * h);
  };
  const double tol = GougeOptions().curvature_tolerance;
  oracle.local_gouge = [=](double R, double r, double theta0) {
    // Umbilic part (1/rho everywhere) against the cutter's smallest curvature.
    const double k_min = r == R ? 1 / R : std::sin(theta0) / (R - r + r * std::sin(theta0));
    return 1 / rho - k_min > tol;
  };
  check_against_oracle(part, oracle, 7, "BALL-D20");
}

TEST_CASE("tool selection: where even the smallest tool gouges, the curvature the design would need") {
  const double rho = 0.4;  // a groove tighter than the smallest ball (R 0.5)
  Part part;
  part.faces.emplace_back("groove", make_cylinder(rho, 5, M_PI + 0.4, 2 * M_PI - 0.4));
  std::vector<Cutter> library = {Cutter("B1", 0.5, 0.5), Cutter("B2", 1, 1)};
  const ToolSelection sel = select_tools(part, library, grid_sites(part, 5));
  CHECK(sel.whole_surface == -1);
  CHECK(sel.without_tool == sel.sites.size());
  CHECK(sel.library.back().name() == "B1");
  for (const SiteSelection& s : sel.sites) {
    CHECK(s.tool == -1);
    REQUIRE(s.smallest_gouges_locally);
    CHECK(s.needed.design_curvature == doctest::Approx(1 / rho).epsilon(1e-9));
    CHECK(s.needed.allowed_curvature == doctest::Approx(1 / 0.5).epsilon(1e-9));
    CHECK(std::abs(s.needed.direction.y()) < 1e-9);  // across the groove
  }
  CHECK_THROWS_AS(select_tools(part, {}, grid_sites(part, 3)), InputError);
}

TEST_CASE("tool selection counts border sites whose neighbour search did not converge") {
  const Part part = read_part(test::source_path("examples/parts/two_face.json"));
  std::vector<ContactSite> sites(3);
  sites[0].face = 0, sites[0].uv = {1.0, 0.37};  // valley_wall's edge against the crown
  sites[1].face = 0, sites[1].uv = {0.5, 0.5};   // interior
  sites[2].face = 1, sites[2].uv = {0.0, 0.37};  // the crown's side of the same edge
  const std::vector<Cutter> library = {Cutter(read_tool_library(test::source_path("examples/tools/library.json")).back())};
  const ToolSelection normal = select_tools(part, library, sites);
  CHECK(normal.border_unresolved == 0);
  ToolSelectionOptions starved;
  starved.scan.border.closest.max_newton_iterations = 1;
  const ToolSelection capped = select_tools(part, library, sites, starved);
  CHECK(capped.border_unresolved == 2);  // both edge sites, not the interior one
  CHECK_FALSE(capped.sites[0].border_search_converged);
  CHECK(capped.sites[1].border_search_converged);
  CHECK_FALSE(capped.sites[2].border_search_converged);
}
