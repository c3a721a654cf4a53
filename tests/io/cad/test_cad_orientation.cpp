// Outward orientation of faces that bound no solid (docs/formats.md
// "Orientation"): surface models in IGES and STEP with faces reversed at
// random are sewn, oriented consistently and, where they close, outward; the
// oracle is OpenCASCADE's solid classifier on the model the faces came from.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include <BRepAdaptor_Curve.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <TopExp_Explorer.hxx>

#include "cad_reference.hpp"
#include "base/error.hpp"
#include "io/cad/cad_import.hpp"
#include "partition/classification.hpp"
#include "partition/part_summary.hpp"
#include "support/run_cli.hpp"
#include "support/trimmed_area.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// The faces of `shape` as a compound of loose faces (no shells, no solids),
// every face reversed with probability 1/2 (seeded): a surface model as a
// careless export writes it.
TopoDS_Compound loose_faces(const TopoDS_Shape& shape, unsigned seed, std::vector<bool>* reversed = nullptr) {
  std::mt19937 random(seed);
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const TopoDS_Face& f : faces_of(shape)) {
    const bool flip = (random() & 1u) != 0;
    if (reversed) reversed->push_back(flip);
    builder.Add(compound, flip ? f.Reversed() : TopoDS_Shape(f));
  }
  return compound;
}

// Interior points of a face away from its trims, with their normals.
std::vector<DifferentialGeometry> interior_points(const Face& face, int n) {
  const ParameterDomain& d = face.domain();
  std::vector<DifferentialGeometry> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = d.u0 + d.width_u() * (0.05 + 0.9 * i / (n - 1));
      const double v = d.v0 + d.width_v() * (0.05 + 0.9 * j / (n - 1));
      if (!face.contains(u, v) || face.trim().distance_to_boundary({u, v}) < 0.03 * std::min(d.width_u(), d.width_v()))
        continue;
      const DifferentialGeometry g = face.geometry(u, v);
      if (!g.degenerate) out.push_back(g);
    }
  return out;
}

// Share of a face's interior points whose normal points out of the model's
// solids: a step along the normal leaves the material, a step against it
// enters it.
double outward_share(const Face& face, SolidsClassifier& solids) {
  int out = 0, total = 0;
  for (const DifferentialGeometry& g : interior_points(face, 6)) {
    ++total;
    out += solids.containing(g.point + 0.05 * g.normal) == 0 && solids.containing(g.point - 0.05 * g.normal) == 1;
  }
  return total == 0 ? 1.0 : static_cast<double>(out) / total;
}

// A block as machined parts are: a boss with a filleted foot (a torus
// blend), a drilled bore, rounded vertical edges (cylinder fillets), and
// beside it a solid with a free-form B-spline top.
ReferenceModel make_filleted_model() {
  using G = ReferenceGeometry;
  TopoDS_Shape block = BRepPrimAPI_MakeBox(G::box_x, G::box_y, G::box_z).Shape();
  block = BRepAlgoAPI_Fuse(block, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(G::boss_x, G::boss_y, G::box_z), gp::DZ()),
                                                           G::boss_r, G::boss_h)
                                      .Shape())
              .Shape();
  block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(58, 30, -1), gp::DZ()), 6, G::box_z + 2).Shape())
              .Shape();
  BRepFilletAPI_MakeFillet fillet(block);
  for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    const BRepAdaptor_Curve c(edge);
    const gp_Pnt a = c.Value(c.FirstParameter()), b = c.Value(c.LastParameter());
    const bool vertical_box_edge = c.GetType() == GeomAbs_Line && std::abs(a.X() - b.X()) < 1e-9 &&
                                   std::abs(a.Y() - b.Y()) < 1e-9 && (a.X() < 1e-9 || a.X() > G::box_x - 1e-9);
    const bool boss_foot = c.GetType() == GeomAbs_Circle && std::abs(c.Circle().Radius() - G::boss_r) < 1e-9 &&
                           std::abs(c.Circle().Location().Z() - G::box_z) < 1e-9;
    if (vertical_box_edge) fillet.Add(5.0, edge);
    if (boss_foot) fillet.Add(2.0, edge);
  }
  ReferenceModel model;
  TopExp_Explorer solid(fillet.Shape(), TopAbs_SOLID);
  model.solids.push_back(solid.Current());
  const TopoDS_Face top = BRepBuilderAPI_MakeFace(freeform_surface(), 1e-7).Face();
  model.solids.push_back(BRepPrimAPI_MakePrism(top, gp_Vec(0, 0, -15)).Shape());
  model.shape = compound_of(model.solids);
  return model;
}

