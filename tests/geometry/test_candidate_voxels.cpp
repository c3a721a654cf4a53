// The voxel lists of the closest-point search (geometry/candidate_voxels.hpp)
// must never change an answer. Oracles: the same finder without the lists
// (the box-tree walk alone, itself checked against brute force in
// test_closest_point.cpp) on thousands of points, and the brute-force
// closest point (support/closest_point_oracle.hpp) on points in the lattice
// where pruning is delicate: past a dimple's centre of curvature, about a
// concave tube's axis, across a seam, over a trimmed hole, far off the part.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <thread>

#include "geometry/candidate_voxels.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/primitives.hpp"
#include "geometry/seed_grid.hpp"
#include "io/part_file.hpp"
#include "support/closest_point_oracle.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

Part single_face(NurbsSurface s, Trim trim = {}) {
  Part p;
  p.faces.emplace_back("face", std::move(s), std::move(trim), false);
  return p;
}

Part mould() { return read_part(test::source_path("examples/parts/mould.json")); }

Part mould_with_hole() {
  Part part = mould();
  const Face& f = part.faces[0];
  UvLoop hole;
  for (int k = 0; k < 40; ++k)
    hole.emplace_back(0.35 + 0.15 * std::cos(2 * M_PI * k / 40), 0.5 + 0.15 * std::sin(2 * M_PI * k / 40));
  part.faces[0] = Face(f.name(), f.surface(), Trim({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, hole}), f.reversed());
  return part;
}

struct Shape {
  std::string name;
  Part part;
};

std::vector<Shape> shapes() {
  std::vector<Shape> out;
  out.push_back({"mould", mould()});
  out.push_back({"mould with a hole", mould_with_hole()});
  out.push_back({"concave half tube", single_face(make_cylinder(30, 60, M_PI, 2 * M_PI))});
  out.push_back({"closed tube with a seam", single_face(make_cylinder(25, 40, 0, 2 * M_PI))});
  return out;
}

// Points near and far off the surface (along the normal, up to 40 mm) and
// uniform in the part's box grown by its largest side on every side: the
// lattice covers a quarter of that side, so both paths are taken.
std::vector<Eigen::Vector3d> query_points(const Part& part, int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1), offset(-40, 40);
  const Eigen::AlignedBox3d box = part.control_box();
  const double grow = box.sizes().maxCoeff();
  const Eigen::Vector3d lo = box.min().array() - grow, hi = box.max().array() + grow;
  std::vector<Eigen::Vector3d> out;
  const Face& face = part.faces[0];
  const ParameterDomain& d = face.domain();
  for (int k = 0; k < count; ++k) {
    if (k % 2) {
      out.push_back(lo + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(hi - lo));
    } else {
      const DifferentialGeometry g = face.geometry(d.u0 + unit(rng) * d.width_u(), d.v0 + unit(rng) * d.width_v());
      out.push_back(g.point + offset(rng) * g.normal);
    }
  }
  return out;
}

// Whether q is in the lattice: asked until its cube's list is built.
bool in_lattice(const CandidateVoxels& lattice, const Eigen::Vector3d& q) {
  for (int ask = 0; ask <= CandidateVoxels::kQueriesBeforeList; ++ask)
    if (lattice.cells_near(q)) return true;
  return false;
}

}  // namespace

TEST_CASE("voxel lists give the tree walk's answer on thousands of points in and around the lattice") {
  for (const Shape& shape : shapes()) {
    CAPTURE(shape.name);
    const ClosestPointFinder with_lists(shape.part);
    ClosestPointOptions tree_only;
    tree_only.candidate_voxels = false;
    const ClosestPointFinder walk(shape.part, tree_only);
    const SeedGrid grid(shape.part, ClosestPointOptions{});
    const CandidateVoxels lattice(grid);
    int inside = 0, outside = 0, differ = 0;
    for (const Eigen::Vector3d& q : query_points(shape.part, 4000, 11)) {
      (in_lattice(lattice, q) ? inside : outside) += 1;
      with_lists.project(q);  // the cube's first query walks; the second takes its list
      const ClosestPoint a = with_lists.project(q), b = walk.project(q);
      if (!(std::abs(a.distance - b.distance) <= 1e-9) || !a.converged) {
        ++differ;
        CAPTURE(q.transpose());
        CHECK(a.distance == doctest::Approx(b.distance).epsilon(0).scale(1e-9));
      }
    }
    CHECK(differ == 0);
    // Both paths were taken, the lattice's many times over.
    CHECK(inside > 1000);
    CHECK(outside > 100);
  }
}

