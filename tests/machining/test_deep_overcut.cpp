// An overcut deeper than the normal search's default range is measured, not
// reported as the range itself (machining/prediction/normal_error.hpp,
// NormalErrorOptions::floor and shadow). Oracles: closed forms for a flat
// end mill's flat bottom and for a vertical wall.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "geometry/primitives.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/prediction/normal_error.hpp"
#include "machining/prediction/path_prediction.hpp"

using namespace furrow;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("normal error: below a floor far under the default range, the overcut is the floor's distance") {
  // H = -50 everywhere: from Q = 0 along +z the cut reaches 50 mm down.
  auto height = [](double, double) { return -50.0; };
  const Eigen::Vector3d q(0, 0, 0), n(0, 0.6, 0.8);
  NormalErrorOptions bounded;
  bounded.floor = -50;
  const NormalError e = normal_error(height, q, n, bounded);
  CHECK(e.reached);
  CHECK(e.converged);
  CHECK(e.error == doctest::Approx(-50 / 0.8).epsilon(1e-12));
  // Without bounds the search stops at its range and says so: a lower
  // bound on the depth, not converged.
  const NormalError capped = normal_error(height, q, n, NormalErrorOptions{});
  CHECK(capped.reached);
  CHECK_FALSE(capped.converged);
  CHECK(capped.error == -10.0);
}

TEST_CASE("normal error: a horizontal normal under a deep cut meets its wall at the edge of the shadow") {
  // Cut 1 mm below Q over |x| < 40, uncut beyond (a pocket wall): along -x
  // from Q the overcut ends at the wall, 40 mm away.
  auto height = [](double x, double) { return std::fabs(x) < 40 ? -1.0 : kInf; };
  const Eigen::Vector3d q(0, 0, 0), n(1, 0, 0);
  NormalErrorOptions bounded;
  bounded.shadow = Eigen::AlignedBox2d(Eigen::Vector2d(-40, -5), Eigen::Vector2d(40, 5));
  const NormalError e = normal_error(height, q, n, bounded);
  CHECK(e.reached);
  CHECK(e.converged);
  CHECK(e.wall);
  CHECK(e.error == doctest::Approx(-40).epsilon(1e-9));
}

TEST_CASE("prediction: a flat end mill 15 mm under a tilted plane overcuts by (15 + x tan a) / cos a") {
  // Plane z = x tan a over x in [-5, 5], y in [0, 30], normal
  // (-sin a, 0, cos a). A flat end mill of radius 20 runs along y at x = 0
  // with its tip at z = -15: its envelope is the flat z = -15 for |x| < 20.
  // From Q = (x, y, x tan a) the normal meets z = -15 at
  // t = -(15 + x tan a) / cos a, at x + (15 + x tan a) tan a, inside the
  // flat for every x of the face; so every sample's error is that t, the
  // deepest -(15 + 5 tan a) / cos a = -17.8995 mm at x = 5 (beyond the
  // 10 mm default range of the normal search, where it used to stop).
  const double a = 20 * kPi / 180, t = std::tan(a);
  Part part;
  part.faces.emplace_back("tilted", make_plane({-5, 0, -5 * t}, {10, 0, 10 * t}, {0, 30, 0}));
  const Cutter flat("flat40", 20, 0);
  Toolpath path;
  path.kind = ToolpathKind::tool_tips;
  path.source = "deep.nc";
  ToolpathPass pass;
  for (int k = 0; k <= 8; ++k) {
    ToolpathPoint p;
    p.position = {0, -5 + 5.0 * k, -15};
    p.line = k + 1;
    pass.points.push_back(p);
  }
  path.passes.push_back(pass);
  PathPredictionOptions options;
  options.resolution = 0.25;
  const PathPrediction r = predict_path(part, flat, path, options);
  const double deepest = -(15 + 5 * t) / std::cos(a);
  REQUIRE(r.map.max_overcut.found);
  CHECK(r.map.max_overcut.error == doctest::Approx(deepest).epsilon(1e-9));
  CHECK(r.map.max_overcut.at.point.x() == doctest::Approx(5).epsilon(1e-6));
  // Every reached sample against the closed form at its own x.
  REQUIRE(r.map.faces.size() == 1);
  const FaceErrorMap& m = r.map.faces[0];
  int checked = 0;
  for (int j = 0; j < m.nv; ++j)
    for (int i = 0; i < m.nu; ++i) {
      const std::size_t k = m.index(i, j);
      REQUIRE(m.status[k] == ErrorCellStatus::reached);
      const double x = part.faces[0].surface().point(m.u(i), m.v(j)).x();
      CHECK(m.error[k] == doctest::Approx(-(15 + x * t) / std::cos(a)).epsilon(1e-6));
      ++checked;
    }
  CHECK(checked > 100);
  CHECK(r.map.max_undercut.error == doctest::Approx(-(15 - 5 * t) / std::cos(a)).epsilon(1e-9));
}
