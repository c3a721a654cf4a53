// `furrow simulate-measurement --scan` end to end: the PLY it writes, read
// back by a parser written here from the PLY format, holds the points the
// library's simulate_scan gives for the same model (in inches when asked),
// and a bad request is exit 2 with nothing written.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "inspection/scan_simulation.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::scratch_dir;
using furrow::test::slurp;
using furrow::test::source_path;

namespace {

struct PlyCloud {
  std::vector<std::string> properties;  // "double x", ...
  std::vector<std::string> comments;
  std::vector<std::vector<double>> rows;
};

// Binary little-endian PLY with one vertex element of uchar, float and
// double properties: enough for what the command writes.
PlyCloud parse_ply(const std::string& bytes) {
  PlyCloud cloud;
  const std::size_t end = bytes.find("end_header\n");
  REQUIRE(end != std::string::npos);
  std::istringstream header(bytes.substr(0, end));
  std::string line;
  std::size_t count = 0;
  std::getline(header, line);
  REQUIRE(line == "ply");
  std::getline(header, line);
  REQUIRE(line == "format binary_little_endian 1.0");
  while (std::getline(header, line)) {
    if (line.rfind("comment ", 0) == 0) cloud.comments.push_back(line.substr(8));
    else if (line.rfind("element vertex ", 0) == 0) count = std::stoul(line.substr(15));
    else if (line.rfind("property ", 0) == 0) cloud.properties.push_back(line.substr(9));
  }
  std::size_t at = end + 11;
  auto take = [&](std::size_t n) {
    REQUIRE(at + n <= bytes.size());
    std::uint64_t bits = 0;
    for (std::size_t b = 0; b < n; ++b) bits |= std::uint64_t(static_cast<unsigned char>(bytes[at + b])) << (8 * b);
    at += n;
    return bits;
  };
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<double> row;
    for (const std::string& p : cloud.properties) {
      if (p.rfind("double ", 0) == 0) {
        const std::uint64_t bits = take(8);
        double v;
        std::memcpy(&v, &bits, 8);
        row.push_back(v);
      } else if (p.rfind("float ", 0) == 0) {
        const auto bits = static_cast<std::uint32_t>(take(4));
        float v;
        std::memcpy(&v, &bits, 4);
        row.push_back(v);
      } else {
        REQUIRE(p.rfind("uchar ", 0) == 0);
        row.push_back(static_cast<double>(take(1)));
      }
    }
    cloud.rows.push_back(row);
  }
  CHECK(at == bytes.size());
  return cloud;
}

}  // namespace

TEST_CASE("simulate-measurement --scan writes the library's scan as a binary PLY, in inches when asked") {
  const std::string dir = scratch_dir("simulate_scan");
  const std::string mould = source_path("examples/parts/mould.json");
  const std::vector<std::string> model = {"--stripe-pitch", "2",     "--point-pitch", "1.5", "--view",
                                          "0.2,0.1,-1",     "--spray", "0.01",        "--misalign",
                                          "5,-3,90,10,20,30", "--seed", "7", "--bump", "50,40,20,8,-0.05"};
  std::vector<std::string> args = {"simulate-measurement", mould, "--scan", "--out", dir + "/scan.ply"};
  args.insert(args.end(), model.begin(), model.end());
  const auto r = run_furrow(args);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("points") != std::string::npos);
  std::vector<std::string> inch = args;
  inch[4] = dir + "/scan_inch.ply";
  inch.push_back("--scan-inch");
  REQUIRE(run_furrow(inch).status == 0);

  ScannerModel m;
  m.stripe_pitch = 2;
  m.point_pitch = 1.5;
  m.view = {0.2, 0.1, -1};
  m.spray_share = 0.01;
  m.part_to_scanner.rotation_deg = {5, -3, 90};
  m.part_to_scanner.translation = {10, 20, 30};
  m.seed = 7;
  m.bumps.push_back({{50, 40, 20}, 8, -0.05});
  const SimulatedScan expected = simulate_scan(read_part(mould), m);

  const PlyCloud mm = parse_ply(slurp(dir + "/scan.ply"));
  const PlyCloud in = parse_ply(slurp(dir + "/scan_inch.ply"));
  CHECK(mm.properties == std::vector<std::string>{"double x", "double y", "double z", "float nx", "float ny",
                                                  "float nz", "uchar red", "uchar green", "uchar blue",
                                                  "float intensity"});
  CHECK(mm.comments.at(1) == "units mm");
  CHECK(in.comments.at(1) == "units inch");
  REQUIRE(mm.rows.size() == expected.points.size());
  REQUIRE(in.rows.size() == expected.points.size());
  double worst_mm = 0, worst_inch = 0, worst_normal = 0;
  for (std::size_t k = 0; k < expected.points.size(); ++k) {
    const Eigen::Vector3d p(mm.rows[k][0], mm.rows[k][1], mm.rows[k][2]);
    const Eigen::Vector3d q(in.rows[k][0], in.rows[k][1], in.rows[k][2]);
    const Eigen::Vector3d n(mm.rows[k][3], mm.rows[k][4], mm.rows[k][5]);
    worst_mm = std::max(worst_mm, (p - expected.points[k]).norm());
    worst_inch = std::max(worst_inch, (25.4 * q - expected.points[k]).norm());
    worst_normal = std::max(worst_normal, (n - expected.normals[k]).norm());
  }
  CHECK(worst_mm == 0);        // doubles, as computed
  CHECK(worst_inch < 1e-12);   // one division by 25.4 and back
  CHECK(worst_normal < 1e-6);  // floats
  // The same command twice writes the same bytes.
  std::vector<std::string> again = args;
  again[4] = dir + "/again.ply";
  REQUIRE(run_furrow(again).status == 0);
  CHECK(slurp(dir + "/again.ply") == slurp(dir + "/scan.ply"));
}

TEST_CASE("simulate-measurement --scan: a plan, probe options, another format or a bad scanner is exit 2, nothing written") {
  const std::string dir = scratch_dir("simulate_scan_bad");
  const std::string mould = source_path("examples/parts/mould.json");
  const std::string out = dir + "/scan.ply";
  struct Bad {
    std::vector<std::string> extra;
    std::string says;
  };
  const std::vector<Bad> cases = {
      {{"--plan", "plan.json"}, "--plan"},
      {{"--noise", "0.01"}, "--scan-noise"},
      {{"--blunders", "3"}, "--spray"},
      {{"--anonymous"}, "--spray"},
      {{"--view", "0,0,0"}, "view"},
      {{"--spray", "1"}, "spray share"},
      {{"--spray", "1.5"}, "--spray"},
      {{"--max-incidence", "95"}, "incidence"},
      {{"--stripe-pitch", "0.0001", "--point-pitch", "0.0001"}, "50 million"},
      {{"--spray-size", "2,1"}, "--spray-size"},
  };
  for (const Bad& c : cases) {
    std::vector<std::string> args = {"simulate-measurement", mould, "--scan", "--out", out};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    CAPTURE(c.says);
    const auto r = run_furrow(args);
    CHECK(r.status == 2);
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(!std::filesystem::exists(out));
  }
  const auto csv = run_furrow({"simulate-measurement", mould, "--scan", "--out", dir + "/scan.csv"});
  CHECK(csv.status == 2);
  CHECK(csv.err.find("PLY") != std::string::npos);
  CHECK(!std::filesystem::exists(dir + "/scan.csv"));
}
