// One classification rule for every command (docs/partition.md "eps"):
// `furrow info` and `furrow partition` give each face of a real multi-face
// part the same eps and the same class shares, and a face of constant
// curvature that comes as a fitted B-spline (its "zero" curvature is noise)
// is one region, not speckles.
#include <doctest/doctest.h>

#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cad_reference.hpp"
#include "io/cad/cad_import.hpp"
#include "partition/curvature_tolerance.hpp"
#include "partition/partition.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// A B-spline fitted through points of a surface given by `at(s, t)`, s, t in
// [0, 1]: the way CAD systems export analytic faces they no longer know.
template <class F>
Part fitted_face(const std::string& name, F at) {
  TColgp_Array2OfPnt pts(1, 25, 1, 25);
  for (int i = 1; i <= 25; ++i)
    for (int j = 1; j <= 25; ++j) pts(i, j) = occ(at((i - 1) / 24.0, (j - 1) / 24.0));
  const Handle(Geom_BSplineSurface) surface = GeomAPI_PointsToBSplineSurface(pts, 3, 5, GeomAbs_C2, 1e-4).Surface();
  // Six micrometres of scatter on the control net: a fit through digitised
  // or tessellated data carries such noise into its "zero" curvature (a few
  // 1e-4 /mm here, above the 1e-4 floor, below 1 % of the real curvature).
  for (int i = 1; i <= surface->NbUPoles(); ++i)
    for (int j = 1; j <= surface->NbVPoles(); ++j) {
      const gp_Pnt p = surface->Pole(i, j);
      surface->SetPole(i, j, gp_Pnt(p.X(), p.Y(), p.Z() + 6e-3 * std::sin(17.0 * i + 29.0 * j)));
    }
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
  const std::string path = scratch_dir("cad-classes-" + name) + "/" + name + ".step";
  write_step(face, path);
  return import_cad(path).part;
}

int region_count_of_face(const RegionMap& map, int face) {
  int n = 0;
  for (const Region& r : map.regions) n += r.face == face;
  return n;
}

}  // namespace

TEST_CASE("one rule: furrow info and furrow partition agree on every face of the reference model") {
  const std::string dir = scratch_dir("cad-classes-model");
  const std::string step = dir + "/model.step";
  write_step(make_reference_model().shape, step);
  const CliResult info = run_furrow({"info", "--json", "--grid", "200", step});
  REQUIRE(info.status == 0);
  const CliResult part = run_furrow({"partition", step, "--out", dir + "/regions.json"});
  REQUIRE(part.status == 0);
  const auto summary = nlohmann::json::parse(info.out);
  const auto regions = nlohmann::json::parse(std::ifstream(dir + "/regions.json"));
  CHECK(summary["eps"] == "per face");
  REQUIRE(summary["faces"].size() == regions["faces"].size());
  REQUIRE(summary["faces"].size() > 20);
  for (std::size_t f = 0; f < regions["faces"].size(); ++f) {
    CAPTURE(f);
    const auto& a = summary["faces"][f];
    const auto& b = regions["faces"][f];
    // The same eps exactly: both come from the face, not from the grid.
    CHECK(a["eps"].template get<double>() == b["eps"].template get<double>());
    const double area = b["area_mm2"].template get<double>();
    for (const char* c : {"planar", "convex", "concave", "saddle"}) {
      CAPTURE(c);
      const double share_info = a["classes"][c]["share"].template get<double>();
      const double share_partition = b["class_area_mm2"][c].template get<double>() / area;
      // Different sampling grids (200 x 200 against the partition's spacing)
      // move class borders by less than a cell: a few percent at most.
      CHECK(std::abs(share_info - share_partition) < 0.03);
    }
  }
}

TEST_CASE("one rule: fitted B-spline cylinder, sphere and torus ring are never split by noise") {
  struct Case {
    std::string name;
    CurvatureClass expected;
    Part part;
  };
  const double pi = std::acos(-1.0);
  std::vector<Case> cases;
  // Convex quarter cylinder, radius 3 mm (a fillet): its axial curvature is zero up to fitting noise.
  cases.push_back({"cylinder", CurvatureClass::convex, fitted_face("cylinder", [&](double s, double t) {
                     // Parameter lines oblique to the rulings, as a fitted export has them.
                     const double a = 0.5 * pi * (0.8 * s + 0.2 * t);
                     return Eigen::Vector3d(3.0 * std::cos(a), 30 * t + 2 * s * s, 3.0 * std::sin(a));
                   })});
  // Concave: the inside of the same cylinder seen from its axis.
  cases.push_back({"trough", CurvatureClass::concave, fitted_face("trough", [&](double s, double t) {
                     const double a = pi + 0.5 * pi * (1 - 0.8 * s - 0.2 * t);
                     return Eigen::Vector3d(3.0 * std::cos(a), 30 * t + 2 * s * s, 3.0 + 3.0 * std::sin(a));
                   })});
  cases.push_back({"sphere", CurvatureClass::convex, fitted_face("sphere", [&](double s, double t) {
                     const double th = 0.1 * pi + 0.3 * pi * s, ph = 2 * pi * 0.25 * t;
                     return Eigen::Vector3d(20 * std::sin(th) * std::cos(ph), 20 * std::sin(th) * std::sin(ph),
                                            20 * std::cos(th));
                   })});
  // The outer side of a torus ring (R 20, r 6): convex everywhere.
  cases.push_back({"ring", CurvatureClass::convex, fitted_face("ring", [&](double s, double t) {
                     const double th = -0.45 * pi + 0.9 * pi * s, ph = 0.5 * pi * t;
                     const double rho = 20 + 6 * std::cos(th);
                     return Eigen::Vector3d(rho * std::cos(ph), rho * std::sin(ph), 6 * std::sin(th));
                   })});
  for (const Case& c : cases) {
    CAPTURE(c.name);
    REQUIRE(c.part.faces.size() == 1);
    // The fit's normals follow the parameterisation; make them face the
    // expected side so the oracle class is the one named above.
    const PartitionResult result = partition_part(c.part, {});
    REQUIRE(result.map.regions.size() >= 1);
    CHECK(region_count_of_face(result.map, 0) == 1);
    const RegionFace& face = result.map.faces[0];
    // Every cell in the one class: no band of another class, merged or not.
    double other = 0;
    for (int k = 0; k < kCurvatureClassCount; ++k)
      if (k != static_cast<int>(result.map.regions[0].curvature_class)) other += face.class_area[k];
    CHECK(other == 0.0);
    const CurvatureClass got = result.map.regions[0].curvature_class;
    // Orientation is the fit's, so a convex cylinder may come as concave; the
    // class pair is what the rule protects.
    const bool same_pair = got == c.expected || (got == CurvatureClass::convex && c.expected == CurvatureClass::concave) ||
                           (got == CurvatureClass::concave && c.expected == CurvatureClass::convex);
    CHECK(same_pair);
    CHECK(face.eps == face_curvature_tolerance(c.part.faces[0]).eps);
  }
  // The noise is real: at the 1e-4 floor alone the fitted cylinder breaks
  // into speckles of another class (the state `furrow info` was in).
  PartitionOptions floor_only;
  floor_only.eps = kEpsFloor;
  const RegionFace floor_face = partition_part(cases[0].part, floor_only).map.faces[0];
  CHECK(floor_face.class_area[static_cast<int>(CurvatureClass::saddle)] > 0.005 * floor_face.area);
}
