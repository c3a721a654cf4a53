// CAD import of solids that OpenCASCADE writes to IGES as trimmed surfaces
// (type 144) with model-space boundary curves only (type 142 PPTR 0), read
// in every CRTN and PREF (the file's type 142 fields rewritten) and from the
// solids turned inside out, against the same solids written as STEP
// (docs/formats.md "IGES boundaries", "Orientation"): a tube with a radial
// hole across both cylinders' seams, a plate with a hole, a B-spline block with a hole,
// a ball cut by a plane through its pole (the cut circle passes the pole in
// its interior) and half balls bounded by a great circle through both
// poles. Every IGES face must sew into its solid's closed shell, and have
// the STEP face's area and the same integral of its outward unit normal.
#include <doctest/doctest.h>
#include <unistd.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeHalfSpace.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "iges_field_rewrite.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cad/cad_reference.hpp"
#include "kept_region.hpp"
#include "support/run_cli.hpp"
#include "support/trimmed_area.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// The solids, each on its own place along x.
std::vector<TopoDS_Shape> model_space_solids() {
  std::vector<TopoDS_Shape> solids;
  // A tube (radii 10 and 6, 30 high, seams on +x) with a radial hole of
  // radius 3 along x through both walls.
  TopoDS_Shape tube = BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(100, 0, 0), gp::DZ()), 10, 30).Shape(),
                                      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(100, 0, -1), gp::DZ()), 6, 32).Shape())
                          .Shape();
  solids.push_back(
      BRepAlgoAPI_Cut(tube, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(80, 0, 15), gp::DX()), 3, 40).Shape()).Shape());
  // A plate with a hole: planes with an inner loop.
  solids.push_back(BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(gp_Pnt(180, -20, 0), 40, 40, 5).Shape(),
                                   BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(200, 0, -1), gp::DZ()), 6, 7).Shape())
                       .Shape());
  // A block with a free-form B-spline top (x 250..290, y 0..30) and a hole
  // through it: a B-spline face with an inner loop.
  const TopoDS_Face top = BRepBuilderAPI_MakeFace(freeform_surface(), 1e-7).Face();
  solids.push_back(BRepAlgoAPI_Cut(BRepPrimAPI_MakePrism(top, gp_Vec(0, 0, -15)).Shape(),
                                   BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(270, 15, -5), gp::DZ()), 4, 40).Shape())
                       .Shape());
  // A ball cut by a plane through its north pole tilted 0.5 rad toward +x:
  // the cut circle passes the pole between its ends and crosses the seam.
  // Written inside out, OpenCASCADE's healing drops the seam from the
  // sphere face's boundary and keeps the cut-off cap: the importer builds
  // the loop from the file's curves and corrects the shell's volume for it.
  const gp_Pnt pole(400, 0, 15);
  const gp_Dir tilted(std::sin(0.5), 0, std::cos(0.5));
  const TopoDS_Face plane = BRepBuilderAPI_MakeFace(gp_Pln(pole, tilted), -100, 100, -100, 100).Face();
  const TopoDS_Shape below = BRepPrimAPI_MakeHalfSpace(plane, gp_Pnt(400, 0, 0)).Solid();
  solids.push_back(BRepAlgoAPI_Common(BRepPrimAPI_MakeSphere(gp_Pnt(400, 0, 0), 15).Shape(), below).Shape());
  // Half balls cut by the plane x = centre: a great circle through both
  // poles; the +x half holds the seam, the -x half does not.
  solids.push_back(BRepAlgoAPI_Common(BRepPrimAPI_MakeSphere(gp_Pnt(500, 0, 0), 15).Shape(),
                                      BRepPrimAPI_MakeBox(gp_Pnt(500, -50, -50), 50, 100, 100).Shape())
                       .Shape());
  solids.push_back(BRepAlgoAPI_Common(BRepPrimAPI_MakeSphere(gp_Pnt(600, 0, 0), 15).Shape(),
                                      BRepPrimAPI_MakeBox(gp_Pnt(550, -50, -50), 50, 100, 100).Shape())
                       .Shape());
  return solids;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A face of an import, with what is compared.
struct Measured {
  const Face* face;
  Eigen::Vector3d centroid;
  double area;
  Eigen::Vector3d normal;  // integral of the unit normal over the kept region
};

