// Analytic surface recognition (docs/formats.md "Analytic surfaces"): a
// cylinder, cone, sphere and torus on an oblique axis, each written as an
// exact B-spline and as a surface of revolution, are recognised after CAD
// import with their radius, axis and centre to 1e-9 mm; a B-spline moved by
// 0.1 um at one pole is not. The truth is the construction's own numbers.
#include <doctest/doctest.h>

#include <GeomConvert.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <cmath>

#include "cad_reference.hpp"
#include "io/cad/cad_import.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

// An oblique frame: axis along (1, 2, 3), origin off the world origin.
const gp_Ax3& frame() {
  static const gp_Ax3 f(gp_Pnt(10, -20, 5), gp_Dir(1, 2, 3), gp_Dir(2, -1, 0));
  return f;
}
Eigen::Vector3d axis() { return eig(frame().Direction()); }
Eigen::Vector3d origin() { return eig(frame().Location()); }

Face imported(const Handle(Geom_Surface)& surface, const std::string& name) {
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
  const std::string path = scratch_dir("cad-analytic-" + name) + "/" + name + ".step";
  write_step(face, path);
  const CadImportResult r = import_cad(path);
  REQUIRE(r.part.faces.size() == 1);
  return r.part.faces[0];
}

Handle(Geom_Surface) as_bspline(const Handle(Geom_Surface)& s, double u0, double u1, double v0, double v1) {
  return GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1));
}

// A surface of revolution about the frame's axis from a meridian curve
// given in the frame's (x, z) plane.
Handle(Geom_Surface) revolved(const Handle(Geom_Curve)& meridian) {
  return new Geom_RectangularTrimmedSurface(new Geom_SurfaceOfRevolution(meridian, frame().Axis()), 0, 1.5 * kPi,
                                            meridian->FirstParameter(), meridian->LastParameter());
}
gp_Pnt in_frame(double x, double z) {
  return gp_Pnt(origin().x(), origin().y(), origin().z())
      .Translated(gp_Vec(frame().XDirection()) * x + gp_Vec(frame().Direction()) * z);
}

// Distance of a point from a line (origin o, unit direction d).
double off_line(const Eigen::Vector3d& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  return ((p - o) - (p - o).dot(d) * d).norm();
}

void check_axis(const AnalyticSurface& a) {
  CHECK(std::abs(std::abs(a.axis.dot(axis().normalized())) - 1) < 1e-12);
  CHECK(a.axis.cross(axis().normalized()).norm() < 1e-9);
  CHECK(off_line(a.origin, origin(), axis().normalized()) < 1e-9);
}

}  // namespace

