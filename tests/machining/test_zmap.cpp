#include <doctest/doctest.h>

#include <omp.h>

#include <cmath>
#include <random>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/furrow_step.hpp"
#include "machining/prediction/pass_scallops.hpp"
#include "machining/prediction/scallop.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

// Passes along y on a cylinder about the y axis (radius rho, convex or
// concave), contact angles psi_k = psi0 + k w / rho: straight moves along the
// axis, side step w (arc length) between passes.
std::vector<std::vector<PathContact>> cylinder_passes(const Part& part, const Cutter& cutter, double rho,
                                                      bool convex, double psi0, double w, int count,
                                                      std::vector<ZMapMove>& moves) {
  const VerticalProjector projector(part);
  std::vector<std::vector<PathContact>> passes;
  for (int k = 0; k < count; ++k) {
    const double psi = psi0 + k * w / rho;
    std::vector<PathContact> pass;
    Eigen::Vector3d tips[2];
    for (int e = 0; e < 2; ++e) {
      const double y = e == 0 ? 5.0 : 45.0;
      const SurfacePoint s = projector.project(rho * std::cos(psi), y);
      REQUIRE(s.valid);
      REQUIRE(std::fabs(s.point.z() - rho * std::sin(psi)) < 1e-9);
      REQUIRE(s.normal.dot(Eigen::Vector3d(std::cos(psi), 0, std::sin(psi))) == doctest::Approx(convex ? 1 : -1));
      tips[e] = cutter_location(cutter, s.point, s.normal).tip;
      pass.push_back(exact_contact(cutter, s));
    }
    moves.push_back({tips[0], tips[1], k, 0});
    passes.push_back(pass);
  }
  return passes;
}

}  // namespace

TEST_CASE("z-map nodes are the lowest swept envelope of all moves, whatever the thread count") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> c(0, 20), z(0, 3);
  const Cutter cutters[] = {Cutter("ball", 2, 2), Cutter("bull", 2.5, 0.5), Cutter("flat", 1.5, 0)};
  for (const Cutter& cutter : cutters) {
    std::vector<ZMapMove> moves;
    for (int k = 0; k < 25; ++k) moves.push_back({{c(rng), c(rng), z(rng)}, {c(rng), c(rng), z(rng)}, 0, k});
    const Eigen::AlignedBox2d extent(Eigen::Vector2d(0, 0), Eigen::Vector2d(20, 20));
    ZMap one(extent, 0.25), two(extent, 0.25);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    one.cut(cutter, moves);
    omp_set_num_threads(2);
    two.cut(cutter, {moves.begin(), moves.begin() + 10});
    two.cut(cutter, {moves.begin() + 10, moves.end()});  // in two batches
    omp_set_num_threads(threads);
    int mismatches = 0, wrong = 0;
    for (int j = 0; j < one.ny(); ++j)
      for (int i = 0; i < one.nx(); ++i) {
        mismatches += one.node_height(i, j) != two.node_height(i, j) || one.node_owner(i, j) != two.node_owner(i, j);
        double expected = std::numeric_limits<double>::infinity();
        int owner = -1;
        for (std::size_t m = 0; m < moves.size(); ++m) {
          const double h = SweptEnvelope(cutter, moves[m].from, moves[m].to).height_at(one.x(i), one.y(j));
          if (h < expected) expected = h, owner = static_cast<int>(m);
        }
        const double got = one.node_height(i, j);
        if (std::isfinite(expected) != std::isfinite(got) ||
            (std::isfinite(expected) && std::fabs(got - expected) > 1e-9) || one.node_owner(i, j) != owner)
          ++wrong;
      }
    CAPTURE(cutter.name());
    CHECK(mismatches == 0);
    CHECK(wrong == 0);
    CHECK(one.cut_node_count() > 0);
    CHECK(one.cut_node_count() < one.node_count());
  }
}

