// Partition of faces whose curvature classes and areas are known exactly.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/primitives.hpp"
#include "partition/curvature_field.hpp"
#include "partition/curvature_tolerance.hpp"
#include "partition/partition.hpp"
#include "partition/region_checks.hpp"
#include "partition/test_faces.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

Part single(Face face) {
  Part p;
  p.faces.push_back(std::move(face));
  return p;
}

}  // namespace

TEST_CASE("sphere cap: one convex region with outward normal, concave when reversed") {
  const double R = 30, lat0 = 0.35;
  const double cap_area = 2 * M_PI * R * R * (1 - std::sin(lat0));
  for (const bool reversed : {false, true}) {
    CAPTURE(reversed);
    const Part part = single(Face("cap", make_sphere(R, 0, 2 * M_PI, lat0, M_PI / 2), {}, reversed));
    const PartitionResult res = partition_part(part, grid(360, 200));
    REQUIRE(res.map.regions.size() == 1);
    const Region& r = res.map.regions[0];
    CHECK(r.curvature_class == (reversed ? CurvatureClass::concave : CurvatureClass::convex));
    CHECK(r.area == doctest::Approx(cap_area).epsilon(1e-3));
    // Umbilic everywhere: k1 = k2 = -+1/R.
    CHECK(r.k1.mean == doctest::Approx((reversed ? 1 : -1) / R).epsilon(1e-9));
    CHECK(r.K.mean == doctest::Approx(1 / (R * R)).epsilon(1e-9));
    CHECK(r.border.size() == 1);
    check_region_at_matches_labels(res);
  }
}

TEST_CASE("cylinder: concave inside, convex outside, never saddle, even with tiny eps") {
  const double R = 20, L = 50, a0 = 0.3, a1 = 2.6;
  for (const bool reversed : {false, true}) {
    for (const double eps : {-1.0, 1e-9}) {  // -1: the default
      CAPTURE(reversed);
      CAPTURE(eps);
      PartitionOptions o = grid(300, 120);
      if (eps > 0) o.eps = eps;
      const PartitionResult res = partition_part(single(Face("cyl", make_cylinder(R, L, a0, a1), {}, reversed)), o);
      // Cell by cell, before any merging could hide a saddle speck.
      int saddles = 0;
      for (unsigned char c : res.cells[0].cell_class) saddles += c == static_cast<unsigned char>(CurvatureClass::saddle);
      CHECK(saddles == 0);
      REQUIRE(res.map.regions.size() == 1);
      CHECK(res.map.regions[0].curvature_class ==
            (reversed ? CurvatureClass::convex : CurvatureClass::concave));
      CHECK(res.map.regions[0].area == doctest::Approx(R * (a1 - a0) * L).epsilon(1e-4));
      CHECK(res.map.regions[0].absorbed_area == 0.0);
    }
  }
}

TEST_CASE("plane: one planar region with the exact area and a rectangular border") {
  const Part part = single(Face("plane", make_plane({1, 2, 3}, {40, 0, 5}, {0, 30, 0})));
  const PartitionResult res = partition_part(part, PartitionOptions{});
  REQUIRE(res.map.regions.size() == 1);
  const Region& r = res.map.regions[0];
  CHECK(r.curvature_class == CurvatureClass::planar);
  // Exact cell by cell; the sum of 64000 cells rounds at ~1e-12.
  CHECK(r.area == doctest::Approx(Eigen::Vector3d(40, 0, 5).cross(Eigen::Vector3d(0, 30, 0)).norm()).epsilon(1e-10));
  REQUIRE(r.border.size() == 1);
  // A straight border on a plane thins to its four corners, in uv and xyz.
  CHECK(r.border[0].uv.size() == 4);
  CHECK(!r.border[0].hole);
  CHECK((r.border[0].xyz[0] - Eigen::Vector3d(1, 2, 3)).norm() < 1e-12);
  CHECK(r.neighbours.empty());
  CHECK(res.map.faces[0].eps == kEpsFloor);
}

TEST_CASE("hyperbolic paraboloid: one saddle region, area against a Simpson quadrature") {
  // z = h x y / (X Y) over [0, X] x [0, Y]: K < 0 everywhere.
  const double X = 60, Y = 40, h = 25;
  const Part part = single(Face("hypar", make_bilinear({0, 0, 0}, {X, 0, 0}, {0, Y, 0}, {X, Y, h})));
  const PartitionResult res = partition_part(part, grid(300, 200));
  REQUIRE(res.map.regions.size() == 1);
  CHECK(res.map.regions[0].curvature_class == CurvatureClass::saddle);
  const double c = h / (X * Y);
  const double area = simpson2d(
      [c](double x, double y) { return std::sqrt(1 + c * c * (x * x + y * y)); }, 0, X, 0, Y);
  CHECK(res.map.regions[0].area == doctest::Approx(area).epsilon(1e-4));
  CHECK(res.map.regions[0].K.max < 0);
}

