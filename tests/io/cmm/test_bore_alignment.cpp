// Part alignment on a bore: a plate with rounded ends (walls facing +-y
// only, no wall across them) and a through bore, built with OpenCASCADE.
// Without two perpendicular walls the planner takes the top plane, the bore
// and a wall. Oracles: OpenCASCADE's own faces (the bore's axis and radius,
// the distance of every datum point to its face), the access check, and the
// strict DMIS, I++ DME and plan.json readers giving back what was written.
#include <doctest/doctest.h>

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "../cad/cad_reference.hpp"
#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/closest_point.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cmm/dmis_program_reader.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/plan_file.hpp"
#include "planning/alignment_moves.hpp"
#include "planning/datum_selection.hpp"
#include "cad_part_fixture.hpp"
#include "nist_checker.hpp"
#include "program_fixtures.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kLength = 100, kWidth = 50, kHeight = 15;   // the plate, ends rounded with radius kWidth / 2
const Eigen::Vector3d kBore(50, 25, 0);                       // the bore's axis at the bottom
constexpr double kBoreRadius = 8;

TopoDS_Shape rounded_plate_with_bore() {
  const double r = kWidth / 2;
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(r, 0, 0), kLength - 2 * r, kWidth, kHeight).Shape();
  for (const double x : {r, kLength - r})
    plate = BRepAlgoAPI_Fuse(plate, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, r, 0), gp::DZ()), r, kHeight).Shape())
                .Shape();
  const TopoDS_Shape bore =
      BRepPrimAPI_MakeCylinder(gp_Ax2(occ(kBore - Eigen::Vector3d(0, 0, 1)), gp::DZ()), kBoreRadius, kHeight + 2)
          .Shape();
  return BRepAlgoAPI_Cut(plate, bore).Shape();
}

struct Fixture : test::CadPart {
  TopoDS_Shape shape;
  TopoDS_Face bore_face;
  std::vector<TopoDS_Face> faces;
  Fixture() : Fixture(rounded_plate_with_bore()) {}
  explicit Fixture(const TopoDS_Shape& s) : CadPart(s, "alignment-bore"), shape(s) {
    faces = faces_of(shape);
    for (const TopoDS_Face& f : faces) {
      BRepAdaptor_Surface s(f);
      if (s.GetType() == GeomAbs_Cylinder && std::abs(s.Cylinder().Radius() - kBoreRadius) < 1e-9) bore_face = f;
    }
  }
};

Fixture& plate() {
  static Fixture f;
  return f;
}

double occ_distance(const TopoDS_Shape& f, const Eigen::Vector3d& p) {
  BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(occ(p)).Vertex(), f);
  REQUIRE(d.IsDone());
  return d.Value();
}

}  // namespace

TEST_CASE("bore alignment: without a wall across the other, the planner takes the top, the bore and a wall") {
  Fixture& f = plate();
  REQUIRE_FALSE(f.bore_face.IsNull());
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  REQUIRE(a.method == PartAlignment::Method::datums);
  REQUIRE(a.datums.size() == 3);
  const DatumFeature& A = a.datums[0];
  const DatumFeature& B = a.datums[1];
  const DatumFeature& C = a.datums[2];
  CHECK(A.kind == DatumFeature::Kind::plane);
  CHECK(B.kind == DatumFeature::Kind::cylinder);
  CHECK(C.kind == DatumFeature::Kind::line);
  CHECK(a.reason.find("bore") != std::string::npos);
  // The bore as OpenCASCADE has it: axis through (50, 25), radius 8.
  BRepAdaptor_Surface bore(f.bore_face);
  const Eigen::Vector3d axis_point = eig(bore.Cylinder().Axis().Location());
  CHECK(B.radius == doctest::Approx(bore.Cylinder().Radius()).epsilon(1e-9));
  CHECK(std::abs(B.origin.x() - axis_point.x()) < 1e-6);
  CHECK(std::abs(B.origin.y() - axis_point.y()) < 1e-6);
  CHECK(B.direction == Eigen::Vector3d::UnitZ());
  // The frame: z on the top, x and y at the bore's axis; C directs x (the
  // walls face +-y) and sets no origin.
  CHECK(a.origin.x() == doctest::Approx(kBore.x()).epsilon(1e-9));
  CHECK(a.origin.y() == doctest::Approx(kBore.y()).epsilon(1e-9));
  CHECK(a.origin.z() == doctest::Approx(kHeight).epsilon(1e-9));
  CHECK(C.axis == 'X');
  CHECK(C.origin_axis == 0);
  CHECK(std::abs(std::abs(C.normal.y()) - 1) < 1e-9);
  // Four points on the bore, at one height, round the axis (no gap wider
  // than 120 degrees), every datum point on its OpenCASCADE face and
  // reachable by the vertical stylus.
  REQUIRE(B.points.size() == 4);
  std::vector<double> angles;
  for (const PlannedPoint& p : B.points) {
    CHECK(std::abs(p.xyz.z() - B.points[0].xyz.z()) < 1e-9);
    CHECK(std::hypot(p.xyz.x() - kBore.x(), p.xyz.y() - kBore.y()) == doctest::Approx(kBoreRadius).epsilon(1e-9));
    angles.push_back(std::atan2(p.xyz.y() - kBore.y(), p.xyz.x() - kBore.x()));
  }
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * kPi - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
  CHECK(gap < radians(120));
  AccessOptions walls = f.access;
  walls.max_tilt = kPi / 2 + 1e-9;
  for (const DatumFeature& d : a.datums)
    for (const PlannedPoint& p : d.points) {
      CAPTURE(p.id);
      double nearest = 1e9;
      for (const TopoDS_Face& face : f.faces) nearest = std::min(nearest, occ_distance(face, p.xyz));
      CHECK(nearest < 1e-6);
      CHECK(check_access(*f.finder, p.xyz, p.ijk, f.probe, walls).ok());
    }
  for (const PlannedPoint& p : B.points) CHECK(occ_distance(f.bore_face, p.xyz) < 1e-6);
  // A bore's wall faces its axis.
  for (const PlannedPoint& p : B.points) CHECK(p.ijk.dot(p.xyz - B.origin) < 0);
}

