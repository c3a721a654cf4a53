// End-to-end: furrow compare PART --scan on a synthetic scan of the mould
// (examples/parts/mould.json) as scanner software writes it - binary PLY
// with double x y z, colour, intensity and float normals, in a scanner frame
// turned by 170 degrees and moved, 5 um noise along the normal, 0.5 % spray
// 0.3 to 3 mm off, and a dent of known depth and radius. The oracle is the
// sampling itself: a point moved by h along the normal at its surface point
// projects back onto that point (h is far below the radius of curvature), so
// its true deviation is exactly what was planted (dent + noise), and its
// true part-frame position the surface point moved by it.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <map>
#include <optional>
#include <set>

#include "base/json_fields.hpp"
#include "base/numbers.hpp"
#include "io/part_file.hpp"
#include "partition/regions_file.hpp"
#include "support/deviation_cloud.hpp"
#include "support/run_cli.hpp"
#include "support/scan_files.hpp"

using namespace furrow;
using furrow::test::DeviationPoint;
using furrow::test::parse_deviation_ply;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

struct SyntheticScan {
  std::vector<Eigen::Vector3d> surface;  // part frame, on the surface
  std::vector<Eigen::Vector3d> normal;   // part frame
  std::vector<Eigen::Vector2d> uv;       // of the surface point on the mould's one face
  std::vector<double> planted;           // true deviation (dent + noise) [mm]; spray: its offset
  std::set<std::size_t> spray;
  Eigen::Isometry3d to_scanner = Eigen::Isometry3d::Identity();  // part -> scanner frame
  Eigen::Vector3d dent_centre = Eigen::Vector3d::Zero();
};

constexpr double kDentDepth = 0.05;   // [mm]
constexpr double kDentRadius = 6.0;   // [mm]
constexpr double kNoise = 0.005;      // [mm] 1 sigma along the normal

// Raised-cosine dent: -depth at the centre, 0 from kDentRadius on (3-D distance).
double dent(const Eigen::Vector3d& p, const Eigen::Vector3d& centre) {
  const double rho = (p - centre).norm();
  return rho >= kDentRadius ? 0.0 : -kDentDepth * 0.5 * (1 + std::cos(kPi * rho / kDentRadius));
}

SyntheticScan make_scan(int nu, int nv) {
  const Part part = read_part(kMould);
  const Face& face = part.faces.at(0);
  const ParameterDomain& d = face.domain();
  SyntheticScan s;
  s.dent_centre = face.geometry(d.u0 + 0.35 * d.width_u(), d.v0 + 0.55 * d.width_v()).point;
  std::mt19937_64 rng(43);
  std::normal_distribution<double> noise(0, kNoise);
  std::uniform_real_distribution<double> off(0.3, 3.0), jitter(-0.4, 0.4);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      // A jittered grid, kept off the domain's edges by half a step so no
      // point lies beyond the part.
      const double u = d.u0 + (i + 0.5 + jitter(rng)) / nu * d.width_u();
      const double v = d.v0 + (j + 0.5 + jitter(rng)) / nv * d.width_v();
      const DifferentialGeometry g = face.geometry(u, v);
      const std::size_t k = s.surface.size();
      s.surface.push_back(g.point);
      s.normal.push_back(g.normal);
      s.uv.emplace_back(u, v);
      if (k % 200 == 17) {
        s.spray.insert(k);
        s.planted.push_back((k % 400 == 17 ? 1 : -1) * off(rng));
      } else {
        s.planted.push_back(dent(g.point, s.dent_centre) + noise(rng));
      }
    }
  s.to_scanner = Eigen::Translation3d(250.0, -40.0, 1200.0) *
                 Eigen::AngleAxisd(170.0 * kPi / 180, Eigen::Vector3d(0.3, -0.5, 0.8).normalized());
  return s;
}

// In the scanner frame, in mm, or in inches with `scale` 1 / 25.4.
std::vector<Eigen::Vector3d> scanner_points(const SyntheticScan& s, double scale = 1.0) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = 0; k < s.surface.size(); ++k)
    out.push_back(scale * (s.to_scanner * (s.surface[k] + s.planted[k] * s.normal[k])));
  return out;
}

}  // namespace