TEST_CASE("voxel lists: points in the lattice where pruning is delicate agree with brute force") {
  for (const Shape& shape : shapes()) {
    CAPTURE(shape.name);
    const ClosestPointFinder finder(shape.part);
    const SeedGrid grid(shape.part, ClosestPointOptions{});
    const CandidateVoxels lattice(grid);
    int checked = 0;
    for (const Eigen::Vector3d& q : query_points(shape.part, 200, 23)) {
      if (!in_lattice(lattice, q) || checked == 25) continue;
      ++checked;
      finder.project(q);
      const ClosestPoint c = finder.project(q);
      const test::Oracle o = test::brute_force(shape.part, q);
      CAPTURE(q.transpose());
      CHECK(c.converged);
      CHECK(std::abs(c.distance - o.distance) <= 1e-9);
    }
    CHECK(checked == 25);
  }
}

TEST_CASE("voxel lattice: a list per cube, built once, and none for points outside it or not finite") {
  const Part part = mould();
  const SeedGrid grid(part, ClosestPointOptions{});
  const CandidateVoxels lattice(grid);
  REQUIRE(lattice.voxel_count() > 0);
  CHECK(lattice.voxel_count() <= CandidateVoxels::kMaxVoxels);
  // About kVoxelsPerCell cubes per cell (the rounding up of the lattice's
  // sides adds at most its surface).
  const double per_cell = static_cast<double>(lattice.voxel_count()) / static_cast<double>(grid.cells().size());
  CHECK(per_cell >= CandidateVoxels::kVoxelsPerCell);
  CHECK(per_cell <= 1.5 * CandidateVoxels::kVoxelsPerCell);
  const Eigen::Vector3d middle = grid.nodes()[0].box.center();
  // The first query in a cube walks the tree; the second builds the list,
  // and later ones get that same list.
  CHECK(!lattice.cells_near(middle));
  const CandidateCells list = lattice.cells_near(middle);
  REQUIRE(list);
  CHECK(list.count > 0);
  CHECK(lattice.cells_near(middle).cells == list.cells);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& q : {Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d(0, inf, 0), Eigen::Vector3d(0, 0, -inf),
                                   Eigen::Vector3d(1e308, 1e308, 1e308), Eigen::Vector3d(middle.x(), middle.y(), 1e6)})
    for (int ask = 0; ask < 3; ++ask) CHECK(!lattice.cells_near(q));
  // Every list names cells of the grid, each once.
  int lists = 0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const Eigen::AlignedBox3d box = grid.nodes()[0].box;
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d q = box.min() + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(box.sizes());
    lattice.cells_near(q);
    const CandidateCells cells = lattice.cells_near(q);
    REQUIRE(cells);
    std::vector<std::uint32_t> sorted(cells.begin(), cells.end());
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    CHECK((sorted.empty() || sorted.back() < grid.cells().size()));
    lists += !sorted.empty();
  }
  CHECK(lists == 500);
}

TEST_CASE("voxel lists: two threads racing to build the same cubes get one thread's answers") {
  const Part part = mould();
  const std::vector<Eigen::Vector3d> points = query_points(part, 6000, 31);
  const ClosestPointFinder serial(part);
  std::vector<double> expected(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) expected[k] = serial.project(points[k]).distance;
  // A fresh finder: the cubes' lists are built while both threads ask for them.
  const ClosestPointFinder shared(part);
  std::vector<double> forward(points.size()), backward(points.size());
  std::thread a([&] {
    for (std::size_t k = 0; k < points.size(); ++k) forward[k] = shared.project(points[k]).distance;
  });
  std::thread b([&] {
    for (std::size_t k = points.size(); k-- > 0;) backward[k] = shared.project(points[k]).distance;
  });
  a.join();
  b.join();
  int differ = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
    differ += !(forward[k] == expected[k] && backward[k] == expected[k]);
  CHECK(differ == 0);
}