TEST_CASE("z-map of a dense path: threads and batches give the same bits as the plain sweep, on an odd grid") {
  // Zigzag passes of short moves over a wavy surface, 0.3 mm apart under a
  // 4 mm ball: every node lies under dozens of moves, so the sweep's
  // ordering and its bound-based skipping are exercised. The reference is
  // the plain sweep: every move in path order over its whole row span, the
  // first strictly lower height wins.
  const Cutter cutter("ball", 2, 2);
  std::vector<ZMapMove> moves;
  auto z = [](double x, double y) { return 0.4 * std::sin(0.7 * x) * std::cos(0.5 * y) + 0.02 * x; };
  for (int p = 0; p < 40; ++p) {
    const double y = 1 + 0.3 * p;
    for (int k = 0; k < 30; ++k) {
      const double xa = p % 2 ? 13 - 0.4 * k : 1 + 0.4 * k, xb = p % 2 ? xa - 0.4 : xa + 0.4;
      const double ya = y + 0.01 * k, yb = y + 0.01 * (k + 1);
      moves.push_back({{xa, ya, z(xa, ya)}, {xb, yb, z(xb, yb)}, p, k});
    }
  }
  const Eigen::AlignedBox2d extent(Eigen::Vector2d(-1.03, -1.03), Eigen::Vector2d(15.1, 15.45));
  const double cell = 0.043;
  ZMap one(extent, cell), two(extent, cell);
  REQUIRE(one.nx() % 2 == 1);
  REQUIRE(one.ny() % 2 == 1);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  one.cut(cutter, moves);
  omp_set_num_threads(2);
  two.cut(cutter, {moves.begin(), moves.begin() + 500});
  two.cut(cutter, {moves.begin() + 500, moves.end()});
  omp_set_num_threads(threads);
  std::vector<double> height(static_cast<std::size_t>(one.nx()) * one.ny(), std::numeric_limits<double>::infinity());
  std::vector<int> owner(height.size(), -1);
  std::vector<double> buffer(one.nx());
  for (std::size_t m = 0; m < moves.size(); ++m) {
    const SweptEnvelope env(cutter, moves[m].from, moves[m].to);
    for (int j = 0; j < one.ny(); ++j) {
      double xl = 0, xh = 0;
      if (!env.row_span(one.y(j), xl, xh)) continue;
      const int i0 = static_cast<int>(std::max(0.0, std::ceil((xl - one.x(0)) / cell)));
      const int i1 = static_cast<int>(std::min(double(one.nx() - 1), std::floor((xh - one.x(0)) / cell)));
      if (i1 < i0) continue;
      env.row(one.y(j), one.x(i0), cell, i1 - i0 + 1, buffer.data());
      for (int i = i0; i <= i1; ++i) {
        const std::size_t at = static_cast<std::size_t>(j) * one.nx() + i;
        if (buffer[i - i0] < height[at]) height[at] = buffer[i - i0], owner[at] = static_cast<int>(m);
      }
    }
  }
  int threads_differ = 0, plain_differs = 0;
  for (int j = 0; j < one.ny(); ++j)
    for (int i = 0; i < one.nx(); ++i) {
      const std::size_t at = static_cast<std::size_t>(j) * one.nx() + i;
      threads_differ += one.node_height(i, j) != two.node_height(i, j) || one.node_owner(i, j) != two.node_owner(i, j);
      plain_differs += one.node_height(i, j) != height[at] || one.node_owner(i, j) != owner[at];
    }
  CHECK(threads_differ == 0);
  CHECK(plain_differs == 0);
  CHECK(one.cut_node_count() > one.node_count() / 2);
}

