// Uncut samples: what the tool never came near carries no number
// (docs/formats.md "prediction.json", summary.samples.not_reached). The
// expected statuses and errors come from brute force on the cutter as the
// docs describe it, never from the library's z-map.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "io/machining/toolpath_file.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/normal_error.hpp"
#include "machining/prediction/path_prediction.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Brute-force machined height of a level ball pass (tip height z, from
// (x0, y) to (x1, y)) above the point (x, y): the ball's lowest point above
// it, R - sqrt(R^2 - d^2) above the tip level at horizontal distance d from
// the tip's segment (docs/architecture.md: the ball is the sphere of radius
// R whose lowest point is the tip); +infinity beyond R (no cutter there).
double ball_pass_height(double R, double z, double x0, double x1, double y, double px, double py) {
  const double cx = std::clamp(px, x0, x1);
  const double d = std::hypot(px - cx, py - y);
  if (d > R) return kInf;
  return z + R - std::sqrt(R * R - d * d);
}

}  // namespace

TEST_CASE("normal error: a normal that crosses uncut stock before a machined surface reaches nothing") {
  // A synthetic machined surface along x: cut (5 mm above Q) for x < 1,
  // uncut for 1 <= x < 1.55, cut deep (-100) beyond. From Q = 0 the normal
  // +x starts under the first cut (g0 = 5 > 0, material left) and leaves it
  // at x = 1: above Q lies stock the tool never came near, whatever lies
  // beyond the gap. The bracket's geometric steps (0.25, 0.4, 0.64, 1.024,
  // 1.64: growth 1.6 from |g0| * 0.05) jump from the first cut straight into
  // the second, so without a step limit the search would meet the far cut's
  // wall at x = 1.55 and call that material left.
  auto height = [](double x, double) { return x < 1 ? 5.0 : x < 1.55 ? kInf : -100.0; };
  const Eigen::Vector3d q(0, 0, 0), n(1, 0, 0);
  NormalErrorOptions unbounded;  // max_step = 0: caught by the wall's uncut near side
  const NormalError a = normal_error(height, q, n, unbounded);
  CHECK_FALSE(a.reached);
  CHECK(a.error == 0.0);
  NormalErrorOptions stepped;
  stepped.max_step = 0.1;  // sees the gap itself
  const NormalError b = normal_error(height, q, n, stepped);
  CHECK_FALSE(b.reached);
  CHECK(b.error == 0.0);
  CHECK(b.end > 1.0);
  CHECK(b.end <= 1.1 + 1e-12);
  // Without the gap the same search meets the far cut's wall legitimately:
  // material left up to it (1.55 along the normal, then the deep cut).
  auto no_gap = [](double x, double) { return x < 1.55 ? 5.0 : -100.0; };
  const NormalError c = normal_error(no_gap, q, n, stepped);
  REQUIRE(c.reached);
  CHECK(c.wall);
  CHECK(c.error == doctest::Approx(1.55).epsilon(1e-8));
}

