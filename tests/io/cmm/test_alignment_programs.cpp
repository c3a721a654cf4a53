// Part alignment: the datums chosen on a part built with OpenCASCADE (the
// reference box with its boss and dimple) against a brute-force oracle of
// OpenCASCADE's own face areas and normals; datum points on their faces
// (OpenCASCADE's distance), reachable; the DMIS and I++ DME programs
// measuring them before the free-form points, read back by the strict
// readers; plan.json carrying them; and the free-form mould getting a
// manual best-fit alignment, never nothing.
#include <doctest/doctest.h>

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepLProp_SLProps.hxx>

#include "../cad/cad_reference.hpp"
#include "base/error.hpp"
#include "geometry/closest_point.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cmm/dmis_program_reader.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/part_file.hpp"
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

struct OccPlane {
  TopoDS_Face face;
  Eigen::Vector3d normal;  // outward
  double area = 0;
};

// Every planar face of the solid with its outward normal and area, from
// OpenCASCADE alone.
std::vector<OccPlane> occ_planes(const TopoDS_Shape& solid) {
  std::vector<OccPlane> out;
  for (const TopoDS_Face& f : faces_of(solid)) {
    BRepAdaptor_Surface s(f);
    if (s.GetType() != GeomAbs_Plane) continue;
    gp_Dir n = s.Plane().Axis().Direction();
    if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
    out.push_back({f, eig(n), occt_area(f)});
  }
  return out;
}

double occ_distance(const TopoDS_Face& f, const Eigen::Vector3d& p) {
  BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(occ(p)).Vertex(), f);
  REQUIRE(d.IsDone());
  return d.Value();
}

struct Fixture : test::CadPart {
  ReferenceModel model;
  Fixture() : Fixture(make_reference_model()) {}
  explicit Fixture(ReferenceModel m) : CadPart(m.solids[0], "alignment-box"), model(std::move(m)) {}
};

Fixture& box() {
  static Fixture f;
  return f;
}

bool along(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() < 1e-9; }

}  // namespace

TEST_CASE("datums: the largest plane facing up, the largest wall, the largest wall across it (OpenCASCADE oracle)") {
  Fixture& f = box();
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  REQUIRE(a.method == PartAlignment::Method::datums);
  REQUIRE(a.datums.size() == 3);
  const std::vector<OccPlane> planes = occ_planes(f.model.solids[0]);
  // Oracle: the largest areas by OpenCASCADE among planes facing +z, facing
  // ±x/±y, and facing the other horizontal axis than the chosen wall.
  double up = 0, wall = 0;
  for (const OccPlane& p : planes) {
    if (along(p.normal, Eigen::Vector3d::UnitZ())) up = std::max(up, p.area);
    if (std::abs(p.normal.z()) < 1e-9) wall = std::max(wall, p.area);
  }
  const DatumFeature& A = a.datums[0];
  const DatumFeature& B = a.datums[1];
  const DatumFeature& C = a.datums[2];
  CHECK(A.kind == DatumFeature::Kind::plane);
  CHECK(B.kind == DatumFeature::Kind::line);
  CHECK(C.kind == DatumFeature::Kind::point);
  CHECK(face_area(f.part.faces[A.face_index], 64) == doctest::Approx(up).epsilon(0.01));
  CHECK(face_area(f.part.faces[B.face_index], 64) == doctest::Approx(wall).epsilon(0.01));
  CHECK(along(A.normal, Eigen::Vector3d::UnitZ()));
  CHECK(std::abs(B.normal.dot(C.normal)) < 1e-9);  // perpendicular walls
  double across = 0;
  for (const OccPlane& p : planes)
    if (std::abs(p.normal.z()) < 1e-9 && std::abs(p.normal.dot(B.normal)) < 1e-9) across = std::max(across, p.area);
  CHECK(face_area(f.part.faces[C.face_index], 64) == doctest::Approx(across).epsilon(0.01));
  // The box is 80 x 60 x 20 from the origin: the top at z = 20, walls on
  // x = 0 | 80 and y = 0 | 60; the frame origin is where A, B and C meet.
  CHECK(A.origin.z() == doctest::Approx(ReferenceGeometry::box_z));
  CHECK(a.origin.z() == doctest::Approx(ReferenceGeometry::box_z));
  for (int k = 0; k < 2; ++k) {
    const double v = a.origin[k];
    const double far = k == 0 ? ReferenceGeometry::box_x : ReferenceGeometry::box_y;
    CHECK((std::abs(v) < 1e-9 || std::abs(v - far) < 1e-9));
  }
  CHECK(A.points.size() == 4);
  CHECK(B.points.size() == 2);
  CHECK(C.points.size() == 1);
  // The line's direction points along + of the axis it directs.
  CHECK(B.direction[B.axis == 'X' ? 0 : 1] == doctest::Approx(1));
}

