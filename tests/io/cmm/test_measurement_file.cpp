#include <doctest/doctest.h>

#include <random>

#include "base/error.hpp"
#include "io/cmm/measurement_csv.hpp"
#include "io/cmm/measurement_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

MeasurementReadOptions centres(double diameter = 2) {
  MeasurementReadOptions o;
  o.probe_diameter = diameter;
  return o;
}

std::string error_of(const std::string& text, MeasurementFormat format,
                     MeasurementReadOptions options = centres()) {
  try {
    parse_measurements(text, "m.csv", format, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("CSV: any column order and case, directions normalised, inch converted") {
  const std::string text =
      "# exported by a CMM\n"
      "Z, id ,X,y,k,j,i\n"
      "1.5,P1,10,20,2,0,0\n"
      "\n"
      "-3,P2,0.25,-7,0,0,-0.5\n";
  MeasurementReadOptions o = centres(4);
  o.units = "inch";
  const MeasurementSet set = parse_measurements(text, "m.csv", MeasurementFormat::csv, o);
  REQUIRE(set.points.size() == 2);
  CHECK(set.ids_from_file);
  CHECK(set.kind == ProbePointKind::probe_centre);
  CHECK(set.probe_radius == 2);  // the diameter is in mm whatever the file units
  CHECK(set.points[0].id == "P1");
  CHECK(set.points[0].line == 3);
  CHECK(set.points[0].xyz == 25.4 * Eigen::Vector3d(10, 20, 1.5));
  CHECK(*set.points[0].ijk == Eigen::Vector3d(0, 0, 1));
  CHECK(set.points[1].line == 5);
  CHECK(*set.points[1].ijk == Eigen::Vector3d(-1, 0, 0));
}

TEST_CASE("CSV without ids numbers the points, contact points need no probe") {
  MeasurementReadOptions o;
  o.kind = ProbePointKind::contact;
  const MeasurementSet set =
      parse_measurements("x,y,z\n1,2,3\n+4,5e1,-.5\n", "m.csv", MeasurementFormat::csv, o);
  CHECK_FALSE(set.ids_from_file);
  CHECK(set.points[1].id == "2");
  CHECK(set.points[1].xyz == Eigen::Vector3d(4, 50, -0.5));
  CHECK(set.probe_radius == 0);
}

TEST_CASE("XYZ text: three or six numbers per line, consistently") {
  const MeasurementSet set =
      parse_measurements("# scan\n1 2 3\n4\t5  6\n", "scan.xyz", MeasurementFormat::xyz, centres());
  CHECK(set.points.size() == 2);
  CHECK(set.points[1].xyz == Eigen::Vector3d(4, 5, 6));
  CHECK_FALSE(set.points[0].ijk.has_value());
  const MeasurementSet six =
      parse_measurements("1 2 3 0 0 2\n", "scan.xyz", MeasurementFormat::xyz, centres());
  CHECK(*six.points[0].ijk == Eigen::Vector3d(0, 0, 1));
  CHECK(error_of("1 2 3\n1 2 3 0 0 1\n", MeasurementFormat::xyz) ==
        "m.csv:2: expected 3 fields like line 1, got 6");
  CHECK(error_of("1 2\n", MeasurementFormat::xyz) ==
        "m.csv:1: expected \"x y z\" or \"x y z i j k\", got 2 fields");
}

TEST_CASE("DMIS results: actuals with their nominals, units, continuations, comments") {
  const std::string text =
      "DMISMN/'furrow mould',4.0\n"
      "UNITS/MM,ANGDEC\n"
      "$$ nominals\n"
      "F(P001)=FEAT/POINT,CART,10.0,20.0,30.0,0,0,1\n"
      "F(P002)=FEAT/POINT,CART,11.0,21.0,31.0,$\n"
      "  0,0,1\n"
      "MEAS/POINT,F(P001),1\n"
      "PTMEAS/CART,10.0,20.0,30.0,0,0,1\n"
      "ENDMES\n"
      "FA(P001)=FEAT/POINT,CART,10.001,20.002,29.998,0,0,1  $$ in tolerance\n"
      "FA(CIR1)=FEAT/CIRCLE,INNER,CART,0,0,0,0,0,1,10\n"
      "UNITS/INCH\n"
      "FA(p002) = FEAT/POINT, CART, 1, 2, 3, 0, 0, -1\n"
      "ENDFIL\n";
  const MeasurementSet set = parse_measurements(text, "run.res", MeasurementFormat::dmis, {});
  REQUIRE(set.points.size() == 2);
  CHECK(set.kind == ProbePointKind::contact);  // CMMs write compensated points
  CHECK(set.points[0].id == "P001");
  CHECK(set.points[0].line == 10);
  CHECK(set.points[0].xyz == Eigen::Vector3d(10.001, 20.002, 29.998));
  REQUIRE(set.points[0].nominal.has_value());
  CHECK(*set.points[0].nominal == Eigen::Vector3d(10, 20, 30));
  CHECK(set.points[1].id == "p002");
  CHECK(set.points[1].xyz == 25.4 * Eigen::Vector3d(1, 2, 3));
  CHECK_FALSE(set.points[1].nominal.has_value());  // labels are matched exactly
  CHECK(error_of("FA(A)=FEAT/POINT,POL,1,2,3,0,0,1\n", MeasurementFormat::dmis, {}) ==
        "m.csv:1: only CART points are supported, got \"POL\"");
  CHECK(error_of("FA(A)=FEAT/POINT,CART,1,2,3\n", MeasurementFormat::dmis, {}) ==
        "m.csv:1: FEAT/POINT,CART needs x,y,z,i,j,k (6 numbers), got 3");
  CHECK(error_of("FA(A)=FEAT/POINT,CART,1,2,3,0,0,1\nFA(A)=FEAT/POINT,CART,1,2,3,0,0,1\n",
                 MeasurementFormat::dmis, {}) == "m.csv:2: duplicate id \"A\" (first on line 1)");
  CHECK(error_of("UNITS/CM\n", MeasurementFormat::dmis, {}) ==
        "m.csv:1: UNITS/CM is not supported (MM or INCH)");
}

TEST_CASE("bad CSV files: one error naming file and line") {
  const auto csv = MeasurementFormat::csv;
  CHECK(error_of("id,x,y,z\nA,1,2,3\nB,1,2,3\nA,4,5,6\n", csv) ==
        "m.csv:4: duplicate id \"A\" (first on line 2)");
  CHECK(error_of("id,x,y,z\nA,1,nan,3\n", csv) ==
        "m.csv:2: column 3 (y): \"nan\" is not a finite number");
  CHECK(error_of("id,x,y,z\nA,1,2,inf\n", csv) ==
        "m.csv:2: column 4 (z): \"inf\" is not a finite number");
  CHECK(error_of("id,x,y,z\nA,1,2mm,3\n", csv) == "m.csv:2: column 3 (y): \"2mm\" is not a number");
  CHECK(error_of("id,x,y,z\nA,1,,3\n", csv) == "m.csv:2: column 3 (y): \"\" is not a number");
  CHECK(error_of("id,x,y\nA,1,2\n", csv) == "m.csv:1: missing column \"z\" (need x, y, z)");
  CHECK(error_of("id,x,y,z,temp\n", csv) ==
        "m.csv:1: unknown column \"temp\" (the header names id, x, y, z, i, j, k)");
  CHECK(error_of("x,y,z,x\n", csv) == "m.csv:1: column \"x\" appears twice");
  CHECK(error_of("x,y,z,i,j\n", csv) == "m.csv:1: columns i, j, k come together or not at all");
  CHECK(error_of("id,x,y,z\nA,1,2,3,4\n", csv) == "m.csv:2: expected 4 fields, got 5");
  CHECK(error_of("id,x,y,z\nA,1,2\n", csv) == "m.csv:2: expected 4 fields, got 3");
  CHECK(error_of("x,y,z,i,j,k\n1,2,3,0,0,0\n", csv) ==
        "m.csv:2: i, j, k: the direction (i, j, k) has zero length");
  CHECK(error_of("id,x,y,z\n ,1,2,3\n", csv) == "m.csv:2: empty id");
  CHECK(error_of("# nothing\n", csv) == "m.csv: no header line (expected id,x,y,z[,i,j,k])");
  CHECK(error_of("id,x,y,z\n", csv) == "m.csv: no measured points in the file");
  CHECK(error_of("id,x,y,z\nA,1,2,3\n", csv, MeasurementReadOptions{}) ==
        "m.csv: the points are probe centres, so the probe diameter is needed "
        "(--probe-diameter, or a plan with a probe)");
  MeasurementReadOptions o = centres();
  o.units = "furlong";
  CHECK(error_of("id,x,y,z\nA,1,2,3\n", csv, o) ==
        "m.csv: units: unknown units \"furlong\" (expected \"mm\" or \"inch\")");
}

TEST_CASE("the CSV writer round-trips every coordinate bit for bit") {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> c(-500, 500);
  MeasurementSet set;
  set.probe_radius = 1.5;
  for (int k = 0; k < 200; ++k) {
    MeasuredPoint p;
    p.id = "P" + std::to_string(k);
    p.xyz = {c(rng), c(rng), c(rng)};
    p.ijk = Eigen::Vector3d(c(rng), c(rng), c(rng)).normalized();
    set.points.push_back(p);
  }
  const std::string dir = test::scratch_dir("measurement-roundtrip");
  write_measurements_csv(set, dir + "/m.csv");
  const MeasurementSet back = read_measurements(dir + "/m.csv", centres(3));
  REQUIRE(back.points.size() == set.points.size());
  for (std::size_t k = 0; k < set.points.size(); ++k) {
    CHECK(back.points[k].id == set.points[k].id);
    CHECK(back.points[k].xyz == set.points[k].xyz);
    // Unit vectors are re-normalised on reading: equal to rounding.
    CHECK((*back.points[k].ijk - *set.points[k].ijk).norm() < 1e-15);
  }
  CHECK_THROWS_WITH_AS(read_measurements(dir + "/m.stl", centres()),
                       doctest::Contains("unknown measurement file type \".stl\""), InputError);
}