TEST_CASE("a patch with exactly one convex, one concave and one saddle area with known borders") {
  // z = alpha (x - x0)^3 + beta (y - y0)^3: the Hessian is diagonal with signs
  // of (x - x0) and (y - y0), so for x < x0, y < y0 the face is convex, for
  // x > x0, y > y0 concave, and saddle in the other two quadrants. Trimming
  // away the quadrant x < x0, y > y0 leaves exactly three areas whose borders
  // are the straight lines x = x0 and y = y0.
  const double X = 100, Y = 80, x0 = 43.3, y0 = 36.7, alpha = 2e-4, beta = 2.5e-4;
  const NurbsSurface s = separable_cubic_patch(X, Y, shifted_cube(alpha, x0, X), shifted_cube(beta, y0, Y));
  const double ut = x0 / X, vt = y0 / Y;
  const Trim trim({{{0, 0}, {1, 0}, {1, 1}, {ut, 1}, {ut, vt}, {0, vt}}});
  const Part part = single(Face("three", s, trim));
  auto element = [&](double x, double y) {
    const double fx = 3 * alpha * (x - x0) * (x - x0), fy = 3 * beta * (y - y0) * (y - y0);
    return std::sqrt(1 + fx * fx + fy * fy);
  };
  const double convex = simpson2d(element, 0, x0, 0, y0);
  const double saddle = simpson2d(element, x0, X, 0, y0);
  const double concave = simpson2d(element, x0, X, y0, Y);

  SUBCASE("eps 0: the borders are exactly the zero lines; areas within 1 %") {
    PartitionOptions o = grid(400, 320);
    o.eps = 0.0;
    const PartitionResult res = partition_part(part, o);
    REQUIRE(res.map.regions.size() == 3);
    double found[4] = {0, 0, 0, 0};
    for (const Region& r : res.map.regions) found[static_cast<int>(r.curvature_class)] += r.area;
    CHECK(found[static_cast<int>(CurvatureClass::convex)] == doctest::Approx(convex).epsilon(0.01));
    CHECK(found[static_cast<int>(CurvatureClass::saddle)] == doctest::Approx(saddle).epsilon(0.01));
    CHECK(found[static_cast<int>(CurvatureClass::concave)] == doctest::Approx(concave).epsilon(0.01));
    CHECK(found[static_cast<int>(CurvatureClass::planar)] == 0.0);
    // Nothing of the trimmed quadrant belongs to a region.
    CHECK(!res.map.region_at(0, 0.2, 0.8).has_value());
    CHECK(res.map.region_at(0, 0.2, 0.2).has_value());
    CHECK(res.map.faces[0].trimmed_cells > 0);
    // The convex region's uv box is the lower-left quadrant, to a cell.
    for (const Region& r : res.map.regions) {
      if (r.curvature_class != CurvatureClass::convex) continue;
      CHECK(std::fabs(r.uv_box.max().x() - ut) <= 0.5 / 400);
      CHECK(std::fabs(r.uv_box.max().y() - vt) <= 0.5 / 320);
      CHECK(r.uv_box.min().x() == 0.0);
      CHECK(r.uv_box.min().y() == 0.0);
      CHECK(r.neighbours.size() == 1);  // the saddle; it touches concave only at a corner
    }
    check_region_at_matches_labels(res);
  }

  SUBCASE("default eps: the same three regions, borders shifted by the tolerance band") {
    const PartitionResult res = partition_part(part, grid(400, 320));
    REQUIRE(res.map.regions.size() == 3);
    int per_class[4] = {0, 0, 0, 0};
    for (const Region& r : res.map.regions) ++per_class[static_cast<int>(r.curvature_class)];
    CHECK(per_class[static_cast<int>(CurvatureClass::convex)] == 1);
    CHECK(per_class[static_cast<int>(CurvatureClass::saddle)] == 1);
    CHECK(per_class[static_cast<int>(CurvatureClass::concave)] == 1);
    // Within eps of zero a principal curvature counts as zero, so a band of
    // saddle next to the lines turns convex or concave: the saddle area
    // shrinks and the others grow by a band ~ eps / |dk/dx| wide (a few
    // tenths of a mm here), still within 2 %.
    double found[4] = {0, 0, 0, 0};
    for (const Region& r : res.map.regions) found[static_cast<int>(r.curvature_class)] = r.area;
    CHECK(found[static_cast<int>(CurvatureClass::saddle)] < saddle);
    CHECK(found[static_cast<int>(CurvatureClass::convex)] > convex);
    CHECK(found[static_cast<int>(CurvatureClass::concave)] > concave);
    CHECK(found[static_cast<int>(CurvatureClass::saddle)] == doctest::Approx(saddle).epsilon(0.02));
    CHECK(found[static_cast<int>(CurvatureClass::convex)] == doctest::Approx(convex).epsilon(0.02));
    CHECK(found[static_cast<int>(CurvatureClass::concave)] == doctest::Approx(concave).epsilon(0.02));
    // The total only moves with the trim border, resolved to half a cell.
    CHECK(total_region_area(res.map) == doctest::Approx(convex + saddle + concave).epsilon(1e-3));
  }
}

