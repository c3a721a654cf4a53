// The line of sight of a scan (io/scan/scan_preprocess.hpp step 5,
// docs/scan.md "Line of sight"): a PCD's VIEWPOINT is the scanner's
// position unless it is PCL's "0 0 0 1 0 0 0"; --viewpoint (file units)
// gives the same result; the options' bad values are refused naming them.
// Oracle: a spherical cap seen from a point on its axis, whose normals are
// known exactly (p / |p|), so the points beyond the incidence limit are
// counted by brute force.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/numbers.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/scan/scan_preprocess.hpp"
#include "io/scan/scan_read.hpp"
#include "support/deviation_cloud.hpp"
#include "support/input_error.hpp"
#include "support/run_cli.hpp"
#include "support/scan_files.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kRadius = 30;                             // [mm] of the sphere
const Eigen::Vector3d kViewpoint(12, -8, 160);             // [mm] the scanner, off the axis a little
const Eigen::Vector3d kCentre(400, -250, 90);              // the sphere's centre in the file's frame

// A cap of the sphere up to 80 degrees from its pole, on a 0.5 mm grid of
// its projection: incidences from 0 to well beyond 75 degrees.
std::vector<Eigen::Vector3d> cap(std::vector<Eigen::Vector3d>& normals) {
  std::vector<Eigen::Vector3d> points;
  const double reach = kRadius * std::sin(radians(80));
  for (double x = -reach; x <= reach; x += 0.5)
    for (double y = -reach; y <= reach; y += 0.5) {
      const double r2 = x * x + y * y;
      if (r2 > reach * reach) continue;
      const Eigen::Vector3d n(x / kRadius, y / kRadius, std::sqrt(kRadius * kRadius - r2) / kRadius);
      points.push_back(kCentre + kRadius * n);
      normals.push_back(n);
    }
  return points;
}

// Brute force: the angle between each exact normal and the line to the viewpoint.
std::size_t grazing_by_brute_force(const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<Eigen::Vector3d>& normals, double limit) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d sight = (kCentre + kViewpoint - points[i]).normalized();
    count += degrees(std::acos(std::min(1.0, std::abs(normals[i].dot(sight))))) > limit;
  }
  return count;
}

std::string viewpoint_header(const Eigen::Vector3d& v) {
  char text[120];
  std::snprintf(text, sizeof text, "%.17g %.17g %.17g 1 0 0 0", v.x(), v.y(), v.z());
  return text;
}

}  // namespace