// The model's faces as a surface model with random flips, in STEP and in
// IGES: every face comes in outward (the solids' classifier), with
// OpenCASCADE's area to 1e-6, and both files give the same class split.
// Returns the folder holding the two files.
std::string check_surface_model(const ReferenceModel& model, const std::string& label) {
  SolidsClassifier solids(model);
  const TopoDS_Compound faces = loose_faces(model.shape, 12345);
  const std::string dir = scratch_dir("cad-orientation-" + label);
  write_step(faces, dir + "/surfaces.step");
  write_iges(faces, dir + "/surfaces.igs");
  std::vector<PartSummary> summaries;
  for (const char* name : {"surfaces.step", "surfaces.igs"}) {
    CAPTURE(name);
    const CadImportResult r = import_cad(dir + "/" + name);
    summaries.push_back(summarize_part(r.part, 100, std::nullopt));
    CHECK(r.solids == 0);
    CHECK(r.free_faces == r.part.faces.size());
    CHECK(r.closed_shells == static_cast<int>(model.solids.size()));
    int turned = 0;
    for (std::size_t f = 0; f < r.part.faces.size(); ++f) {
      CAPTURE(std::string(r.part.faces[f].name()));
      CHECK(r.faces[f].orientation == CadFaceOrientation::closed_shell);
      CHECK(outward_share(r.part.faces[f], solids) == 1.0);
      turned += r.faces[f].flipped;
    }
    // The random flips had to be undone somewhere (about half the faces).
    CHECK(turned > 0);
  }
  // Both files give the same faces: every face's area (Green's theorem on
  // its trim, tests/support/trimmed_area.hpp) against OpenCASCADE's area of
  // the source faces, matched by size.
  std::vector<double> expected;
  for (const TopoDS_Face& face : faces_of(model.shape)) expected.push_back(occt_area(face));
  std::sort(expected.begin(), expected.end());
  for (const char* name : {"surfaces.step", "surfaces.igs"}) {
    CAPTURE(name);
    const CadImportResult r = import_cad(dir + "/" + name);
    std::vector<double> areas;
    for (const Face& face : r.part.faces) areas.push_back(trimmed_area(face));
    std::sort(areas.begin(), areas.end());
    REQUIRE(areas.size() == expected.size());
    double worst = 0;
    for (std::size_t k = 0; k < areas.size(); ++k) worst = std::max(worst, std::abs(areas[k] - expected[k]) / expected[k]);
    INFO(name << ": largest relative face-area difference from OpenCASCADE " << worst);
    CHECK(worst < 1e-6);
  }
  // And, with the same orientation, the same convex/concave/saddle split
  // (up to the grids' sampling).
  CHECK(std::abs(summaries[0].area - summaries[1].area) < 2e-4 * summaries[0].area);
  for (int c = 0; c < kCurvatureClassCount; ++c)
    CHECK(std::abs(summaries[0].class_area[c] - summaries[1].class_area[c]) < 5e-3 * summaries[0].area);
  return dir;
}

}  // namespace

TEST_CASE("orientation: a surface model with random face flips comes in outward, in STEP and in IGES") {
  const ReferenceModel model = make_reference_model();
  const std::string dir = check_surface_model(model, "model");
  SolidsClassifier solids(model);
  // Without sewing only the faces that close on themselves (the ball, the
  // ring) are decided; every other face is its own open shell, kept as the
  // file has it and reported undecided.
  CadImportOptions no_sewing;
  no_sewing.sewing_tolerance = 0;
  const CadImportResult raw = import_cad(dir + "/surfaces.step", no_sewing);
  int inward = 0, closed = 0;
  for (std::size_t f = 0; f < raw.part.faces.size(); ++f) {
    const double share = outward_share(raw.part.faces[f], solids);
    if (raw.faces[f].orientation == CadFaceOrientation::closed_shell) {
      ++closed;
      CHECK(share == 1.0);
      continue;
    }
    CHECK(raw.faces[f].orientation == CadFaceOrientation::file);
    CHECK(!raw.faces[f].flipped);
    inward += share < 0.5;
  }
  CHECK(closed == 2);
  CHECK(inward > 0);
}

