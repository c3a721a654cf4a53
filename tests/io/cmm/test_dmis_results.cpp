// DMIS results (dmis_results.hpp): points and the datum features a plan
// measures, continuations, comments, units and the datum set in force.
#include <doctest/doctest.h>

#include "base/error.hpp"
#include "io/cmm/dmis_results.hpp"
#include "io/cmm/measurement_file.hpp"

using namespace furrow;

namespace {

MeasurementSet read_dmis(const std::string& text) {
  return parse_measurements(text, "run.dmo", MeasurementFormat::dmis, {});
}

std::string error_of(const std::string& text) {
  try {
    read_dmis(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("DMIS results: plane, circle and cylinder actuals with their values and datum") {
  const std::string text =
      "DMISMN/'fixture',05.2\n"
      "UNITS/MM,ANGDEC\n"
      "F(PL1)=FEAT/PLANE,CART,0,0,0,0,0,1\n"
      "FA(PL1)=FEAT/PLANE,CART,0.5,-1.25,0.003,0,0,2\n"
      "D(A)=DATSET/FA(PL1)\n"
      "FA(CIR1)=FEAT/CIRCLE,INNER,CART,10,20,0.25,0,0,1,12.004\n"
      "fa(cyl_2) = feat/cylndr, outer, cart, 1, 2, 3, 1, 0, 0, 25.5, $\n"
      "   40 $$ length\n"
      "D(ABC)=DATSET/FA(PL1),FA(CIR1)\n"
      "FA(CYL3)=FEAT/CYLNDR,INNER,CART,0,0,0,0,1,0,8\n"
      "FA(P1)=FEAT/POINT,CART,1,2,3,0,0,1\n";
  const MeasurementSet set = read_dmis(text);
  REQUIRE(set.features.size() == 4);
  const MeasuredFeature& plane = set.features[0];
  CHECK(plane.label == "PL1");
  CHECK(plane.type == MeasuredFeatureType::plane);
  CHECK(plane.position == Eigen::Vector3d(0.5, -1.25, 0.003));
  CHECK(plane.direction == Eigen::Vector3d(0, 0, 1));  // normalised
  CHECK(plane.diameter == 0);
  CHECK(plane.datum.empty());  // measured before any DATSET
  CHECK(plane.line == 4);
  const MeasuredFeature& circle = set.features[1];
  CHECK(circle.type == MeasuredFeatureType::circle);
  CHECK(circle.inner);
  CHECK(circle.position == Eigen::Vector3d(10, 20, 0.25));
  CHECK(circle.diameter == 12.004);
  CHECK(circle.datum == "A");
  const MeasuredFeature& boss = set.features[2];
  CHECK(boss.label == "cyl_2");
  CHECK(boss.type == MeasuredFeatureType::cylinder);
  CHECK_FALSE(boss.inner);
  CHECK(boss.direction == Eigen::Vector3d(1, 0, 0));
  CHECK(boss.diameter == 25.5);
  CHECK(boss.length == 40);
  CHECK(boss.line == 7);
  CHECK(set.features[3].length == 0);  // no length given
  CHECK(set.features[3].datum == "ABC");
  REQUIRE(set.points.size() == 1);  // points stay points
  CHECK(set.points[0].datum == "ABC");
}

TEST_CASE("DMIS results: inch units scale positions and diameters, continuations and comments") {
  const std::string text =
      "$$ results of run 7\n"
      "UNITS/INCH,ANGDEC\n"
      "FA(H1)=FEAT/CIRCLE,INNER,CART,1,2,0,$\n"
      "  0,0,1,$   $$ the normal\n"
      "  0.5\n"
      "F(P1)=FEAT/POINT,CART,1,1,1,0,0,1\n"
      "FA(P1)=FEAT/POINT,CART,1.001,1,1,0,0,1\n"
      "UNITS/MM\n"
      "FA(P2)=FEAT/POINT,CART,25.4,0,0,1,0,0\n";
  const MeasurementSet set = read_dmis(text);
  REQUIRE(set.features.size() == 1);
  CHECK(set.features[0].position == Eigen::Vector3d(25.4, 50.8, 0));
  CHECK(set.features[0].diameter == 0.5 * 25.4);
  CHECK(set.features[0].line == 3);
  REQUIRE(set.points.size() == 2);
  CHECK(set.points[0].xyz == 25.4 * Eigen::Vector3d(1.001, 1, 1));
  CHECK(*set.points[0].nominal == Eigen::Vector3d(25.4, 25.4, 25.4));
  CHECK(set.points[1].xyz == Eigen::Vector3d(25.4, 0, 0));
  CHECK(set.kind == ProbePointKind::contact);
}

TEST_CASE("DMIS results: malformed features name the line") {
  CHECK(error_of("FA(C)=FEAT/CIRCLE,CART,0,0,0,0,0,1,10\n") == "run.dmo:1: FEAT/CIRCLE needs INNER or OUTER, got \"CART\"");
  CHECK(error_of("FA(C)=FEAT/CIRCLE,INNER,POL,0,0,0,0,0,1,10\n") ==
        "run.dmo:1: only CART features are supported, got \"POL\"");
  CHECK(error_of("\nFA(C)=FEAT/CYLNDR,INNER,CART,0,0,0,0,0,1\n") ==
        "run.dmo:2: FEAT/CYLNDR,INNER|OUTER,CART needs x,y,z,i,j,k,diam[,length] (7 or 8 numbers), got 6");
  CHECK(error_of("FA(C)=FEAT/CIRCLE,OUTER,CART,0,0,0,0,0,1,-2\n") == "run.dmo:1: the diameter must be positive");
  CHECK(error_of("FA(S)=FEAT/PLANE,CART,0,0,0,0,0,0\n") == "run.dmo:1: i, j, k: the direction (i, j, k) has zero length");
  CHECK(error_of("FA(S)=FEAT/PLANE,CART,0,0,0,0,0,1\nFA(S)=FEAT/PLANE,CART,0,0,0,0,0,1\nFA(P)=FEAT/POINT,CART,0,0,0,0,0,1\n") ==
        "run.dmo:2: duplicate feature \"S\" (first on line 1)");
  CHECK(error_of("FA(S)=FEAT/PLANE,CART,0,0,0,0,0,1\n") == "run.dmo: no measured points in the file");
}

TEST_CASE("DMIS results: every DMIS output extension in any case, .res is sniffed") {
  for (const char* path : {"a.dmo", "a.DMS", "a.Out", "a.dmi", "a.DMIS", "a.res"})
    CHECK(measurement_format_from_path(path) == MeasurementFormat::dmis);
  CHECK(measurement_format_from_path("a.RES", "FA(P)=FEAT/POINT,CART,0,0,0,0,0,1\n") == MeasurementFormat::dmis);
  CHECK(measurement_format_from_path("a.res", "\n00012 # X(1), Y(2), Z(3)\n") == MeasurementFormat::ippdme_log);
  CHECK(measurement_format_from_path("a.LOG") == MeasurementFormat::ippdme_log);
  CHECK(measurement_format_from_path("a.ipp") == MeasurementFormat::ippdme_log);
  CHECK_THROWS_AS(measurement_format_from_path("a.dat"), InputError);
}
