// The cells' screening (seed_grid.hpp): a cell is only ever skipped when it
// cannot hold the answer. Oracle: points built to have a known orthogonal
// foot - a surface point p of the cell pushed along its normal, q = p + t n(p)
// - must never be screened out of p's cell, whatever t (near, far, past the
// centre of curvature, below the surface), on shapes whose normals turn fast.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "geometry/primitives.hpp"
#include "geometry/seed_grid.hpp"
#include "io/part_file.hpp"
#include "support/random_surface.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

struct Screened {
  int tested = 0, pruned_elsewhere = 0;
};

// For random points of every cell with a cone, q = p + t n: the cell's
// screen must keep q and give a lower bound no larger than |q - p|.
void check_cells_keep_their_feet(const Part& part, std::mt19937& rng, Screened& count) {
  const SeedGrid grid(part, ClosestPointOptions{});
  std::uniform_real_distribution<double> unit(0.0, 1.0), height(-60.0, 60.0);
  for (std::size_t index = 0; index < grid.cells().size(); ++index) {
    const SeedCell& cell = grid.cells()[index];
    const CellBounds& bounds = grid.bounds()[index];
    const Face& face = part.faces[cell.face];
    // The upper-bound sample is a kept surface point of this cell.
    bool sample_found = false;
    for (int k = 0; k < 5; ++k)
      if (cell.sample_kept >> k & 1u)
        sample_found = sample_found ||
                       (face.surface().point(cell.sample_uv[k].x(), cell.sample_uv[k].y()) - bounds.surface_point)
                               .norm() < 1e-12 * (1 + bounds.surface_point.norm());
    CHECK(sample_found == (cell.sample_kept != 0));
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector2d uv = cell.lo + Eigen::Vector2d(unit(rng), unit(rng)).cwiseProduct(cell.hi - cell.lo);
      const DifferentialGeometry g = face.geometry(uv.x(), uv.y());
      if (g.degenerate) continue;
      const double t = k == 0 ? 0.0 : k == 1 ? 1e-9 : height(rng);
      const Eigen::Vector3d q = g.point + t * g.normal;
      CAPTURE(uv.transpose());
      CAPTURE(t);
      // The oriented box holds the cell's surface.
      CHECK(((bounds.axes * (g.point - bounds.centre)).cwiseAbs() - bounds.half_extent).maxCoeff() <= 0);
      CHECK(bounds.may_hold_foot(q));
      const double reach = std::abs(t) * (1 + 1e-12) + 1e-9;
      CHECK(bounds.squared_screen(q) <= reach * reach);
      ++count.tested;
      // The same q is screened out of some other cells: the test has teeth.
      for (const CellBounds& other : grid.bounds())
        if (&other != &bounds && !other.may_hold_foot(q)) {
          ++count.pruned_elsewhere;
          break;
        }
    }
  }
}

}  // namespace

TEST_CASE("a cell is never screened out for a point whose orthogonal foot lies in it") {
  std::mt19937 rng(4);
  Screened count;
  SUBCASE("mould") {
    check_cells_keep_their_feet(read_part(test::source_path("examples/parts/mould.json")), rng, count);
  }
  SUBCASE("sphere, concave and convex") {
    for (bool reversed : {false, true}) {
      Part part;
      part.faces.emplace_back("sphere", make_sphere(12, 0, 2 * M_PI, -1.2, 1.2), Trim{}, reversed);
      check_cells_keep_their_feet(part, rng, count);
    }
  }
  SUBCASE("random rational surfaces of degrees 2, 3 and 5") {
    for (int degree : {2, 3, 5}) {
      Part part;
      part.faces.emplace_back("random", test::random_surface(rng, degree, 3, true, true));
      check_cells_keep_their_feet(part, rng, count);
    }
  }
  CHECK(count.tested > 100);
  CHECK(count.pruned_elsewhere > count.tested / 2);
}