TEST_CASE("datum points lie on their faces, clear of the edges, and the probe reaches them") {
  Fixture& f = box();
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  const std::vector<OccPlane> planes = occ_planes(f.model.solids[0]);
  AccessOptions walls = f.access;
  walls.max_tilt = kPi / 2 + 1e-9;
  for (const DatumFeature& d : a.datums)
    for (const PlannedPoint& p : d.points) {
      CAPTURE(p.id);
      // On the OpenCASCADE face with that normal (inside its boundary: the
      // distance to the bounded face, not to its plane).
      double nearest = 1e9;
      for (const OccPlane& q : planes)
        if (along(q.normal, p.ijk)) nearest = std::min(nearest, occ_distance(q.face, p.xyz));
      CHECK(nearest < 1e-6);
      CHECK(check_access(*f.finder, p.xyz, p.ijk, f.probe, walls).ok());
      CHECK((p.approach - (p.xyz + (f.probe.ball_radius + f.access.approach) * p.ijk)).norm() < 1e-9);
    }
  // Spread: the four points on A span most of the top face.
  double widest = 0;
  for (const PlannedPoint& p : a.datums[0].points)
    for (const PlannedPoint& q : a.datums[0].points) widest = std::max(widest, (p.xyz - q.xyz).norm());
  CHECK(widest > 0.8 * std::hypot(ReferenceGeometry::box_x, ReferenceGeometry::box_y));
}

TEST_CASE("named datums take the faces in the order given, a face that cannot serve is refused by name") {
  Fixture& f = box();
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  DatumChoice named = parse_datum_choice(a.datums[0].face + "," + a.datums[2].face + "," + a.datums[1].face, "--datums");
  const PartAlignment b = choose_alignment(f.part, *f.finder, f.probe, f.access, named);
  REQUIRE(b.method == PartAlignment::Method::datums);
  CHECK(b.datums[1].face == a.datums[2].face);
  CHECK(b.datums[2].face == a.datums[1].face);
  CHECK(b.datums[1].origin_axis == a.datums[2].origin_axis);
  // The boss (a vertical cylinder) named second is a boss datum: both
  // in-plane origins at its axis (OpenCASCADE built it there), the wall
  // named third a line for the direction; a boss is measured from outside.
  std::string cylinder, sphere;
  for (const Face& face : f.part.faces) {
    if (face.analytic() && face.analytic()->type == AnalyticSurface::Type::cylinder) cylinder = face.name();
    if (face.analytic() && face.analytic()->type == AnalyticSurface::Type::sphere) sphere = face.name();
  }
  REQUIRE_FALSE(cylinder.empty());
  REQUIRE_FALSE(sphere.empty());
  named.faces = {a.datums[0].face, cylinder, a.datums[2].face};
  const PartAlignment boss = choose_alignment(f.part, *f.finder, f.probe, f.access, named);
  REQUIRE(boss.datums.size() == 3);
  CHECK(boss.datums[1].kind == DatumFeature::Kind::cylinder);
  CHECK(boss.datums[1].radius == doctest::Approx(ReferenceGeometry::boss_r).epsilon(1e-9));
  CHECK(boss.origin.x() == doctest::Approx(ReferenceGeometry::boss_x).epsilon(1e-9));
  CHECK(boss.origin.y() == doctest::Approx(ReferenceGeometry::boss_y).epsilon(1e-9));
  CHECK(boss.datums[2].kind == DatumFeature::Kind::line);
  for (const PlannedPoint& p : boss.datums[1].points) CHECK(p.ijk.dot(p.xyz - boss.datums[1].origin) > 0);
  const ProbeProgram program = tiny_program_with_alignment(boss, f.access.clearance_z);
  CHECK(dmis_program_text(program).find("F(DATUM_B)=FEAT/CIRCLE,OUTER,CART,20.000000,30.000000,") != std::string::npos);
  // The dimple (a sphere) can be neither; a wall cannot be primary.
  named.faces = {a.datums[0].face, sphere, a.datums[2].face};
  CHECK_THROWS_WITH_AS(choose_alignment(f.part, *f.finder, f.probe, f.access, named),
                       doctest::Contains("is neither a plane nor a cylinder"), InputError);
  named.faces = {a.datums[1].face, a.datums[0].face, a.datums[2].face};
  CHECK_THROWS_WITH_AS(choose_alignment(f.part, *f.finder, f.probe, f.access, named),
                       doctest::Contains("does not face +z"), InputError);
  CHECK_THROWS_AS(parse_datum_choice("top,side", "--datums"), InputError);
}