TEST_CASE("reference step through the z-map: -0.100 mm at mid-step, as the per-step predictor says") {
  const Part part = read_part(example("semi_cylinder.json"));
  const VerticalProjector projector(part);
  const Cutter ball("ball", 12.7, 12.7);
  const double rho = 25.4, half = 0.5 * 3.68 / rho;
  const SurfacePoint a = projector.project(rho * std::cos(M_PI / 2 + half), 25.4);
  const SurfacePoint b = projector.project(rho * std::cos(M_PI / 2 - half), 25.4);
  const Eigen::Vector3d t0 = cutter_location(ball, a.point, a.normal).tip;
  const Eigen::Vector3d t1 = cutter_location(ball, b.point, b.normal).tip;
  ZMap zmap(part_xy_extent(part), 0.05);
  zmap.cut(ball, {{t0, t1, 0, 0}});
  const Eigen::Vector3d top(0, 25.4, 25.4), up(0, 0, 1);
  const NormalError e = zmap_error(zmap, top, up);
  REQUIRE(e.reached);
  CHECK(std::fabs(e.error - (-0.100)) <= 0.001);
  CHECK(std::fabs(e.error + (rho + 12.7) * (1 - std::cos(half))) < 1e-7);
  const FurrowStepResult step = furrow_step_error(ball, vertical_section_curve(projector, a, b));
  CHECK(std::fabs(e.error - step.overcut.error) < 1e-7);
  // The plain bilinear z-map agrees within its interpolation error
  // (cell^2 / (8 R) on the ball's smooth bottom).
  auto interpolated = [&](double x, double y) { return zmap.interpolated_height_at(x, y); };
  const NormalError ei = normal_error(interpolated, top, up);
  CHECK(std::fabs(ei.error - e.error) <= 0.05 * 0.05 / (8 * 12.7) + 1e-9);
}

TEST_CASE("flat plane, parallel passes: the z-map scallop is the ball formula, for the side step it inverts") {
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {40, 0, 0}, {0, 30, 0}));
  const VerticalProjector projector(part);
  const double r = 3.0;
  const Cutter ball("ball", r, r);
  for (double h : {0.002, 0.005, 0.02}) {
    const SideStepResult step = ball_side_step_for_scallop(r, 0.0, h);
    REQUIRE(step.converged);
    const double w = step.side_step;
    CHECK(w == doctest::Approx(2 * std::sqrt(2 * r * h - h * h)).epsilon(1e-10));
    std::vector<ZMapMove> moves;
    std::vector<std::vector<PathContact>> passes;
    for (int k = 0; k < 6; ++k) {
      const double y = 10 + k * w;
      const SurfacePoint s0 = projector.project(5, y), s1 = projector.project(35, y);
      moves.push_back({s0.point, s1.point, k, 0});  // tips = contacts on a plane
      passes.push_back({exact_contact(ball, s0), exact_contact(ball, s1)});
    }
    ZMap zmap(part_xy_extent(part), 0.05);
    zmap.cut(ball, moves);
    const auto scallops = pass_pair_scallops(projector, zmap, ball, passes);
    REQUIRE(scallops.size() == 5);
    for (const PassScallop& s : scallops) {
      CAPTURE(h);
      // Straight passes leave no furrow along them: ridge and cusp agree.
      for (const ScallopPeak& peak : {s.ridge, s.cusp}) {
        REQUIRE(peak.found);
        CHECK(std::abs(peak.height - h) < 1e-7);  // mm: a top found to 1e-6 mm along the section
        // The ridge lies half-way between the passes.
        CHECK(peak.at.point.y() == doctest::Approx(10 + (s.pass_a + 0.5) * w).epsilon(1e-6));
      }
    }
    // The plain bilinear z-map misses the cusp by at most its slope times half
    // a cell (here sqrt(2h/r) on each side of the ridge).
    auto interpolated = [&](double x, double y) { return zmap.interpolated_height_at(x, y); };
    const double ridge_y = 10 + 2.5 * w;
    double worst = 0;
    for (int k = 0; k <= 200; ++k) {
      const double y = ridge_y - 0.05 + 0.1 * k / 200;
      const NormalError e = normal_error(interpolated, Eigen::Vector3d(20.013, y, 0), Eigen::Vector3d::UnitZ());
      worst = std::max(worst, e.error);
    }
    const double slope = (0.5 * w) / std::sqrt(r * r - 0.25 * w * w);
    CHECK(worst <= h + 1e-12);
    CHECK(worst >= h - slope * 0.5 * 0.05 - 1e-9);
  }
}

