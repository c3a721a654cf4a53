// furrow compare --align cmm end to end (docs/registration.md "Alignments"):
// the measurement frame is the part frame, so each reported deviation is the
// analytic distance of the written point from the nominal surface. Oracle: a
// sphere cap of radius 30 about the origin and points written at a known
// radius along known directions - their deviation is |p| - 30 (contact
// points) or |p| - 30 - r (probe centres), exactly, whatever a best fit would
// make of them.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "geometry/primitives.hpp"
#include "inspection/comparison_file.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;

namespace {

struct Written {
  std::string csv;
  std::vector<double> offset;  // planted deviation per point [mm]
};

// `n` points on the cap (latitude 0.4..1.2 rad, longitude 0.2..6 rad, well
// inside the face) at radius 30 + offset (+ the probe radius for centres).
// The offsets: a location error (the sphere's centre moved 0.03 mm along z
// in the measurement frame, seen as 0.03 sin(latitude) to first order - here
// exactly, as the distance from the nominal sphere) plus a form error.
Written write_points(int n, double probe_radius) {
  Written w;
  w.csv = "id,x,y,z\n";
  const Eigen::Vector3d shift(0, 0, 0.03);
  for (int k = 0; k < n; ++k) {
    const double lat = 0.4 + 0.8 * std::fmod(0.618034 * k, 1.0);
    const double lon = 0.2 + 5.8 * (k + 0.5) / n;
    const Eigen::Vector3d d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    const double form = 0.012 * std::sin(3.0 * k);
    // On the sphere of radius 30 + form about the shifted centre.
    const Eigen::Vector3d contact = shift + (30 + form) * d;
    const Eigen::Vector3d p = contact + probe_radius * contact.normalized();
    w.offset.push_back(contact.norm() - 30);
    char line[200];
    std::snprintf(line, sizeof line, "P%d,%.10f,%.10f,%.10f\n", k + 1, p.x(), p.y(), p.z());
    w.csv += line;
  }
  return w;
}

}  // namespace

TEST_CASE("compare --align cmm: each deviation is the analytic distance of the written point, no fit") {
  const std::string dir = test::scratch_dir("cli-compare-cmm");
  const Part cap = test::one_face("cap", make_sphere(30, 0, 2 * 3.141592653589793, 0.3, 1.3));
  write_part_json(cap, dir + "/cap.json");
  for (const bool centres : {false, true}) {
    CAPTURE(centres);
    const double r = centres ? 2 : 0;
    const Written w = write_points(60, r);
    const std::string m = dir + (centres ? "/centres.csv" : "/contact.csv");
    test::write_text(m, w.csv);
    std::vector<std::string> args = {"compare", dir + "/cap.json", "--measurements", m, "--align", "cmm",
                                     "--tolerance", "0.1", "--out", dir + "/cmm.json"};
    if (centres) {
      args.insert(args.end(), {"--points", "centre", "--probe-diameter", "4"});
    } else {
      args.insert(args.end(), {"--points", "contact"});
    }
    const test::CliResult run = test::run_furrow(args);
    INFO(run.out << run.err);
    // Every |offset| is below 0.05 (0.03 + 0.012): inside the +-0.05 zone.
    CHECK(run.status == 0);
    const ComparisonDocument doc = read_comparison(dir + "/cmm.json");
    CHECK(doc.alignment.method == "cmm");
    REQUIRE(doc.points.size() == w.offset.size());
    double worst = 0, largest = 0;
    for (std::size_t i = 0; i < doc.points.size(); ++i) {
      CAPTURE(i);
      CHECK(doc.points[i].evaluated);
      CHECK(doc.points[i].outlier.empty());
      CHECK(doc.points[i].foot_location == "interior");
      worst = std::max(worst, std::abs(doc.points[i].deviation - w.offset[i]));
      largest = std::max(largest, std::abs(w.offset[i]));
      // The identity: registered where measured.
      CHECK((doc.points[i].registered - doc.points[i].measured).norm() < 1e-9);
    }
    CHECK(worst < 1e-7);
    CHECK(doc.summary.evaluated == w.offset.size());
    CHECK(doc.summary.profile == doctest::Approx(2 * largest).epsilon(1e-6).scale(0));
    // The best fit of the same points is recorded beside it: it moves the
    // sphere back onto the points' centre, leaving about the form error
    // (2 x 0.012), well below the cmm frame's form + location.
    REQUIRE(doc.alignment.bestfit_profile.has_value());
    CHECK(*doc.alignment.bestfit_profile < 2 * 0.0125);
    CHECK(*doc.alignment.bestfit_profile < doc.summary.profile - 0.02);
  }
}

TEST_CASE("compare --align cmm: a point planted outside the zone fails the part, the same point a best fit keeps") {
  const std::string dir = test::scratch_dir("cli-compare-cmm-fail");
  const Part cap = test::one_face("cap", make_sphere(30, 0, 2 * 3.141592653589793, 0.3, 1.3));
  write_part_json(cap, dir + "/cap.json");
  const Written w = write_points(60, 0);
  test::write_text(dir + "/m.csv", w.csv);
  // Tolerance +-0.035: the location error (up to 0.03 + 0.012) takes some
  // points out of the zone in the cmm frame, not in the best fit.
  int outside = 0;
  for (double d : w.offset) outside += std::abs(d) > 0.035;
  REQUIRE(outside > 0);
  const test::CliResult cmm =
      test::run_furrow({"compare", dir + "/cap.json", "--measurements", dir + "/m.csv", "--points", "contact",
                        "--align", "cmm", "--tolerance", "0.07", "--out", dir + "/cmm.json"});
  INFO(cmm.out << cmm.err);
  CHECK(cmm.status == 1);
  const ComparisonDocument doc = read_comparison(dir + "/cmm.json");
  CHECK(doc.summary.out_of_tolerance == static_cast<std::size_t>(outside));
  for (std::size_t i = 0; i < doc.points.size(); ++i) {
    REQUIRE(doc.points[i].in_tolerance.has_value());
    CHECK(*doc.points[i].in_tolerance == (std::abs(w.offset[i]) <= 0.035));
  }
  const test::CliResult best = test::run_furrow({"compare", dir + "/cap.json", "--measurements", dir + "/m.csv",
                                                 "--points", "contact", "--tolerance", "0.07", "--out",
                                                 dir + "/best.json"});
  CHECK(best.status == 0);
}