TEST_CASE("programs measure the datums first, and the strict readers give back the same points") {
  Fixture& f = box();
  const PartAlignment a = choose_alignment(f.part, *f.finder, f.probe, f.access, {});
  ProbeProgram p = tiny_program_with_alignment(a, f.access.clearance_z);
  const std::string dmi = dmis_program_text(p);
  const std::size_t datum_a = dmi.find("F(DATUM_A)=FEAT/PLANE,CART,");
  const std::size_t manual = dmi.find("D(MANUAL)=DATSET/FA(DATUM_A),ZDIR,ZORIG,FA(DATUM_B),");
  const std::size_t datset = dmi.find("D(DATUMS)=DATSET/");
  const std::size_t part_frame = dmi.find("D(PART)=TRANS/XORIG,");
  const std::size_t first = dmi.find("F(P0001)=FEAT/POINT");
  CHECK(dmi.find("F(DATUM_B)=FEAT/LINE,BND,CART,") != std::string::npos);
  CHECK(dmi.find("F(DATUM_C)=FEAT/POINT,CART,") != std::string::npos);
  CHECK(dmi.find("TEXT/MAN,'Datum A: touch 4 point(s)") != std::string::npos);
  REQUIRE(datum_a != std::string::npos);
  REQUIRE(manual != std::string::npos);
  REQUIRE(part_frame != std::string::npos);
  CHECK(datum_a < manual);
  CHECK(manual < datset);
  CHECK(datset < part_frame);
  CHECK(part_frame < first);
  // The frame is saved for the programs that run on this set-up.
  const std::size_t saved = dmi.find("SAVE/DA(PART)\r\n");
  CHECK(part_frame < saved);
  CHECK(saved < first);
  const ProbeProgram back = parse_dmis_program(dmi, "box.dmi");
  check_alignment_read_back(back, a);
  const std::vector<PlannedPoint> want = a.points();
  REQUIRE(back.steps.size() == p.steps.size());
  for (std::size_t k = 0; k < p.steps.size(); ++k) {
    CHECK(back.steps[k].point.xyz == p.steps[k].point.xyz);
    CHECK(back.steps[k].moves_before == p.steps[k].moves_before);  // the alignment's moves are its own
  }
  REQUIRE(back.alignment_final_moves.size() == p.alignment_final_moves.size());
  for (std::size_t k = 0; k < p.alignment_final_moves.size(); ++k)
    CHECK((back.alignment_final_moves[k] - p.alignment_final_moves[k]).cwiseAbs().maxCoeff() <= 5e-7);

  const std::string prg = ippdme_program_text(p);
  const std::size_t last_datum = prg.rfind("PtMeas", prg.find("SetCoordSystem(PartCsy)", prg.find("OnPtMeasReport")));
  CHECK(last_datum < prg.find("PtMeas(X(5.000000), Y(5.000000), Z(5.000000)"));
  // A multi-face STEP part with plane datums: NIST's context checker finds nothing.
  CHECK(nist_checker_findings(prg, "box.prg") == "");
  const ProbeProgram ipp = parse_ippdme_program(prg, "box.prg");
  REQUIRE(ipp.alignment_steps.size() == want.size());
  for (std::size_t k = 0; k < want.size(); ++k)
    CHECK((ipp.alignment_steps[k].point.xyz - want[k].xyz).cwiseAbs().maxCoeff() <= 5e-7);
  REQUIRE(ipp.steps.size() == p.steps.size());
  CHECK(ipp.steps[0].point.order == 1);
}