TEST_CASE("scan viewpoint: a PCD's VIEWPOINT rejects the same grazing points as --viewpoint, PCL's default none") {
  const std::string dir = scratch_dir("scan-viewpoint");
  std::vector<Eigen::Vector3d> normals;
  const std::vector<Eigen::Vector3d> points = cap(normals);
  REQUIRE(points.size() > 8000);
  const Eigen::Vector3d scanner = kCentre + kViewpoint;
  write_bytes(dir + "/with.pcd", pcd_text(points, true, viewpoint_header(scanner)));
  write_bytes(dir + "/without.pcd", pcd_text(points, true));

  const ScanCloud with = read_scan(dir + "/with.pcd");
  REQUIRE(with.viewpoint.has_value());
  // PCL reads the header's numbers as floats.
  CHECK((*with.viewpoint - scanner).norm() < 1e-4);
  const ScanCloud without = read_scan(dir + "/without.pcd");
  CHECK_FALSE(without.viewpoint.has_value());

  ScanPreprocessOptions weights;
  weights.incidence_weights = true;
  const ScanPreprocessed from_file = preprocess_scan(with, weights);
  ScanPreprocessOptions given = weights;
  given.viewpoint = Eigen::Vector3d(static_cast<float>(scanner.x()), static_cast<float>(scanner.y()),
                                    static_cast<float>(scanner.z()));  // as the file's floats hold it
  const ScanPreprocessed from_option = preprocess_scan(without, given);
  CHECK(from_file.view == ScanViewKind::viewpoint);
  CHECK(from_file.view_source == "file");
  CHECK(from_option.view_source == "option");
  CHECK(from_file.grazing == from_option.grazing);
  CHECK(from_file.fit == from_option.fit);
  CHECK_FALSE(from_file.fit_weights.empty());
  CHECK(from_file.fit_weights == from_option.fit_weights);
  REQUIRE(from_file.incidence.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) CHECK(from_file.incidence[i] == from_option.incidence[i]);

  // Against the exact normals: the estimated ones put few points on the
  // other side of the limit (measured below; bound 2 % of the points).
  const std::size_t expected = grazing_by_brute_force(points, normals, 75);
  REQUIRE(expected > 500);
  const long difference = static_cast<long>(from_file.grazing_count) - static_cast<long>(expected);
  MESSAGE("grazing: " << from_file.grazing_count << " with estimated normals, " << expected << " by brute force");
  CHECK(std::abs(difference) < static_cast<long>(points.size() / 50));
  // Every point far from the limit is judged as the exact normal says.
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d sight = (scanner - points[i]).normalized();
    const double angle = degrees(std::acos(std::min(1.0, std::abs(normals[i].dot(sight)))));
    if (std::abs(angle - 75) > 3) CHECK(from_file.grazing[i] == (angle > 75));
  }

  // PCL's default header: no view, nothing rejected.
  const ScanPreprocessed blind = preprocess_scan(without, ScanPreprocessOptions{});
  CHECK(blind.view == ScanViewKind::none);
  CHECK(blind.grazing_count == 0);
  CHECK(blind.fit_weights.empty());

  // In inches: the file's VIEWPOINT and --viewpoint are both in the file's
  // units, scaled as its points are.
  std::vector<Eigen::Vector3d> inches;
  for (const Eigen::Vector3d& p : points) inches.push_back(p / 25.4);
  write_bytes(dir + "/inch.pcd", pcd_text(inches, true, viewpoint_header(scanner / 25.4)));
  write_bytes(dir + "/inch_plain.pcd", pcd_text(inches, true));
  const ScanPreprocessed inch_file = preprocess_scan(read_scan(dir + "/inch.pcd", 25.4), ScanPreprocessOptions{});
  ScanPreprocessOptions inch_given;
  const ScanCloud plain = read_scan(dir + "/inch_plain.pcd", 25.4);
  const ScanCloud inch_cloud = read_scan(dir + "/inch.pcd", 25.4);
  inch_given.viewpoint = *inch_cloud.viewpoint / 25.4;  // the file's numbers, in inches
  const ScanPreprocessed inch_option = preprocess_scan(plain, inch_given);
  CHECK(inch_file.grazing == inch_option.grazing);
  CHECK(std::abs(static_cast<long>(inch_file.grazing_count) - static_cast<long>(expected)) <
        static_cast<long>(points.size() / 50));
}

TEST_CASE("scan viewpoint: a largest incidence outside (0, 90), a zero view direction and two views are refused") {
  std::vector<Eigen::Vector3d> normals;
  ScanCloud cloud;
  cloud.file = "cap.pcd";
  cloud.points = cap(normals);
  cloud.read = cloud.points.size();
  for (const double bad : {0.0, 90.0, 95.0, -10.0, std::nan("")}) {
    CAPTURE(bad);
    ScanPreprocessOptions o;
    o.view_direction = Eigen::Vector3d(0, 0, -1);
    o.max_incidence_deg = bad;
    CHECK(input_error_of([&] { preprocess_scan(cloud, o); }).find("--max-incidence") != std::string::npos);
  }
  ScanPreprocessOptions zero;
  zero.view_direction = Eigen::Vector3d::Zero();
  CHECK(input_error_of([&] { preprocess_scan(cloud, zero); }).find("--view-direction") != std::string::npos);
  ScanPreprocessOptions both;
  both.view_direction = Eigen::Vector3d(0, 0, -1);
  both.viewpoint = Eigen::Vector3d(0, 0, 100);
  const std::string two = input_error_of([&] { preprocess_scan(cloud, both); });
  CHECK(two.find("--viewpoint") != std::string::npos);
  CHECK(two.find("--view-direction") != std::string::npos);

  // On the command line: exit 2 naming the option, before any file is read.
  const std::string part = source_path("examples/parts/mould.json");
  const std::string scan = source_path("examples/scans/mould_dent.ply");
  const std::string dir = scratch_dir("scan-viewpoint-cli");
  struct Bad {
    std::vector<std::string> flags;
    std::string named;
  };
  for (const Bad& b : std::vector<Bad>{{{"--max-incidence", "90"}, "--max-incidence"},
                                       {{"--max-incidence", "0"}, "--max-incidence"},
                                       {{"--max-incidence", "120"}, "--max-incidence"},
                                       {{"--view-direction", "0,0,0"}, "--view-direction"},
                                       {{"--viewpoint", "1,2"}, "--viewpoint"},
                                       {{"--viewpoint", "0,0,100", "--view-direction", "0,0,-1"}, "--view-direction"}}) {
    CAPTURE(b.named);
    std::vector<std::string> args = {"compare", part, "--scan", scan, "--out", dir + "/c.json"};
    args.insert(args.end(), b.flags.begin(), b.flags.end());
    const CliResult r = run_furrow(args);
    CHECK(r.status == 2);
    CHECK(r.err.find(b.named) != std::string::npos);
  }
}

