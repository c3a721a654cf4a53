// Grid choice from a spacing in mm, and the default curvature tolerance.
#include <doctest/doctest.h>

#include <cmath>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "partition/curvature_field.hpp"
#include "partition/curvature_tolerance.hpp"
#include "partition/face_grid.hpp"
#include "partition/partition.hpp"

using namespace furrow;

TEST_CASE("face extent: lengths on the surface along u and v") {
  const Face plane("p", make_plane({0, 0, 0}, {70, 0, 0}, {0, 20, 15}));
  const FaceExtent p = face_extent(plane);
  CHECK(p.length_u == doctest::Approx(70).epsilon(1e-12));
  CHECK(p.length_v == doctest::Approx(25).epsilon(1e-12));
  // A quarter cylinder of radius 20 and length 40: an arc of 10 pi along u.
  const Face cyl("c", make_cylinder(20, 40, 0, M_PI / 2));
  const FaceExtent c = face_extent(cyl);
  CHECK(c.length_u == doctest::Approx(10 * M_PI).epsilon(1e-3));
  CHECK(c.length_u < 10 * M_PI);  // chords underestimate
  CHECK(c.length_v == doctest::Approx(40).epsilon(1e-12));
  // A sphere cap up to the pole: the collapsed edge has length 0, the
  // longest parallel is the base circle.
  const Face cap("s", make_sphere(10, 0, 2 * M_PI, 0.0, M_PI / 2));
  CHECK(face_extent(cap).length_u == doctest::Approx(20 * M_PI).epsilon(1e-3));
}

TEST_CASE("grid for a spacing: whole counts, a minimum, and a clear limit") {
  const FaceExtent e{90, 36};
  const GridSize g = grid_for_spacing(e, 0.5, "f");
  CHECK(g.nu == 180);
  CHECK(g.nv == 72);
  const GridSize h = grid_for_spacing(e, 0.7, "f");
  CHECK(h.nu == static_cast<int>(std::ceil(90 / 0.7)));
  const GridSize coarse = grid_for_spacing(e, 50, "f");
  CHECK(coarse.nu == kMinCellsPerDirection);
  CHECK(coarse.nv == kMinCellsPerDirection);
  CHECK_THROWS_WITH_AS(grid_for_spacing(e, 0.001, "wing"), doctest::Contains("face \"wing\": spacing 0.001 mm"),
                       InputError);
  CHECK_THROWS_AS(grid_for_spacing(e, 0, "f"), InputError);
  CHECK_THROWS_AS(check_grid({0, 4}, "f"), InputError);
  CHECK_THROWS_AS(check_grid({kMaxCellsPerDirection + 1, 4}, "f"), InputError);
  CHECK_NOTHROW(check_grid({kMaxCellsPerDirection, 500}, "f"));
  CHECK(default_spacing({{90, 36}, {120, 5}}) == doctest::Approx(120.0 / kDefaultCellsAlongLongestSide));
  CHECK_THROWS_AS(default_spacing({{0, 0}}), InputError);
}

TEST_CASE("grids of a whole part: at most kMaxCellsPerPart cells over all faces, checked before any field") {
  // 16 faces at the per-face cap fill the part's cap exactly; one cell more is refused.
  const long per_face = kMaxCellsPerFace;  // 4 Mi = 2048 x 2048
  REQUIRE(per_face == 2048L * 2048);
  std::vector<GridSize> grids(kMaxCellsPerPart / per_face, GridSize{2048, 2048});
  CHECK_NOTHROW(check_part_grids(grids));
  grids.push_back({1, 1});
  const std::string expected = "the grids of the 17 faces need " + std::to_string(kMaxCellsPerPart + 1) + " cells in all";
  CHECK_THROWS_WITH_AS(check_part_grids(grids), doctest::Contains(expected.c_str()), InputError);
  // partition_part refuses such a part before it samples a face: 17 planes at
  // 2048 x 2048 would take most of a minute and gigabytes if it did not.
  Part part;
  for (int f = 0; f < 17; ++f)
    part.faces.emplace_back("plane " + std::to_string(f), make_plane({0, 0, 10.0 * f}, {50, 0, 0}, {0, 50, 0}));
  PartitionOptions options;
  options.grid = GridSize{2048, 2048};
  CHECK_THROWS_WITH_AS(partition_part(part, options), doctest::Contains("cells in all"), InputError);
}

TEST_CASE("default eps: the floor on flat faces, 1 % of the typical curvature on curved ones") {
  const Face plane("p", make_plane({0, 0, 0}, {70, 0, 0}, {0, 20, 0}));
  const CurvatureTolerance flat = default_curvature_tolerance(compute_curvature_field(plane, 20, 20));
  CHECK(flat.eps == kEpsFloor);
  CHECK(flat.curvature_scale == doctest::Approx(0.0).scale(1e-12));
  // A cylinder of radius 12.5 has |k| = 0.08 everywhere: eps = 8e-4.
  const Face cyl("c", make_cylinder(12.5, 40, 0, 2.0));
  const CurvatureTolerance t = default_curvature_tolerance(compute_curvature_field(cyl, 50, 30));
  CHECK(t.curvature_scale == doctest::Approx(0.08).epsilon(1e-9));
  CHECK(t.eps == doctest::Approx(8e-4).epsilon(1e-9));
  // A large radius gives a relative term below the floor: the floor wins.
  const Face big("b", make_cylinder(500, 40, 0, 0.2));
  CHECK(default_curvature_tolerance(compute_curvature_field(big, 20, 20)).eps == kEpsFloor);
}