TEST_CASE("sparse path on a plane: between far passes the samples are uncut, errors match brute force") {
  // A plane 40 x 30 at z = 0, a ball of radius 3. Two adjacent passes at
  // y = 5 and y = 6.5 (a scallop between them) and one far away at y = 25,
  // all level at z = 0 from x = 5 to x = 35. Between y = 9.5 and y = 22
  // nothing was cut: those samples are uncut (not_reached), carry no number
  // and are in no statistic.
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {40, 0, 0}, {0, 30, 0}));
  const double R = 3;
  const Cutter ball("ball", R, R);
  const double ys[] = {5.0, 6.5, 25.0};
  std::vector<ZMapMove> moves;
  for (int k = 0; k < 3; ++k) moves.push_back({{5, ys[k], 0}, {35, ys[k], 0}, k, 0});
  ZMap zmap(part_xy_extent(part), 0.1);
  zmap.cut(ball, moves);
  // Nodes: cut exactly where a pass is within R (brute force, away from the
  // rim by a rounding margin).
  int node_mismatch = 0, uncut_between = 0;
  for (int j = 0; j < zmap.ny(); ++j)
    for (int i = 0; i < zmap.nx(); ++i) {
      double h = kInf;
      for (const double y : ys) h = std::min(h, ball_pass_height(R, 0, 5, 35, y, zmap.x(i), zmap.y(j)));
      const bool cut = zmap.node_owner(i, j) >= 0;
      if (std::isfinite(h) != cut) {
        double d = kInf;  // how close the node is to a shadow's rim
        for (const double y : ys)
          d = std::min(d, std::abs(std::hypot(zmap.x(i) - std::clamp(zmap.x(i), 5.0, 35.0), zmap.y(j) - y) - R));
        node_mismatch += d > 1e-9;
      }
      if (zmap.y(j) > 9.6 && zmap.y(j) < 21.9) {
        CHECK_FALSE(cut);
        CHECK(std::isinf(zmap.node_height(i, j)));
        ++uncut_between;
      }
    }
  CHECK(node_mismatch == 0);
  CHECK(uncut_between > 100 * 120);

  ErrorMapOptions options;
  const ErrorMap map = compute_error_map(part, zmap, options);
  REQUIRE(map.faces.size() == 1);
  const FaceErrorMap& m = map.faces[0];
  // Every sample against brute force: the plane's normal is +z, so the error
  // is the machined height above the point.
  std::size_t reached = 0, uncut = 0, status_mismatch = 0, error_mismatch = 0;
  double brute_max = -kInf, brute_min = kInf;
  for (int j = 0; j < m.nv; ++j)
    for (int i = 0; i < m.nu; ++i) {
      const double x = 40 * m.u(i), y = 30 * m.v(j);
      double h = kInf;
      for (const double yp : ys) h = std::min(h, ball_pass_height(R, 0, 5, 35, yp, x, y));
      const std::size_t k = m.index(i, j);
      const ErrorCellStatus s = m.status[k];
      reached += s == ErrorCellStatus::reached;
      uncut += s == ErrorCellStatus::not_reached;
      if (s == ErrorCellStatus::not_reached) CHECK(m.error[k] == 0.0f);  // no number
      if (m.boundary[k]) continue;  // within a cell of a shadow's rim: resolution-dependent
      if ((s == ErrorCellStatus::reached) != std::isfinite(h)) {
        ++status_mismatch;
        continue;
      }
      if (s != ErrorCellStatus::reached) continue;
      brute_max = std::max(brute_max, h);
      brute_min = std::min(brute_min, h);
      error_mismatch += std::abs(m.error[k] - h) > 1e-6;  // stored as float
    }
  CHECK(status_mismatch == 0);
  CHECK(error_mismatch == 0);
  CHECK(map.not_reached == uncut);
  CHECK(map.reached == reached);
  CHECK(uncut > map.samples / 3);  // the band between y = 9.5 and 22 at least
  // The statistics are over reached samples only: the largest undercut is
  // the ball's flank at a shadow's rim (below R, the flank's top), the
  // largest overcut 0 (the passes are level on the plane).
  REQUIRE(map.max_undercut.found);
  CHECK(map.max_undercut.error >= brute_max - 1e-6);
  CHECK(map.max_undercut.error <= R + 1e-9);
  REQUIRE(map.max_overcut.found);
  CHECK(std::abs(map.max_overcut.error) < 1e-9);
  CHECK(brute_min >= 0);
  // The scallop between the adjacent passes, brute force at the ridge
  // (y = 5.75): R - sqrt(R^2 - 0.75^2).
  const NormalError ridge = zmap_error(zmap, Eigen::Vector3d(20, 5.75, 0), Eigen::Vector3d::UnitZ());
  REQUIRE(ridge.reached);
  CHECK(ridge.error == doctest::Approx(R - std::sqrt(R * R - 0.75 * 0.75)).epsilon(1e-9));
  // In the middle of the gap: uncut, no number.
  const NormalError gap = zmap_error(zmap, Eigen::Vector3d(20, 15, 0), Eigen::Vector3d::UnitZ());
  CHECK_FALSE(gap.reached);
  CHECK(gap.error == 0.0);
}