TEST_CASE("a program on the first one's set-up recalls its saved alignment, and reads back") {
  ProbeProgram p = tiny_program();
  p.recalled_alignment = "PART";
  const std::string dmi = dmis_program_text(p);
  const std::size_t recall = dmi.find("\r\nRECALL/DA(PART)\r\n");
  REQUIRE(recall != std::string::npos);
  CHECK(recall < dmi.find("F(P0001)=FEAT/POINT"));
  CHECK(dmi.find("recalled from the first program") != std::string::npos);
  const ProbeProgram back = parse_dmis_program(dmi, "again.dmi");
  CHECK(back.recalled_alignment == "PART");
  CHECK_FALSE(back.alignment.has_value());
  // Not beside an alignment of its own, and only a label.
  Fixture& f = box();
  ProbeProgram both =
      tiny_program_with_alignment(choose_alignment(f.part, *f.finder, f.probe, f.access, {}), f.access.clearance_z);
  both.recalled_alignment = "PART";
  CHECK_THROWS_WITH_AS(dmis_program_text(both), doctest::Contains("beside an alignment"), InputError);
  p.recalled_alignment = "PART)";
  CHECK_THROWS_WITH_AS(dmis_program_text(p), doctest::Contains("is not a label"), InputError);
}

TEST_CASE("plan.json carries the alignment and reads it back bit for bit") {
  Fixture& f = box();
  InspectionPlan plan = plan_with_alignment(choose_alignment(f.part, *f.finder, f.probe, f.access, {}));
  const std::string text = plan_to_json_text(plan);
  const InspectionPlan back = parse_plan(text, "plan.json");
  REQUIRE(back.alignment.has_value());
  CHECK(plan_to_json_text(back) == text);
  const std::vector<PlannedPoint> want = plan.alignment->points(), got = back.alignment->points();
  REQUIRE(got.size() == want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    CHECK(got[k].xyz == want[k].xyz);
    CHECK(got[k].uv == want[k].uv);
    CHECK(got[k].face_index == want[k].face_index);
  }
  CHECK(back.alignment->origin == plan.alignment->origin);
  CHECK(back.alignment->datums[1].direction == plan.alignment->datums[1].direction);
  check_plan_against_part(back, f.part, "plan.json", 1e-9);
  // An id used by a point and by the alignment is refused.
  plan.alignment->datums[0].points[0].id = plan.points[0].id;
  CHECK_THROWS_AS(parse_plan(plan_to_json_text(plan), "plan.json"), InputError);
}

TEST_CASE("a part of one free-form face gets a manual best-fit alignment, documented, never nothing") {
  const Part mould = read_part(source_path("examples/parts/mould.json"));
  const ClosestPointFinder finder(mould);
  ProbeGeometry probe;
  AccessOptions access;
  access.clearance_z = mould.control_box().max().z() + 3;
  const PartAlignment a = choose_alignment(mould, finder, probe, access, {});
  REQUIRE(a.method == PartAlignment::Method::free_form);
  REQUIRE(a.manual.size() == 3);
  CHECK(a.reason.find("no plane facing +z") != std::string::npos);
  for (const PlannedPoint& p : a.manual) {
    CHECK((mould.faces[p.face_index].surface().point(p.uv.x(), p.uv.y()) - p.xyz).norm() < 1e-12);
    CHECK(check_access(finder, p.xyz, p.ijk, probe, access).ok());
  }
  // Well spread: the smallest side of the triangle is a fair share of the part.
  const double side = std::min({(a.manual[0].xyz - a.manual[1].xyz).norm(), (a.manual[1].xyz - a.manual[2].xyz).norm(),
                                (a.manual[2].xyz - a.manual[0].xyz).norm()});
  CHECK(side > 0.3 * mould.control_box().sizes().head<2>().minCoeff());
  ProbeProgram p = tiny_program_with_alignment(a, access.clearance_z);
  const std::string dmi = dmis_program_text(p);
  CHECK(dmi.find("TEXT/MAN,'Touch M1 on face") < dmi.find("F(P0001)=FEAT"));
  const ProbeProgram back = parse_dmis_program(dmi, "mould.dmi");
  REQUIRE(back.alignment.has_value());
  CHECK(back.alignment->method == PartAlignment::Method::free_form);
  REQUIRE(back.alignment_steps.size() == 3);
  for (std::size_t k = 0; k < 3; ++k)
    CHECK((back.alignment_steps[k].point.xyz - a.manual[k].xyz).cwiseAbs().maxCoeff() <= 5e-7);
  REQUIRE(back.steps.size() == p.steps.size());
  CHECK(back.steps[0].moves_before == p.steps[0].moves_before);
  CHECK(nist_checker_findings(ippdme_program_text(p), "mould.prg") == "");
  const ProbeProgram ipp = parse_ippdme_program(ippdme_program_text(p), "mould.prg");
  CHECK(ipp.alignment_steps.size() == 3);
}
