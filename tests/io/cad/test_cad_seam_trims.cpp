// CAD import of trimmed faces on periodic surfaces whose boundary loops touch
// or cross the surface's seam (docs/formats.md "CAD import", "Seams and
// poles"): quarter, half and three-quarter patches of spheres, cylinders and
// tori, each with its loop in both orientations, written to IGES (faces mode:
// trimmed surfaces; BRep mode: an MSBO shell of faces) and to STEP. Every
// imported face must keep the region its boundary encloses, not the rest of
// the surface: its area equals OpenCASCADE's area of the original face and
// the area of the same face imported from STEP.
#include <doctest/doctest.h>
#include <unistd.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Ax3.hxx>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/cad/cad_import.hpp"
#include "io/cad/cad_reference.hpp"
#include "kept_region.hpp"
#include "support/run_cli.hpp"
#include "support/trimmed_area.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// Faces are placed this far apart along x so that each imported face is
// found again by where it lies, whatever order a format keeps them in.
constexpr double kSpacing = 80;

struct SeamCase {
  std::string name;
  TopoDS_Face face;
  double area = 0;  // OpenCASCADE's, of the face as built
};

// `model_space_only`: boundaries as 3-D curves only (type 142 without a
// parameter-space curve, as CATIA writes them).
void write_iges_mode(const TopoDS_Shape& shape, const std::string& path, int mode, bool model_space_only = false) {
  silence_occt();
  if (model_space_only) Interface_Static::SetIVal("write.surfacecurve.mode", 0);
  IGESControl_Writer writer("MM", mode);  // 0: trimmed surfaces (144), 1: BRep (186/510/508)
  writer.AddShape(shape);
  writer.ComputeModel();
  const bool written = writer.Write(path.c_str());
  Interface_Static::SetIVal("write.surfacecurve.mode", 1);
  if (!written) throw std::runtime_error("cannot write " + path);
}

// Patches [u0, u1] x [v0, v1] of a sphere (radius 4.75, the quarter of the
// report: half the equator and two quarter meridians, 70.88 mm^2), a
// cylinder and a torus, starting on the seam, crossing it from either side
// and ending on it; each once as built and once with its boundary wire
// reversed (the region it encloses is the same; the loop runs the other way).
std::vector<SeamCase> seam_cases() {
  const double pi = M_PI, radius = 4.75;
  struct Patch {
    const char* name;
    int surface;  // 0 sphere, 1 cylinder, 2 torus
    double du, v0, v1;
  };
  const Patch patches[] = {
      {"sphere-quarter", 0, pi, 0, pi / 2},        {"sphere-half", 0, pi, -pi / 2, pi / 2},
      {"sphere-three-quarter", 0, 1.5 * pi, -pi / 2, pi / 2},
      {"cylinder-half", 1, pi, 0, 10},             {"cylinder-three-quarter", 1, 1.5 * pi, 0, 10},
      {"torus-quarter", 2, pi / 2, -pi / 2, pi / 2}, {"torus-three-quarter", 2, 1.5 * pi, 0.3, 0.3 + 1.5 * pi},
  };
  std::vector<SeamCase> cases;
  for (const Patch& p : patches)
    for (const double start : {0.0, -pi / 2, pi, 1.5 * pi})
      for (const bool reversed : {false, true}) {
        gp_Ax3 frame(gp_Pnt(kSpacing * static_cast<double>(cases.size()), 0, 0), gp::DZ(), gp::DX());
        Handle(Geom_Surface) surface;
        if (p.surface == 0) surface = new Geom_SphericalSurface(frame, radius);
        if (p.surface == 1) surface = new Geom_CylindricalSurface(frame, radius);
        if (p.surface == 2) surface = new Geom_ToroidalSurface(frame, 3 * radius, radius);
        TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, start, start + p.du, p.v0, p.v1, 1e-7).Face();
        if (reversed) {
          const TopoDS_Wire wire = TopoDS::Wire(BRepTools::OuterWire(face).Reversed());
          face = BRepBuilderAPI_MakeFace(surface, wire, true).Face();
        }
        SeamCase c;
        c.name = std::string(p.name) + " from " + std::to_string(start) + (reversed ? " reversed" : "");
        c.face = face;
        c.area = occt_area(face);
        cases.push_back(c);
      }
  return cases;
}