TEST_CASE("compare scan of the mould turned 170 degrees recovers the dent and the transform") {
  const std::string dir = test::scratch_dir("cli-scan-mould");
  const SyntheticScan s = make_scan(220, 180);  // 39,600 points, about 0.45 mm apart
  test::PlyOptions o;
  o.extras = true;  // colour, intensity and (unit +z, wrong) normals are read past or replaced
  for (std::size_t k = 0; k < s.surface.size(); ++k) o.normals.push_back((s.to_scanner.linear() * s.normal[k]).cast<float>());
  const std::string scan = dir + "/scan.ply";
  test::write_bytes(scan, test::ply_text(scanner_points(s), o));
  const auto r = test::run_furrow({"compare", kMould, "--scan", scan, "--out", dir + "/c.json", "--deviations",
                                   dir + "/d.ply"});
  INFO(r.out << r.err);
  CHECK(r.status == 1);  // the 50 um dent lies outside the default +-25 um zone
  CHECK(r.out.find("FAIL") != std::string::npos);

  const std::vector<DeviationPoint> cloud = parse_deviation_ply(test::slurp(dir + "/d.ply"));
  REQUIRE(cloud.size() == s.surface.size());
  std::size_t spray_flagged = 0, good_flagged = 0, off_part = 0;
  double worst_position = 0, worst_deviation = 0, sum_sq = 0;
  std::size_t compared = 0;
  double deepest = 0;
  std::size_t dent_points = 0;
  double dent_error_sum = 0;
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    const DeviationPoint& p = cloud[k];
    if (s.spray.count(k)) {
      spray_flagged += p.outlier == 1 || p.outlier == 2;
      continue;
    }
    if (p.outlier == 1 || p.outlier == 2) ++good_flagged;
    if (p.outlier == 3) ++off_part;
    if (p.outlier != 0) continue;
    const Eigen::Vector3d truth = s.surface[k] + s.planted[k] * s.normal[k];
    worst_position = std::max(worst_position, (p.xyz - truth).norm());
    const double error = p.deviation - s.planted[k];
    worst_deviation = std::max(worst_deviation, std::abs(error));
    sum_sq += error * error;
    ++compared;
    const double planted_dent = dent(s.surface[k], s.dent_centre);
    deepest = std::min(deepest, static_cast<double>(p.deviation));
    if (planted_dent < -0.9 * kDentDepth) {  // the dent's floor: within about 2 mm of its centre
      ++dent_points;
      dent_error_sum += p.deviation - planted_dent;
    }
  }
  const double rms = std::sqrt(sum_sq / static_cast<double>(compared));
  MESSAGE("scan: " << compared << " compared, spray " << spray_flagged << "/" << s.spray.size() << ", good flagged "
                   << good_flagged << ", off part " << off_part << "; position error max " << worst_position * 1e3
                   << " um; deviation error rms " << rms * 1e3 << " um, max " << worst_deviation * 1e3
                   << " um; deepest " << deepest * 1e3 << " um; dent floor mean error "
                   << dent_error_sum / static_cast<double>(dent_points) * 1e3 << " um over " << dent_points);
  CHECK(spray_flagged == s.spray.size());
  CHECK(good_flagged < s.surface.size() / 100);  // docs/scan.md: at most 1 % of good points
  CHECK(off_part == 0);
  // The transform: every compared point where the planted offset put it,
  // to the noise level. Across the normal the fit is good to a fraction of
  // a micrometre; along the mould's shallow surface (it curves by 12 mm over
  // 100) a slide changes the deviations little and is fixed less well:
  // measured 3.5 um at the worst point.
  CHECK(worst_position < kNoise);
  // Deviations: the planted ones (dent + noise) within 1 um each.
  CHECK(worst_deviation < 0.001);
  CHECK(rms < 0.0005);
  // The dent's depth: its floor reads the planted depth to within the
  // noise's standard error (5 um / sqrt(points)), here well under 1 um.
  REQUIRE(dent_points > 20);
  CHECK(std::abs(dent_error_sum / static_cast<double>(dent_points)) < 3 * kNoise / std::sqrt(dent_points) + 2e-4);
  CHECK(deepest < -kDentDepth + 4 * kNoise);
  CHECK(deepest > -kDentDepth - 5 * kNoise);

  // comparison.json: counts, per reason, and no per-point records.
  const json_fields::json c = json_fields::json::parse(test::slurp(dir + "/c.json"));
  CHECK(c["kind"] == "scan");
  CHECK(c["points"]["read"] == s.surface.size());
  CHECK(c["points"]["kept"].get<std::size_t>() == compared);
  CHECK(c["points"]["removed"]["spray_far"].get<std::size_t>() + c["points"]["removed"]["spray_near"].get<std::size_t>() ==
        spray_flagged + good_flagged);
  CHECK(c["preprocessing"]["normals"] == "file");
  CHECK(c["summary"]["verdict"] == "FAIL");
  CHECK(c["summary"]["out_of_tolerance"].get<std::size_t>() > 0);
  CHECK(std::abs(c["summary"]["deviations"]["min"].get<double>() - deepest) < 1e-6);
  // The transform, scanner -> part, is the inverse of the one applied: its
  // rotation within 1e-4 rad (the slide above over the part's 50 mm
  // half-size); its translation is checked through the points above (the
  // scanner's origin lies 1.2 m away, where the same rotation error moves
  // it 0.1 mm).
  Eigen::Matrix3d rotation;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rotation(i, j) = c["registration"]["transform"][i][j].get<double>();
  const double turn = Eigen::AngleAxisd(rotation * s.to_scanner.linear()).angle();
  MESSAGE("rotation error " << turn << " rad");
  CHECK(turn < 1e-4);
}

