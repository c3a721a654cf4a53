// CSV dialects (measurement_csv.hpp): every way CMM software and Excel write
// the same three points must read back as exactly those points.
#include <doctest/doctest.h>

#include "base/error.hpp"
#include "io/cmm/measurement_csv.hpp"
#include "io/cmm/measurement_file.hpp"

using namespace furrow;

namespace {

// The points every file below holds, written out by hand in each dialect.
struct Reference {
  const char* id;
  Eigen::Vector3d xyz, ijk;
};
const Reference kReference[] = {{"P1", {12.5, -40.25, 3.125}, {0, 0, 1}},
                                {"P2", {0.001, 1000, -7.5}, {1, 0, 0}},
                                {"P3", {100.75, 0.5, -0.375}, {0, -1, 0}}};

MeasurementSet read_csv(const std::string& text, const CsvDialect& dialect = {}) {
  MeasurementReadOptions o;
  o.probe_diameter = 2;
  o.dialect = dialect;
  return parse_measurements(text, "m.csv", MeasurementFormat::csv, o);
}

void check_reference(const MeasurementSet& set, bool directions = true) {
  REQUIRE(set.points.size() == 3);
  CHECK(set.ids_from_file);
  for (int k = 0; k < 3; ++k) {
    CAPTURE(k);
    CHECK(set.points[k].id == kReference[k].id);
    CHECK(set.points[k].xyz == kReference[k].xyz);
    if (directions) {
      REQUIRE(set.points[k].ijk.has_value());
      CHECK(*set.points[k].ijk == kReference[k].ijk);
    }
  }
}

std::string error_of(const std::string& text, const CsvDialect& dialect = {}) {
  try {
    read_csv(text, dialect);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("CSV dialects: comma, semicolon with decimal comma, tab, blanks give the same points") {
  check_reference(read_csv("id,x,y,z,i,j,k\n"
                           "P1,12.5,-40.25,3.125,0,0,1\n"
                           "P2,0.001,1000,-7.5,1,0,0\n"
                           "P3,100.75,0.5,-0.375,0,-1,0\n"));
  check_reference(read_csv("id;x;y;z;i;j;k\n"
                           "P1;12,5;-40,25;3,125;0;0;1\n"
                           "P2;0,001;1000;-7,5;1;0;0\n"
                           "P3;100,75;0,5;-0,375;0;-1;0\n"));
  check_reference(read_csv("ID\tX\tY\tZ\tI\tJ\tK\n"
                           "P1\t12.5\t-40.25\t3.125\t0\t0\t1\n"
                           "P2\t0.001\t1000\t-7.5\t1\t0\t0\n"
                           "P3\t100.75\t0.5\t-0.375\t0\t-1\t0\n"));
  check_reference(read_csv("  id   x   y   z   i  j  k\n"
                           "P1   12.5   -40.25  3.125  0 0 1\n"
                           "P2 0.001 1000 -7.5 1 0 0   \n"
                           "P3\t100.75 0.5 -0.375 0 -1 0\n"));
}

TEST_CASE("CSV dialects: RFC 4180 quotes hold the delimiter and doubled quotes") {
  // Quoted fields may hold the delimiter (here the decimal comma) and doubled quotes.
  check_reference(read_csv("\"Point ID\";\"X\";\"Y\";\"Z\";\"I\";\"J\";\"K\"\n"
                           "\"P1\";\"12,5\";\"-40,25\";\"3,125\";0;0;1\n"
                           "\"P2\"; \"0,001\" ;1000;\"-7,5\";1;0;0\n"
                           "P3;\"100,75\";\"0,5\";\"-0,375\";0;-1;0\n"));
  const MeasurementSet quoted = read_csv("id,x,y,z\n\"A,1 \"\"left\"\"\",1,2,3\n\"B\",7,8,9\n");
  CHECK(quoted.points[0].id == "A,1 \"left\"");
  CHECK(quoted.points[1].xyz == Eigen::Vector3d(7, 8, 9));
}

TEST_CASE("CSV dialects: Excel CSV UTF-8 with a byte-order mark and CR LF") {
  check_reference(read_csv("\xEF\xBB\xBFid;x;y;z;i;j;k\r\n"
                           "P1;12,5;-40,25;3,125;0;0;1\r\n"
                           "P2;0,001;1000;-7,5;1;0;0\r\n"
                           "\r\n"
                           "P3;100,75;0,5;-0,375;0;-1;0\r\n"));
}

TEST_CASE("CSV dialects: a header mapped by the user, a saved dialect") {
  CsvDialect d;
  d.columns = parse_csv_columns("id=Punkt,x=Xm,y=Ym,z=Zm,i=Nx,j=Ny,k=Nz", "--columns");
  const std::string text = "Punkt|Xm|Ym|Zm|Nx|Ny|Nz|Temp\n"
                           "P1|12.5|-40.25|3.125|0|0|1|20.1\n"
                           "P2|0.001|1000|-7.5|1|0|0|20.2\n"
                           "P3|100.75|0.5|-0.375|0|-1|0|20.3\n";
  std::string tabbed = text;
  for (char& c : tabbed)
    if (c == '|') c = '\t';
  check_reference(read_csv(tabbed, d));
  // The same from a saved dialect that also names the delimiter and the units.
  const CsvDialect saved = parse_csv_dialect(
      R"({"delimiter": "tab", "decimal_comma": false, "units": "mm",
          "columns": {"id": "PUNKT", "x": " xm ", "y": "Ym", "z": "Zm", "i": "Nx", "j": "Ny", "k": "Nz"}})",
      "d.json");
  CHECK(saved.delimiter == '\t');
  check_reference(read_csv(tabbed, saved));
  CHECK_THROWS_WITH_AS(parse_csv_dialect(R"({"delimiter": ";", "sep": 1})", "d.json"),
                       "d.json: sep: unknown member (delimiter, decimal_comma, columns, units)", InputError);
  CHECK_THROWS_WITH_AS(parse_csv_columns("id=Name,q=Q", "--columns"),
                       "--columns: unknown field \"q\" (id, x, y, z, i, j, k, nx, ny, nz)", InputError);
}

TEST_CASE("CSV dialects: nominal/actual/deviation tables use the actual columns") {
  const MeasurementSet a = read_csv("Name;Nominal X;Nominal Y;Nominal Z;Actual X;Actual Y;Actual Z;Deviation;I;J;K\n"
                                    "P1;12;-40;3;12,5;-40,25;3,125;0,1;0;0;1\n"
                                    "P2;0;1000;-7;0,001;1000;-7,5;-0,5;1;0;0\n"
                                    "P3;100;0;0;100,75;0,5;-0,375;0,2;0;-1;0\n");
  check_reference(a);
  REQUIRE(a.points[0].nominal.has_value());
  CHECK(*a.points[0].nominal == Eigen::Vector3d(12, -40, 3));
  CHECK(*a.points[2].nominal == Eigen::Vector3d(100, 0, 0));
  const MeasurementSet b = read_csv("ID,X nom,Y nom,Z nom,X act,Y act,Z act,Dev,Tol+,Tol-\n"
                                    "P1,12,-40,3,12.5,-40.25,3.125,0.1,0.05,-0.05\n"
                                    "P2,0,1000,-7,0.001,1000,-7.5,-0.5,0.05,-0.05\n"
                                    "P3,100,0,0,100.75,0.5,-0.375,0.2,0.05,-0.05\n");
  check_reference(b, false);
  CHECK(*b.points[1].nominal == Eigen::Vector3d(0, 1000, -7));
}

TEST_CASE("CSV dialects: malformed files name the line and the column") {
  CHECK(error_of("id;x;y;z\nP1;1,5;2,x;3\n") == "m.csv:2: column 3 (y): \"2,x\" is not a number");
  CHECK(error_of("id\tx\ty\tz\nP1\t1\t2\t3\n\nP2\t1\t\t3\n") == "m.csv:4: column 3 (y): \"\" is not a number");
  CHECK(error_of("id,x,y,z\n\"P1,1,2,3\n") == "m.csv:2: column 1: a quote is not closed on its line");
  CHECK(error_of("id,x,y,z\nP1,\"1\"x,2,3\n") == "m.csv:2: column 2: text after a closing quote");
  CsvDialect comma;
  comma.delimiter = ',';
  comma.decimal_comma = true;
  CHECK(error_of("id,x,y,z\nP1,1,2,3\n", comma) == "m.csv:1: a decimal comma needs a delimiter other than ','");
  CsvDialect mapped;
  mapped.columns = {{"x", "Foo"}};
  CHECK(error_of("id,x,y,z\nP1,1,2,3\n", mapped) == "m.csv:1: no column \"Foo\" (mapped to x) in the header");
  CHECK(error_of("id,x,Actual X,y,z\n") == "m.csv:1: columns \"x\" and \"Actual X\" are both the actual x");
  CHECK(error_of("id,X nom,Y nom,x,y,z\n") == "m.csv:1: nominal columns x, y, z come together or not at all");
}