// Imported faces by the case they belong to (their place along x).
std::map<int, const Face*> by_case(const CadImportResult& result) {
  std::map<int, const Face*> faces;
  for (const Face& f : result.part.faces) {
    const ParameterDomain& d = f.domain();
    const Eigen::Vector3d p = f.surface().point(d.u0 + 0.5 * d.width_u(), d.v0 + 0.5 * d.width_v());
    faces[static_cast<int>(std::lround(p.x() / kSpacing))] = &f;
  }
  return faces;
}

}  // namespace

TEST_CASE("CAD import: trims touching or crossing the seam keep the enclosed region in IGES and STEP") {
  const std::vector<SeamCase> cases = seam_cases();
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const SeamCase& c : cases) builder.Add(compound, c.face);

  const std::string dir = scratch_dir("cad-seam-trims-" + std::to_string(getpid()));
  write_step(compound, dir + "/part.step");
  write_iges_mode(compound, dir + "/faces.igs", 0);
  write_iges_mode(compound, dir + "/brep.igs", 1);
  write_iges_mode(compound, dir + "/faces-3d.igs", 0, true);
  const CadImportResult step = import_cad(dir + "/part.step");
  const std::map<int, const Face*> step_faces = by_case(step);
  REQUIRE(step_faces.size() == cases.size());

  for (const char* file : {"faces.igs", "brep.igs", "faces-3d.igs"}) {
    CAPTURE(file);
    const CadImportResult iges = import_cad(dir + "/" + file);
    CHECK(iges.format == "IGES");
    const std::map<int, const Face*> iges_faces = by_case(iges);
    REQUIRE(iges_faces.size() == cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
      CAPTURE(cases[k].name);
      const Face& from_iges = *iges_faces.at(static_cast<int>(k));
      const Face& from_step = *step_faces.at(static_cast<int>(k));
      const double area = trimmed_area(from_iges);
      CHECK(area == doctest::Approx(cases[k].area).epsilon(1e-6));
      CHECK(area == doctest::Approx(trimmed_area(from_step)).epsilon(1e-6));
      // The same side out as STEP, whose faces carry their orientation.
      CHECK((normal_integral(from_iges) - normal_integral(from_step)).norm() < 1e-2 * area);
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}

TEST_CASE("CAD import: a cap around a sphere's pole from IGES with only 3-D curves runs along the seam") {
  // The octant of a sphere whose axis points into it: a three-sided cap
  // around the pole. IGES written without parameter-space curves makes
  // OpenCASCADE project the edges and close the wire along the seam; the
  // projected seam edges stray ~1e-8 rad past the period (within their
  // 1e-7 mm tolerance), which must not make the face span "more than one
  // period" (cad_face_trims.cpp period_slack).
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 1), gp_Dir(1, -1, 0)), 4.75).Shape();
  const TopoDS_Shape octant = BRepAlgoAPI_Common(ball, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(50, 50, 50)).Shape()).Shape();
  TopoDS_Face cap;
  for (const TopoDS_Face& f : faces_of(octant))
    if (BRepAdaptor_Surface(f).GetType() == GeomAbs_Sphere) cap = f;
  REQUIRE(!cap.IsNull());
  const double area = occt_area(cap);
  CHECK(area == doctest::Approx(M_PI * 4.75 * 4.75 / 2).epsilon(1e-9));  // an eighth of the sphere
  const std::string dir = scratch_dir("cad-seam-cap-" + std::to_string(getpid()));
  // Written in BRep mode first, as a part is exported in several flavours:
  // the writer leaves the face's edges with the curves that make the
  // faces-mode file's projected seam stray past the period.
  write_iges_mode(cap, dir + "/cap_brep.igs", 1);
  silence_occt();
  Interface_Static::SetIVal("write.surfacecurve.mode", 0);  // 3-D curves only
  IGESControl_Writer writer("MM", 0);
  writer.AddShape(cap);
  writer.ComputeModel();
  const bool written = writer.Write((dir + "/cap.igs").c_str());
  Interface_Static::SetIVal("write.surfacecurve.mode", 1);
  REQUIRE(written);
  for (const char* file : {"cap.igs", "cap_brep.igs"}) {
    CAPTURE(file);
    const CadImportResult result = import_cad(dir + "/" + file);
    REQUIRE(result.part.faces.size() == 1);
    // Projected curves are OpenCASCADE's approximation (~1e-6 of the area).
    CHECK(trimmed_area(result.part.faces[0]) == doctest::Approx(area).epsilon(1e-5));
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}