TEST_CASE("nearly flat patch with ripples below eps stays one planar region") {
  // Ripples of amplitude a and wavelength w have curvature ~ a (2 pi / w)^2.
  const double a = 4e-4, w = 20;
  const NurbsSurface s = height_field_patch(100, 100, 40, [&](double x, double y) {
    return a * std::sin(2 * M_PI * x / w) * std::sin(2 * M_PI * y / w);
  });
  const Part part = single(Face("ripples", s));
  // Precondition of the test: the ripples are real but below the default eps.
  const CurvatureField field = compute_curvature_field(part.faces[0], 200, 200);
  double kmax = 0;
  for (const CurvatureSample& c : field.samples) kmax = std::max({kmax, std::fabs(c.k1), std::fabs(c.k2)});
  REQUIRE(kmax < kEpsFloor);
  REQUIRE(kmax > 0.2 * kEpsFloor);

  const PartitionResult res = partition_part(part, grid(200, 200));
  REQUIRE(res.map.regions.size() == 1);
  CHECK(res.map.regions[0].curvature_class == CurvatureClass::planar);
  CHECK(res.map.regions[0].merged_components == 1);  // planar cell by cell, nothing merged

  // The same ripples with eps far below them fall apart into many regions.
  PartitionOptions fine = grid(200, 200);
  fine.eps = 1e-7;
  fine.min_area = 0;
  CHECK(partition_part(part, fine).map.regions.size() > 10);
}

TEST_CASE("a degenerate parameter line marks its cells invalid and splits the face, no failure") {
  // Degree 2 in u with two equal control columns: Su = 0 along u = 0.5.
  std::vector<std::vector<Eigen::Vector3d>> net;
  for (double x : {0.0, 30.0, 30.0, 60.0}) net.push_back({{x, 0, 0}, {x, 40, 0}});
  const NurbsSurface s(2, 1, {0, 0, 0, 0.5, 1, 1, 1}, {0, 0, 1, 1}, net);
  const Part part = single(Face("pinched", s));
  const PartitionResult res = partition_part(part, grid(11, 20));  // column 5 is centred on u = 0.5
  const RegionFace& info = res.map.faces[0];
  CHECK(info.degenerate_cells == 20);
  CHECK(info.valid_cells == 200);
  REQUIRE(res.map.regions.size() == 2);
  for (const Region& r : res.map.regions) CHECK(r.curvature_class == CurvatureClass::planar);
  for (int j = 0; j < 20; ++j) CHECK(res.cells[0].labels.at(5, j) == -1);
  CHECK(total_region_area(res.map) == doctest::Approx(info.area).epsilon(1e-12));
  check_region_at_matches_labels(res);
}

TEST_CASE("spacing in mm gives cells of about that size on the surface") {
  const Part part = single(Face("plane", make_plane({0, 0, 0}, {90, 0, 0}, {0, 36, 0})));
  PartitionOptions o;
  o.spacing = 0.5;
  const PartitionResult res = partition_part(part, o);
  CHECK(res.map.faces[0].nu == 180);
  CHECK(res.map.faces[0].nv == 72);
  // Default: the longest side gets kDefaultCellsAlongLongestSide cells.
  const PartitionResult def = partition_part(part, PartitionOptions{});
  CHECK(def.map.faces[0].nu == kDefaultCellsAlongLongestSide);
  CHECK(def.map.faces[0].nv == 160);
}