TEST_CASE("compare scan bad clouds and options exit 2 naming the file") {
  const std::string dir = test::scratch_dir("cli-scan-bad");
  const std::string out = dir + "/c.json";
  struct Bad {
    std::string name, bytes;
  };
  for (const Bad& b : {Bad{"empty.ply", ""}, Bad{"garbage.ply", "ply\nformat nonsense\n\x01\x02\x03"},
                       Bad{"truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty "
                                            "double x\nproperty double y\nproperty double z\nend_header\n\x01\x02"},
                       Bad{"garbage.pcd", "\x7f" "ELF not a cloud"}}) {
    CAPTURE(b.name);
    const std::string path = dir + "/" + b.name;
    test::write_bytes(path, b.bytes);
    const auto r = test::run_furrow({"compare", kMould, "--scan", path, "--out", out});
    CHECK(r.status == 2);
    CHECK(r.err.find(path) != std::string::npos);
    CHECK(!std::filesystem::exists(out));
  }
  const auto both = test::run_furrow({"compare", kMould, "--scan", dir + "/empty.ply", "--measurements", "m.csv",
                                      "--out", out});
  CHECK(both.status == 2);
  CHECK(both.err.find("--measurements does not apply to --scan") != std::string::npos);
  const auto voxel = test::run_furrow({"compare", kMould, "--scan", dir + "/empty.ply", "--voxel", "-1",
                                       "--out", out});
  CHECK(voxel.status == 2);
  CHECK(voxel.err.find("--voxel") != std::string::npos);
}

namespace {

// `env_assignment` is put in front of the CLI inside the shell command.
test::CliResult run_with_env(const std::string& env_assignment, const std::string& args, const std::string& dir) {
  const std::string cmd = "env " + env_assignment + " " + test::shell_quote(FURROW_CLI) + " " + args + " > " +
                          test::shell_quote(dir + "/out") + " 2> " + test::shell_quote(dir + "/err") + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  test::CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = test::slurp(dir + "/out");
  r.err = test::slurp(dir + "/err");
  return r;
}

}  // namespace

TEST_CASE("furrow needs no PCL or VTK library to start") {
  const std::string dir = test::scratch_dir("scan-module-start");
  const test::CliResult trace = run_with_env("LD_TRACE_LOADED_OBJECTS=1", "", dir);
  REQUIRE(trace.status == 0);
  CHECK(trace.out.find("libstdc++") != std::string::npos);  // the loader's list is really there
  CHECK(trace.out.find("libpcl") == std::string::npos);
  CHECK(trace.out.find("libvtk") == std::string::npos);
}