// A point off every face's centroid in no special direction: the flux of
// the position field about it changes sign when a face is turned round.
Eigen::Vector3d flux_point(const Eigen::Vector3d& centroid) { return centroid + Eigen::Vector3d(1.3, -2.1, 1.7); }

std::vector<Measured> measure(const CadImportResult& result) {
  std::vector<Measured> faces;
  for (const Face& f : result.part.faces)
    faces.push_back({&f, kept_centroid(f, 60), trimmed_area(f), normal_integral(f, 100)});
  return faces;
}

}  // namespace

TEST_CASE("CAD import: solids as IGES with model-space boundaries only, every CRTN and PREF, agree with STEP face by face") {
  const std::string dir = scratch_dir("iges-model-space-solids-" + std::to_string(getpid()));
  for (const bool inside_out : {false, true}) {
    const std::vector<TopoDS_Shape> solids = model_space_solids();
    const TopoDS_Compound compound = compound_of(solids);
    write_step(compound, dir + "/part.step");
    const CadImportResult step_import = import_cad(dir + "/part.step");
    const std::vector<Measured> step = measure(step_import);
    REQUIRE(step.size() >= 20);
    // IGES faces mode without parameter-space curves, as CATIA writes.
    silence_occt();
    Interface_Static::SetIVal("write.surfacecurve.mode", 0);
    IGESControl_Writer writer("MM", 0);
    writer.AddShape(inside_out ? compound.Reversed() : TopoDS_Shape(compound));
    writer.ComputeModel();
    const bool written = writer.Write((dir + "/written.igs").c_str());
    Interface_Static::SetIVal("write.surfacecurve.mode", 1);
    REQUIRE(written);
    const std::string original = read_text(dir + "/written.igs");
    for (int crtn = 0; crtn <= 3; ++crtn)
      for (int pref = 0; pref <= 3; ++pref) {
        CAPTURE(inside_out);
        CAPTURE(crtn);
        CAPTURE(pref);
        std::string text = original;
        const CurveOnSurfaceFields fields = set_curve_on_surface_fields(text, crtn, pref);
        REQUIRE(fields.rewritten >= static_cast<int>(step.size()));  // every face's boundaries
        REQUIRE(fields.model_space_only == fields.rewritten);
        const std::string path = dir + "/crtn" + std::to_string(crtn) + "-pref" + std::to_string(pref) + ".igs";
        std::ofstream(path, std::ios::binary) << text;
        const CadImportResult iges = import_cad(path);
        CHECK(iges.closed_shells == static_cast<int>(solids.size()));
        const std::vector<Measured> faces = measure(iges);
        REQUIRE(faces.size() == step.size());
        for (std::size_t k = 0; k < faces.size(); ++k) {
          // Its STEP face: of those with nearly its area (a tube's two walls
          // share a centroid), the nearest centroid (faces of
          // these solids lie millimetres apart; a grid centroid is within
          // ~0.1 mm).
          std::size_t best = step.size();
          double nearest = std::numeric_limits<double>::infinity();
          for (std::size_t j = 0; j < step.size(); ++j) {
            const double d = (faces[k].centroid - step[j].centroid).norm();
            if (std::abs(faces[k].area - step[j].area) < 1e-4 * step[j].area && d < nearest) nearest = d, best = j;
          }
          CAPTURE(faces[k].centroid.transpose());
          CAPTURE(faces[k].area);
          CHECK(best < step.size());
          if (best == step.size()) continue;
          CHECK(nearest < 0.5);
          CHECK(std::abs(faces[k].area - step[best].area) < 1e-6 * step[best].area);
          // The same side out (the grid integral differs by ~1e-3 of the
          // area between two trims of one region; turned round, by twice
          // its size).
          CHECK((faces[k].normal - step[best].normal).norm() < 1e-2 * step[best].area);
          // ... also where that integral nearly vanishes: the flux about a
          // point beside the face, within 1e-2 of its scale.
          const Eigen::Vector3d q = flux_point(step[best].centroid);
          const Eigen::Vector2d flux = position_flux(*faces[k].face, q), reference = position_flux(*step[best].face, q);
          CAPTURE(flux.transpose());
          CAPTURE(reference.transpose());
          CHECK(std::abs(flux.x() - reference.x()) < 1e-2 * reference.y());
          CHECK(std::abs(reference.x()) > 5e-2 * reference.y());  // the check can tell the two senses apart
        }
      }
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
}