TEST_CASE("orientation: a filleted block with a bore and a torus blend, and a B-spline top, in STEP and IGES") {
  const ReferenceModel model = make_filleted_model();
  // The fillets are there: 4 rounded vertical edges and the torus at the boss's foot.
  int cylinders = 0, tori = 0, bsplines = 0;
  for (const TopoDS_Face& f : faces_of(model.shape)) {
    const GeomAbs_SurfaceType t = BRepAdaptor_Surface(f).GetType();
    cylinders += t == GeomAbs_Cylinder;
    tori += t == GeomAbs_Torus;
    bsplines += t == GeomAbs_BSplineSurface;
  }
  CHECK(cylinders >= 6);  // 4 fillets, the boss, the bore
  CHECK(tori == 1);
  CHECK(bsplines >= 1);
  check_surface_model(model, "filleted");
}

TEST_CASE("orientation: an open shell is made consistent, +z, -z and a point rule decide its side") {
  // The free-form block's top and its four sides, no bottom: an open shell.
  const ReferenceModel model = make_reference_model();
  SolidsClassifier solids(model);
  const TopoDS_Shape block = model.solids[3];
  TopoDS_Compound open;
  BRep_Builder builder;
  builder.MakeCompound(open);
  // The bottom is the copy of the top swept down: the face lowest in z.
  const std::vector<TopoDS_Face> block_faces = faces_of(block);
  std::vector<double> top_z;
  for (const TopoDS_Face& f : block_faces) {
    Bnd_Box fb;
    BRepBndLib::Add(f, fb);
    double a, b, c, d, e, zmax;
    fb.Get(a, b, c, d, e, zmax);
    top_z.push_back(zmax);
  }
  const std::size_t bottom = static_cast<std::size_t>(std::min_element(top_z.begin(), top_z.end()) - top_z.begin());
  std::mt19937 random(7);
  int kept = 0;
  for (std::size_t k = 0; k < block_faces.size(); ++k) {
    if (k == bottom) continue;
    builder.Add(open, (random() & 1u) ? block_faces[k].Reversed() : TopoDS_Shape(block_faces[k]));
    ++kept;
  }
  REQUIRE(kept == 5);
  const std::string path = scratch_dir("cad-orientation-open") + "/open.igs";
  write_iges(open, path);

  CadImportOptions up;
  up.outward.kind = OutwardRule::Kind::plus_z;
  const CadImportResult r = import_cad(path, up);
  REQUIRE(r.part.faces.size() == 5);
  CHECK(r.sewn_shells == 1);
  CHECK(r.closed_shells == 0);
  for (std::size_t f = 0; f < 5; ++f) {
    CAPTURE(std::string(r.part.faces[f].name()));
    CHECK(r.faces[f].orientation == CadFaceOrientation::rule);
    CHECK(outward_share(r.part.faces[f], solids) == 1.0);
  }
  // A point inside the material gives the same answer; -z the opposite one.
  CadImportOptions inside;
  inside.outward = parse_outward_rule("point:270,15,12", "test");
  CadImportOptions down;
  down.outward = parse_outward_rule("-z", "test");
  const CadImportResult by_point = import_cad(path, inside);
  const CadImportResult by_down = import_cad(path, down);
  for (std::size_t f = 0; f < 5; ++f) {
    CHECK(outward_share(by_point.part.faces[f], solids) == 1.0);
    CHECK(outward_share(by_down.part.faces[f], solids) == 0.0);
  }
  // No rule: consistent with its neighbours, side undecided and said so.
  const CadImportResult undecided = import_cad(path);
  const double first = outward_share(undecided.part.faces[0], solids);
  CHECK((first == 0.0 || first == 1.0));
  for (std::size_t f = 0; f < 5; ++f) {
    CHECK(undecided.faces[f].orientation == CadFaceOrientation::file);
    CHECK(outward_share(undecided.part.faces[f], solids) == first);
  }
}

TEST_CASE("orientation: a sewing tolerance beyond 1 mm is refused") {
  const std::string path = scratch_dir("cad-orientation-tolerance") + "/ball.step";
  write_step(BRepPrimAPI_MakeSphere(10).Shape(), path);
  for (const double bad : {1.5, 1e308, -1.0, std::nan("")}) {
    CadImportOptions o;
    o.sewing_tolerance = bad;
    CHECK_THROWS_WITH_AS(import_cad(path, o), doctest::Contains("sewing tolerance must lie between 0 and 1 mm"),
                         InputError);
  }
}

TEST_CASE("orientation: bad --outward rules are refused naming the option") {
  for (const char* bad : {"up", "point:1,2", "point:1,2,3,4", "point:1,x,3", "point:1,2,nan", ""}) {
    CAPTURE(bad);
    CHECK_THROWS_WITH_AS(parse_outward_rule(bad, "furrow import: --outward"),
                         doctest::Contains("furrow import: --outward"), InputError);
  }
}