TEST_CASE("compare scan without its scan module: exit 3, the place looked at named, nothing written") {
  const std::string dir = test::scratch_dir("scan-module-missing");
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(i, 0.5 * i, 20);
  test::write_bytes(dir + "/s.ply", test::ply_text(points, test::PlyOptions{}));
  const std::string out = dir + "/c.json";
  const test::CliResult missing =
      run_with_env("FURROW_SCAN_MODULE=/nonexistent/furrow_scan.so",
                   "compare " + test::shell_quote(kMould) + " --scan " + test::shell_quote(dir + "/s.ply") +
                       " --out " + test::shell_quote(out),
                   dir);
  CHECK(missing.status == 3);
  CHECK(missing.err.find("/nonexistent/furrow_scan.so: no such file") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
  // A file that is no PLY is refused before the module is looked for.
  test::write_bytes(dir + "/t.ply", "solid ascii stl\n");
  const test::CliResult plain =
      run_with_env("FURROW_SCAN_MODULE=/nonexistent/furrow_scan.so",
                   "compare " + test::shell_quote(kMould) + " --scan " + test::shell_quote(dir + "/t.ply") +
                       " --out " + test::shell_quote(out),
                   dir);
  CHECK(plain.status == 2);
  CHECK(plain.err.find("furrow_scan.so") == std::string::npos);
}

TEST_CASE("compare scan in inches with a partition gives per-region statistics of the planted deviations") {
  const std::string dir = test::scratch_dir("cli-scan-regions");
  const SyntheticScan s = make_scan(160, 130);  // 20,800 points
  const std::string scan = dir + "/scan_inch.ply";
  test::PlyOptions o;
  o.format = "binary_big_endian";
  test::write_bytes(scan, test::ply_text(scanner_points(s, 1 / 25.4), o));
  REQUIRE(test::run_furrow({"partition", kMould, "--out", dir + "/regions.json"}).status == 0);
  const auto r = test::run_furrow({"compare", kMould, "--scan", scan, "--units", "inch", "--regions",
                                   dir + "/regions.json", "--tolerance", "0.2", "--out", dir + "/c.json",
                                   "--deviations", dir + "/d.ply"});
  INFO(r.out << r.err);
  CHECK(r.status == 0);  // the 50 um dent lies inside +-100 um
  CHECK(r.out.find("PASS") != std::string::npos);
  const std::vector<DeviationPoint> cloud = parse_deviation_ply(test::slurp(dir + "/d.ply"));
  REQUIRE(cloud.size() == s.surface.size());
  // The oracle: each compared point's region is the partition's region at
  // the (u, v) the test sampled, and its deviation the planted one.
  const RegionMap regions = read_regions(dir + "/regions.json");
  std::map<int, std::vector<double>> planted_by_region;
  double worst = 0;
  std::size_t compared = 0;
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    if (cloud[k].outlier != 0) continue;
    ++compared;
    worst = std::max(worst, std::abs(cloud[k].deviation - s.planted[k]));
    if (const std::optional<int> id = regions.region_at(0, s.uv[k].x(), s.uv[k].y()))
      planted_by_region[*id].push_back(s.planted[k]);
  }
  // Half the noise: the sparser cloud fixes the slide along the mould a
  // little less well than the one above (measured 1.4 um at the worst point).
  CHECK(worst < kNoise / 2);
  const json_fields::json c = json_fields::json::parse(test::slurp(dir + "/c.json"));
  CHECK(c["sources"]["scan_units"] == "inch");
  const auto& listed = c["summary"]["regions"];
  REQUIRE(listed.size() == planted_by_region.size());
  std::size_t counted = 0;
  for (const auto& g : listed) {
    const int id = g["region"].get<int>();
    CAPTURE(id);
    REQUIRE(planted_by_region.count(id) == 1);
    const std::vector<double>& values = planted_by_region[id];
    double sum = 0;
    for (const double v : values) sum += v;
    const std::size_t count = g["deviations"]["count"].get<std::size_t>();
    counted += count;
    // A point within a micrometre of a region's border may fall on the
    // other side of it after the fit: counts agree within 1 %.
    CHECK(std::abs(static_cast<double>(count) - static_cast<double>(values.size())) <=
          0.01 * static_cast<double>(values.size()) + 1);
    CHECK(std::abs(g["deviations"]["mean"].get<double>() - sum / static_cast<double>(values.size())) < 0.001);
  }
  CHECK(counted == compared);

  // The removed points per region: recounted from the (u, v) each point
  // was planted at. A spray point lies along the normal of that surface
  // point, so its projection's foot is that point (its offset is far below
  // the mould's radius of curvature); so does a good point's.
  std::map<int, std::array<std::size_t, 3>> recount;  // region (-1 none) -> far, near, off part
  std::size_t removed = 0;
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    if (cloud[k].outlier == 0) continue;
    ++removed;
    const std::optional<int> id = regions.region_at(0, s.uv[k].x(), s.uv[k].y());
    ++recount[id.value_or(-1)][cloud[k].outlier - 1];
  }
  REQUIRE(removed >= s.spray.size());
  const auto& by_region = c["points"]["removed_by_region"];
  REQUIRE(by_region.is_array());
  std::size_t listed_removed = 0;
  for (const auto& g : by_region) {
    const int id = g["region"].is_null() ? -1 : g["region"].get<int>();
    CAPTURE(id);
    const std::array<std::size_t, 3> got = {g["spray_far"].get<std::size_t>(), g["spray_near"].get<std::size_t>(),
                                            g["off_part"].get<std::size_t>()};
    listed_removed += got[0] + got[1] + got[2];
    REQUIRE(recount.count(id) == 1);
    for (int k = 0; k < 3; ++k) CHECK(got[k] == recount[id][k]);
  }
  CHECK(by_region.size() == recount.size());
  CHECK(listed_removed == removed);
}