TEST_CASE("sparse path through prediction.json: uncut samples counted per face, no number beyond the cut") {
  // The same kind of path as a contact-point CSV would give (normal +z on
  // the plane), through the whole prediction and its JSON: the uncut samples
  // are counted in summary.samples and per face, their cells are 'N' with
  // null values, and every number in the error fields lies within what the
  // ball can leave on a plane ([0, R], brute force above).
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {40, 0, 0}, {0, 30, 0}));
  const double R = 3;
  const Cutter ball("ball", R, R);
  Toolpath path;
  path.kind = ToolpathKind::contact_points;
  path.source = "sparse.csv";
  int line = 2;
  for (const double y : {5.0, 25.0}) {
    ToolpathPass pass;
    for (double x = 5; x <= 35 + 1e-9; x += 5) {
      ToolpathPoint p;
      p.position = {x, y, 0};
      p.normal = {0, 0, 1};
      p.line = line++;
      pass.points.push_back(p);
    }
    path.passes.push_back(pass);
  }
  PathPredictionOptions options;
  options.resolution = 0.1;
  const PathPrediction result = predict_path(part, ball, path, options);
  const Prediction p = make_prediction(part, result, options, "plane.json", "sparse.csv");
  const nlohmann::json doc = nlohmann::json::parse(prediction_to_json_text(p));
  const auto& samples = doc["summary"]["samples"];
  CHECK(samples["not_reached"].get<std::size_t>() > 0);
  REQUIRE(doc["faces"].size() == 1);
  const auto& face = doc["faces"][0];
  CHECK(face["samples"]["not_reached"] == samples["not_reached"]);
  CHECK(face["samples"]["reached"] == samples["reached"]);
  CHECK(face["samples"]["outside"].get<std::size_t>() == 0);
  // Cells of the gap (y = 9 .. 21, cells of about 1 mm) are 'N' with nulls.
  const int cu = face["cells"][0], cv = face["cells"][1];
  int gap_cells = 0;
  for (int cj = 0; cj < cv; ++cj) {
    const double y0 = 30.0 * cj / cv, y1 = 30.0 * (cj + 1) / cv;
    if (y0 < 9 || y1 > 21) continue;
    const std::string row = face["status"][cj];
    for (int ci = 0; ci < cu; ++ci) {
      CHECK(row[ci] == 'N');
      CHECK(face["max_undercut"][cj * cu + ci].is_null());
      ++gap_cells;
    }
  }
  CHECK(gap_cells > 10 * cu);
  for (const char* key : {"mean", "max_undercut", "max_overcut"})
    for (const auto& v : face[key])
      if (!v.is_null()) {
        CHECK(v.get<double>() >= -1e-7);
        CHECK(v.get<double>() <= R + 1e-7);
      }
  const double top = doc["summary"]["max_undercut"]["error"];
  CHECK(top <= R + 1e-7);
  CHECK(top > 0);
  // Read back: the counts survive.
  const Prediction back = parse_prediction_json(prediction_to_json_text(p), "p.json");
  REQUIRE(back.faces.size() == 1);
  CHECK(back.faces[0].has_samples);
  CHECK(back.faces[0].samples_not_reached == samples["not_reached"].get<std::size_t>());
  CHECK(back.faces[0].samples_reached == samples["reached"].get<std::size_t>());
  // A count that contradicts the cells' letters is bad input: 'N' cells
  // but no uncut sample.
  nlohmann::json bad = doc;
  bad["faces"][0]["samples"]["not_reached"] = 0;
  CHECK_THROWS_WITH_AS(parse_prediction_json(bad.dump(), "bad.json"),
                       doctest::Contains("bad.json: faces[0].samples.not_reached: 0, but cell"), InputError);
  // Files written before the per-face counts still read.
  nlohmann::json old = doc;
  old["faces"][0].erase("samples");
  CHECK_FALSE(parse_prediction_json(old.dump(), "old.json").faces[0].has_samples);
}