TEST_CASE("analytic: cylinder, cone, sphere and torus as B-spline and as revolution are recognised exactly") {
  const double r = 12.5, R = 30, rho = 6, half = 20 * kPi / 180;
  // Cylinder.
  const Handle(Geom_Surface) cyl = new Geom_CylindricalSurface(frame(), r);
  for (const Face& f : {imported(as_bspline(cyl, 0, 1.5 * kPi, -10, 25), "cyl-bspline"),
                        imported(revolved(new Geom_TrimmedCurve(new Geom_Line(in_frame(r, 0), frame().Direction()),
                                                                -10, 25)),
                                 "cyl-revolution")}) {
    CAPTURE(f.source_type());
    REQUIRE(f.analytic());
    CHECK(f.analytic()->type == AnalyticSurface::Type::cylinder);
    CHECK(std::abs(f.analytic()->radius - r) < 1e-9);
    check_axis(*f.analytic());
  }
  // Cone: apex at the frame's origin, opening along +axis.
  gp_Ax3 cone_frame = frame();
  cone_frame.SetLocation(in_frame(0, 0).Translated(gp_Vec(frame().Direction()) * 10));
  const Handle(Geom_Surface) cone = new Geom_ConicalSurface(cone_frame, half, 10 * std::tan(half));
  const gp_Pnt rim = in_frame(40 * std::tan(half), 40);
  for (const Face& f :
       {imported(as_bspline(cone, 0, 1.5 * kPi, 0, 25), "cone-bspline"),
        imported(revolved(new Geom_TrimmedCurve(
                     new Geom_Line(in_frame(0, 0), gp_Dir(gp_Vec(in_frame(0, 0), rim))), 8, 40)),
                 "cone-revolution")}) {
    CAPTURE(f.source_type());
    REQUIRE(f.analytic());
    CHECK(f.analytic()->type == AnalyticSurface::Type::cone);
    CHECK(std::abs(f.analytic()->half_angle - half) < 1e-11);
    CHECK((f.analytic()->origin - origin()).norm() < 1e-9);
    check_axis(*f.analytic());
  }
  // Sphere: centre at the frame's origin.
  const Handle(Geom_Surface) sphere = new Geom_SphericalSurface(frame(), R);
  gp_Ax2 meridian_plane(frame().Location(), frame().YDirection().Reversed(), frame().XDirection());
  for (const Face& f : {imported(as_bspline(sphere, 0, 1.5 * kPi, -1.2, 1.3), "sphere-bspline"),
                        imported(revolved(new Geom_TrimmedCurve(new Geom_Circle(meridian_plane, R), -1.2, 1.3)),
                                 "sphere-revolution")}) {
    CAPTURE(f.source_type());
    REQUIRE(f.analytic());
    CHECK(f.analytic()->type == AnalyticSurface::Type::sphere);
    CHECK(std::abs(f.analytic()->radius - R) < 1e-9);
    CHECK((f.analytic()->origin - origin()).norm() < 1e-9);
  }
  // Torus: centre at the frame's origin, tube circle at x = R in the frame.
  const Handle(Geom_Surface) torus = new Geom_ToroidalSurface(frame(), R, rho);
  gp_Ax2 tube_plane(in_frame(R, 0), frame().YDirection().Reversed(), frame().XDirection());
  for (const Face& f : {imported(as_bspline(torus, 0, 1.5 * kPi, 0, 2 * kPi), "torus-bspline"),
                        imported(revolved(new Geom_TrimmedCurve(new Geom_Circle(tube_plane, rho), 0, 2 * kPi)),
                                 "torus-revolution")}) {
    CAPTURE(f.source_type());
    REQUIRE(f.analytic());
    CHECK(f.analytic()->type == AnalyticSurface::Type::torus);
    CHECK(std::abs(f.analytic()->radius - R) < 1e-9);
    CHECK(std::abs(f.analytic()->minor_radius - rho) < 1e-9);
    CHECK((f.analytic()->origin - origin()).norm() < 1e-9);
    check_axis(*f.analytic());
  }
}

TEST_CASE("analytic: a perturbed B-spline and a free-form face are not recognised, the part file keeps the metadata") {
  const Handle(Geom_BSplineSurface) cyl = Handle(Geom_BSplineSurface)::DownCast(
      as_bspline(new Geom_CylindricalSurface(frame(), 12.5), 0, 1.5 * kPi, -10, 25));
  REQUIRE(!cyl.IsNull());
  const gp_Pnt p = cyl->Pole(2, 2);
  cyl->SetPole(2, 2, gp_Pnt(p.X(), p.Y(), p.Z() + 1e-4));
  CHECK(!imported(cyl, "cyl-perturbed").analytic());
  CHECK(!imported(freeform_surface(), "freeform").analytic());

  // Written and read back: the same numbers, exactly as printed.
  const Face f = imported(new Geom_SphericalSurface(frame(), 30), "sphere-roundtrip");
  REQUIRE(f.analytic());
  Part part;
  part.faces.push_back(f);
  const Part back = parse_part_json(part_to_json_text(part), "roundtrip.json");
  REQUIRE(back.faces[0].analytic());
  CHECK(back.faces[0].analytic()->type == AnalyticSurface::Type::sphere);
  CHECK(std::abs(back.faces[0].analytic()->radius - f.analytic()->radius) < 1e-12);
  CHECK((back.faces[0].analytic()->origin - f.analytic()->origin).norm() < 1e-12);
}