TEST_CASE("convex and concave cylinders, passes along the axis: z-map scallops follow the curved formula") {
  const Part convex = read_part(example("semi_cylinder.json"));
  Part concave;
  concave.faces.emplace_back("tube", make_cylinder(25.4, 50.8, -M_PI, 0.0));
  const double rho = 25.4, r = 4.0;
  const Cutter ball("ball", r, r);
  for (int is_convex = 0; is_convex < 2; ++is_convex) {
    const Part& part = is_convex ? convex : concave;
    const double k = is_convex ? -1 / rho : 1 / rho;
    const double psi0 = is_convex ? M_PI / 2 - 0.3 : -M_PI / 2 - 0.3;
    const SideStepResult step = ball_side_step_for_scallop(r, k, 0.01);
    REQUIRE(step.converged);
    std::vector<ZMapMove> moves;
    const auto passes = cylinder_passes(part, ball, rho, is_convex, psi0, step.side_step, 5, moves);
    ZMap zmap(part_xy_extent(part), 0.05);
    zmap.cut(ball, moves);
    const VerticalProjector projector(part);
    const auto scallops = pass_pair_scallops(projector, zmap, ball, passes);
    REQUIRE(scallops.size() == 4);
    const double expected = *ball_scallop_height(r, k, step.side_step);
    CHECK(expected == doctest::Approx(0.01).epsilon(1e-9));
    for (const PassScallop& s : scallops) {
      CAPTURE(is_convex);
      for (const ScallopPeak& peak : {s.ridge, s.cusp}) {
        REQUIRE(peak.found);
        CHECK(std::abs(peak.height - expected) < 1e-7);  // mm, as above
      }
    }
    // The same side step on the other curvature gives a different scallop:
    // the check above is not blind to the sign of k.
    CHECK(std::fabs(*ball_scallop_height(r, -k, step.side_step) - expected) > 1e-3);
  }
}

TEST_CASE("error map: statuses, cell summaries and extremes on a partly machined plane") {
  Part part;
  part.faces.emplace_back("plane", make_plane({0, 0, 0}, {20, 0, 0}, {0, 10, 0}));
  const Cutter ball("ball", 2, 2);
  // One level pass 0.01 mm too low along y = 5 from x = 4 to 16: it overcuts
  // by 0.01 under the ball's bottom; the rest of the plane is not reached.
  ZMap zmap(part_xy_extent(part), 0.05);
  zmap.cut(ball, {{{4, 5, -0.01}, {16, 5, -0.01}, 0, 0}});
  ErrorMapOptions options;
  options.cell_size = 1.0;
  const ErrorMap map = compute_error_map(part, zmap, options);
  REQUIRE(map.faces.size() == 1);
  const FaceErrorMap& m = map.faces[0];
  CHECK(m.cells_u == 20);
  CHECK(m.cells_v == 10);
  CHECK(m.nu == 20 * m.block_u);
  CHECK(map.reached > 0);
  CHECK(map.not_reached > 0);
  CHECK(map.reached + map.not_reached == map.samples);
  REQUIRE(map.max_overcut.found);
  CHECK(map.max_overcut.error == doctest::Approx(-0.01).epsilon(1e-9));
  // The ball's rim rises above the plane: positive errors where the shadow
  // ends (the normal meets the ball's flank).
  REQUIRE(map.max_undercut.found);
  CHECK(map.max_undercut.error > 0);
  int reached_cells = 0;
  for (const ErrorCell& c : m.cells) {
    if (c.status != ErrorCellStatus::reached) continue;
    ++reached_cells;
    CHECK(c.max_overcut <= c.mean);
    CHECK(c.mean <= c.max_undercut);
    CHECK(c.max_overcut >= -0.01 - 1e-7);
  }
  // The shadow is 4 mm wide and 16 mm long: about 16 x 4 cells.
  CHECK(reached_cells >= 12 * 4);
  CHECK(reached_cells <= 18 * 6);
}