TEST_CASE("scan viewpoint: furrow compare --view-direction flags grazing points 4 in the deviation cloud and counts them") {
  // The bundled scan (examples/scans/README.md): seen along (0.2, 0.1, -1)
  // in the part frame, the part turned by --misalign 5,-3,170,10,20,30 into
  // the scanner's frame; its file normals are the nominal ones. The
  // scanner kept points up to 75 degrees: a limit of 30 makes some grazing.
  const std::string part = source_path("examples/parts/mould.json");
  const std::string scan = source_path("examples/scans/mould_dent.ply");
  const std::string dir = scratch_dir("scan-viewpoint-compare");
  Misalignment m;
  m.rotation_deg = {5, -3, 170};
  m.translation = {10, 20, 30};
  const Eigen::Vector3d view = m.part_to_cmm().linear() * Eigen::Vector3d(0.2, 0.1, -1).normalized();
  const ScanCloud cloud = read_scan(scan);
  REQUIRE(cloud.normals.size() == cloud.points.size());
  std::vector<bool> expected;
  std::size_t expected_count = 0;
  for (const Eigen::Vector3f& n : cloud.normals) {
    expected.push_back(degrees(std::acos(std::min(1.0, std::abs(n.cast<double>().dot(view))))) > 30);
    expected_count += expected.back();
  }
  REQUIRE(expected_count > 50);
  char direction[100];
  std::snprintf(direction, sizeof direction, "%.17g,%.17g,%.17g", view.x(), view.y(), view.z());
  const CliResult r = run_furrow({"compare", part, "--scan", scan, "--view-direction", direction, "--max-incidence",
                                  "30", "--incidence-weights", "--out", dir + "/c.json", "--deviations", dir + "/d.ply"});
  REQUIRE(r.status <= 1);  // FAIL by the planted dent, or PASS: compared either way
  const nlohmann::json c = nlohmann::json::parse(slurp(dir + "/c.json"));
  const nlohmann::json& sight = c["preprocessing"]["line_of_sight"];
  CHECK(sight["view"] == "direction");
  CHECK(sight["source"] == "option");
  CHECK(sight["max_incidence"] == 30);
  CHECK(sight["grazing"] == expected_count);
  CHECK(sight["weights"] == "cos_incidence");
  CHECK(c["points"]["removed"]["grazing"] == expected_count);
  const std::vector<DeviationPoint> points = parse_deviation_ply(slurp(dir + "/d.ply"));
  REQUIRE(points.size() == expected.size());
  std::size_t flagged = 0, disagree = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    flagged += points[i].outlier == 4;
    disagree += (points[i].outlier == 4) != expected[i];
    if (points[i].outlier == 4) CHECK(points[i].deviation == 0.0f);
  }
  CHECK(flagged == expected_count);
  CHECK(disagree == 0);
  CHECK(r.out.find("line of sight: direction") != std::string::npos);

  // Without a view: said so, nothing flagged grazing.
  const CliResult blind = run_furrow({"compare", part, "--scan", scan, "--out", dir + "/blind.json", "--deviations",
                                      dir + "/blind.ply"});
  REQUIRE(blind.status <= 1);
  const nlohmann::json b = nlohmann::json::parse(slurp(dir + "/blind.json"));
  CHECK(b["preprocessing"]["line_of_sight"]["view"] == "none");
  CHECK(b["preprocessing"]["line_of_sight"]["note"].get<std::string>().find("no point rejected") != std::string::npos);
  CHECK(b["points"]["removed"]["grazing"] == 0);
  for (const DeviationPoint& p : parse_deviation_ply(slurp(dir + "/blind.ply"))) CHECK(p.outlier != 4);
  CHECK(blind.out.find("line of sight: none") != std::string::npos);
}