TEST_CASE("compare scan flags the table around the part as off the part and still fits the part") {
  const std::string dir = test::scratch_dir("cli-scan-table");
  const SyntheticScan s = make_scan(120, 100);  // 12,000 points on the mould (100 x 80 mm)
  std::vector<Eigen::Vector3d> points = scanner_points(s);
  // The table the part lies on, scanned around it: a 5 to 15 mm wide frame
  // 3 mm below the mould's lowest point, beyond its edges.
  std::vector<Eigen::Vector3d> table;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-15, 115), y(-15, 95);
  std::normal_distribution<double> noise(0, kNoise);
  while (table.size() < 3000) {
    const Eigen::Vector3d p(x(rng), y(rng), 15 + noise(rng));
    if (p.x() > -5 && p.x() < 105 && p.y() > -5 && p.y() < 85) continue;
    table.push_back(p);
    points.push_back(s.to_scanner * p);
  }
  const std::string scan = dir + "/scan.ply";
  test::write_bytes(scan, test::ply_text(points, test::PlyOptions{}));
  const auto r = test::run_furrow({"compare", kMould, "--scan", scan, "--tolerance", "0.2", "--out", dir + "/c.json",
                                   "--deviations", dir + "/d.ply"});
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  const std::vector<DeviationPoint> cloud = parse_deviation_ply(test::slurp(dir + "/d.ply"));
  REQUIRE(cloud.size() == s.surface.size() + table.size());
  std::size_t table_off = 0, table_compared = 0, part_off = 0;
  double worst = 0;
  for (std::size_t k = 0; k < cloud.size(); ++k) {
    if (k >= s.surface.size()) {
      table_off += cloud[k].outlier == 3;
      table_compared += cloud[k].outlier == 0;
      continue;
    }
    part_off += cloud[k].outlier == 3;
    if (cloud[k].outlier == 0) worst = std::max(worst, std::abs(cloud[k].deviation - s.planted[k]));
  }
  MESSAGE("table: " << table_off << " of " << table.size() << " off the part; part points off: " << part_off
                    << "; worst deviation error " << worst * 1e3 << " um");
  // No table point is compared: each is off the part or, where the table
  // is scanned more sparsely than the part, flagged by the far-spray rule
  // (a density rule; measured: 353 of 3000).
  CHECK(table_compared == 0);
  CHECK(table_off > table.size() * 3 / 4);
  CHECK(part_off == 0);
  CHECK(worst < kNoise / 2);
  const json_fields::json c = json_fields::json::parse(test::slurp(dir + "/c.json"));
  CHECK(c["points"]["removed"]["off_part"].get<std::size_t>() == table_off);
}