TEST_CASE("beside a pass of a large ball: errors up to the search range are true crossings, beyond it uncut") {
  // A plane rising along y (z = 0.3 y), one level pass of a ball of radius
  // 10 along x at the contact line y = 20. Downhill of the pass the normal
  // (0, -0.3, 1)/|.| leans away from it and meets the ball's flank far up:
  // close to the shadow's rim the distance along the normal exceeds the
  // 10 mm search range (NormalErrorOptions::max_distance). Brute force (a
  // 5 um scan of the ball envelope along the normal, then bisection): where
  // it meets the flank within the range, the error map has that number;
  // where it does not (beyond the range, or the normal leaves the shadow
  // first), the sample is uncut and has none. Values just under 10 mm are
  // thus real material left on the flank, not the range written as an
  // error.
  Part part;
  part.faces.emplace_back("slope", make_plane({0, 0, 0}, {40, 0, 0}, {0, 30, 9}));
  const double R = 10, range = NormalErrorOptions{}.max_distance;
  const Cutter ball("ball", R, R);
  const Eigen::Vector3d n = Eigen::Vector3d(0, -0.3, 1).normalized();
  const Eigen::Vector3d tip = Eigen::Vector3d(0, 20, 6) + R * n - R * Eigen::Vector3d::UnitZ();
  ZMap zmap(part_xy_extent(part), 0.1);
  zmap.cut(ball, {{{5, tip.y(), tip.z()}, {35, tip.y(), tip.z()}, 0, 0}});
  const ErrorMap map = compute_error_map(part, zmap);
  const FaceErrorMap& m = map.faces[0];
  auto brute = [&](const Eigen::Vector3d& q, bool& found) {
    auto g = [&](double t) {
      const Eigen::Vector3d x = q + t * n;
      return ball_pass_height(R, tip.z(), 5, 35, tip.y(), x.x(), x.y()) - x.z();
    };
    found = false;
    if (!std::isfinite(g(0))) return 0.0;
    double a = 0;
    for (double t = 5e-3; t <= range; t += 5e-3) {
      const double gt = g(t);
      if (!std::isfinite(gt)) return 0.0;  // left the shadow first: uncut
      if (gt <= 0) {
        double lo = a, hi = t;
        for (int k = 0; k < 60; ++k) (g(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
        found = true;
        return hi;
      }
      a = t;
    }
    return 0.0;
  };
  int compared = 0, near_range = 0, beyond = 0, mismatch = 0;
  double largest = 0;
  for (int j = 0; j < m.nv; ++j)
    for (int i = 0; i < m.nu; i += 7) {  // a spread of columns
      const double x = 40 * m.u(i), y = 30 * m.v(j);
      if (x < 12 || x > 28 || y > 20) continue;  // downhill of the pass, away from its ends
      const std::size_t k = m.index(i, j);
      if (m.boundary[k]) continue;
      bool found = false;
      const double e = brute({x, y, 0.3 * y}, found);
      if (found && std::abs(e - range) < 1e-3) continue;  // at the range itself: either way
      ++compared;
      const bool reached = m.status[k] == ErrorCellStatus::reached;
      if (reached != found) {
        ++mismatch;
        continue;
      }
      if (!found) {
        ++beyond;
        CHECK(m.error[k] == 0.0f);
        continue;
      }
      mismatch += std::abs(m.error[k] - e) > 1e-5;  // float storage
      near_range += e > 9;
      largest = std::max(largest, double(m.error[k]));
    }
  CHECK(mismatch == 0);
  CHECK(compared > 500);
  CHECK(near_range > 5);  // true crossings between 9 and 10 mm exist
  CHECK(beyond > 5);      // and samples beyond the range are uncut
  CHECK(largest < range);
}