TEST_CASE("bore alignment: named faces, and a rounded end refused as a bore with the reason") {
  Fixture& f = plate();
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  const DatumChoice named =
      parse_datum_choice(a.datums[0].face + "," + a.datums[1].face + "," + a.datums[2].face, "--datums");
  const PartAlignment b = choose_alignment(f.part, *f.finder, f.probe, f.access, named);
  REQUIRE(b.datums.size() == 3);
  CHECK(b.datums[1].kind == DatumFeature::Kind::cylinder);
  CHECK(b.datums[2].kind == DatumFeature::Kind::line);
  CHECK(b.origin == a.origin);
  // A rounded end: a half cylinder, its points leave a half turn open.
  std::string end;
  for (const Face& face : f.part.faces)
    if (face.analytic() && face.analytic()->type == AnalyticSurface::Type::cylinder &&
        std::abs(face.analytic()->radius - kWidth / 2) < 1e-6)
      end = face.name();
  REQUIRE_FALSE(end.empty());
  const DatumChoice rounded = parse_datum_choice(a.datums[0].face + "," + end + "," + a.datums[2].face, "--datums");
  CHECK_THROWS_WITH_AS(choose_alignment(f.part, *f.finder, f.probe, f.access, rounded),
                       doctest::Contains("do not go round the axis"), InputError);
}

TEST_CASE("bore alignment: DMIS measures the bore as a circle, sets both origins from it, and reads back") {
  Fixture& f = plate();
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  ProbeProgram p = tiny_program_with_alignment(a, f.access.clearance_z);
  const std::string dmi = dmis_program_text(p);
  const std::size_t circle = dmi.find("F(DATUM_B)=FEAT/CIRCLE,INNER,CART,50.000000,25.000000,");
  REQUIRE(circle != std::string::npos);
  const std::string circle_line = dmi.substr(circle, dmi.find("\r\n", circle) - circle);
  // The axis (0, 0, 1) and the diameter, last.
  const std::string ending = "," + fixed_number(0.0, kDirectionDecimals) + "," + fixed_number(0.0, kDirectionDecimals) +
                             "," + fixed_number(1.0, kDirectionDecimals) + ",16.000000";
  CHECK(circle_line.substr(circle_line.size() - ending.size()) == ending);
  CHECK(dmi.find("MEAS/CIRCLE,F(DATUM_B),4") != std::string::npos);
  CHECK(dmi.find("D(DATUMS)=DATSET/FA(DATUM_A),ZDIR,ZORIG,FA(DATUM_B),XORIG,YORIG,FA(DATUM_C),XDIR\r\n") !=
        std::string::npos);
  const ProbeProgram back = parse_dmis_program(dmi, "plate.dmi");
  check_alignment_read_back(back, a);
  const std::vector<PlannedPoint> want = a.points();
  CHECK(back.alignment->datums[1].radius == doctest::Approx(kBoreRadius).epsilon(1e-9));
  // A circle whose axis is not vertical is refused by the reader, naming the line.
  std::string tilted = dmi;
  const std::string tilted_axis = "," + fixed_number(0.6, kDirectionDecimals) + "," +
                                  fixed_number(0.0, kDirectionDecimals) + "," + fixed_number(0.8, kDirectionDecimals) +
                                  ",16.000000";
  tilted.replace(circle + circle_line.size() - ending.size(), ending.size(), tilted_axis);
  CHECK_THROWS_WITH_AS(parse_dmis_program(tilted, "plate.dmi"), doctest::Contains("axis must be vertical"), InputError);
  // I++ DME measures the same points before setting the part frame.
  CHECK(nist_checker_findings(ippdme_program_text(p), "plate.prg") == "");  // the bore datum too
  const ProbeProgram ipp = parse_ippdme_program(ippdme_program_text(p), "plate.prg");
  REQUIRE(ipp.alignment_steps.size() == want.size());
  for (std::size_t k = 0; k < want.size(); ++k)
    CHECK((ipp.alignment_steps[k].point.xyz - want[k].xyz).cwiseAbs().maxCoeff() <= 5e-7);
}

TEST_CASE("bore alignment: plan.json carries the bore and the wall line and reads them back bit for bit") {
  Fixture& f = plate();
  InspectionPlan plan = plan_with_alignment(choose_alignment(f.part, *f.finder, f.probe, f.access, {}));
  const std::string text = plan_to_json_text(plan);
  CHECK(text.find("\"origin_axis\": \"\"") != std::string::npos);
  const InspectionPlan back = parse_plan(text, "plan.json");
  REQUIRE(back.alignment.has_value());
  CHECK(plan_to_json_text(back) == text);
  CHECK(back.alignment->datums[1].radius == plan.alignment->datums[1].radius);
  // A line that sets neither a direction nor an origin is refused.
  nlohmann::json doc = nlohmann::json::parse(text);
  doc["alignment"]["datums"][2]["axis"] = "";
  CHECK_THROWS_WITH_AS(parse_plan(doc.dump(), "plan.json"), doctest::Contains("sets neither a direction"), InputError);
}
