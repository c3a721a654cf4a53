// `furrow report` of a scan comparison, end to end: a simulated scan of the
// mould with a planted dent, compared with --deviations, then reported.
// Oracles: the deviation cloud of the same run, parsed from its documented
// layout (tests/support/deviation_cloud.hpp), for the histogram (recounted
// here over every evaluated point with the written edges) and the display
// sample (each one a point of the cloud, same place, same deviation);
// python3-jsonschema for report.json; a second run for the bytes; headless
// Chromium for the page (images load, the 3D view draws the sample).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "report_checks.hpp"
#include "support/deviation_cloud.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;

namespace {

// Every file of a folder, path -> bytes.
std::map<std::string, std::string> folder_files(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[std::filesystem::relative(e.path(), dir).string()] = slurp(e.path().string());
  return out;
}

// One scan of the mould, compared and reported, shared by the cases.
struct ScanReportFixture {
  std::string dir, mould, comparison, cloud, report;
  json c;
  std::vector<test::DeviationPoint> points;
  int compare_status = -1, report_status = -1;
  std::string report_out;

  ScanReportFixture() {
    dir = test::scratch_dir("cli-report-scan");
    mould = test::source_path("examples/parts/mould.json");
    comparison = dir + "/comparison.json";
    cloud = dir + "/deviations.ply";
    report = dir + "/report";
    // About 4 500 points: stripes 1.5 mm apart, points 1.2 mm along them; a
    // 0.1 mm deep dent of radius 5 mm on the dome's flank; turned 170 deg.
    const auto sim = run_furrow({"simulate-measurement", mould, "--scan", "--out", dir + "/scan.ply",
                                 "--stripe-pitch", "1.5", "--point-pitch", "1.2", "--view", "0.2,0.1,-1", "--spray",
                                 "0.005", "--misalign", "5,-3,170,10,20,30", "--seed", "11", "--bump",
                                 "30,40,28.85,5,-0.1"});
    INFO(sim.out << sim.err);
    REQUIRE(sim.status == 0);
    const auto cmp = run_furrow({"compare", mould, "--scan", dir + "/scan.ply", "--out", comparison,
                                 "--deviations", cloud});
    INFO(cmp.out << cmp.err);
    compare_status = cmp.status;
    c = json::parse(slurp(comparison));
    points = test::parse_deviation_ply(slurp(cloud));
    const auto rep = run_furrow({"report", comparison, "--out", report, "--title", "scan"});
    report_status = rep.status;
    report_out = rep.out + rep.err;
  }
};

const ScanReportFixture& fixture() {
  static const ScanReportFixture f;
  return f;
}

}  // namespace

TEST_CASE("report of a scan: the histogram counts every evaluated point of the deviation cloud") {
  const ScanReportFixture& f = fixture();
  REQUIRE(f.compare_status == 1);  // the dent leaves points outside the zone
  const std::vector<double> edges = f.c["histogram"]["edges"].get<std::vector<double>>();
  const std::vector<std::size_t> counts = f.c["histogram"]["counts"].get<std::vector<std::size_t>>();
  REQUIRE(edges.size() == counts.size() + 1);
  // Recounted from the cloud: bin k holds edges[k] <= d < edges[k+1], the last closed.
  std::vector<std::size_t> recount(counts.size(), 0);
  std::size_t evaluated = 0, outside = 0;
  const double lower = f.c["tolerance"]["outside"].get<double>() - f.c["tolerance"]["width"].get<double>();
  const double upper = f.c["tolerance"]["outside"].get<double>();
  for (const test::DeviationPoint& p : f.points) {
    if (p.outlier != 0) continue;
    ++evaluated;
    const double d = p.deviation;
    outside += d < lower || d > upper;
    std::size_t k = 0;
    while (k + 1 < counts.size() && d >= edges[k + 1]) ++k;
    REQUIRE(d >= edges[k]);
    REQUIRE(d <= edges.back());
    ++recount[k];
  }
  CHECK(recount == counts);
  CHECK(evaluated == f.c["summary"]["evaluated"].get<std::size_t>());
  CHECK(evaluated > 3000);
  CHECK(outside > 0);
  CHECK(outside == f.c["summary"]["out_of_tolerance"].get<std::size_t>());
}

TEST_CASE("report of a scan: every display point is a point of the deviation cloud with its deviation") {
  const ScanReportFixture& f = fixture();
  const json& display = f.c["display"];
  const json& rows = display["points"];
  CHECK(display["cap"].get<std::size_t>() == 50000);
  // Fewer evaluated points than the cap: all of them are shown, in the cloud's order.
  CHECK(display["voxel"].get<double>() == 0);
  REQUIRE(rows.size() == f.c["summary"]["evaluated"].get<std::size_t>());
  long previous = -1;
  for (const json& row : rows) {
    const long index = row[0].get<long>();
    REQUIRE(index > previous);
    previous = index;
    REQUIRE(static_cast<std::size_t>(index) < f.points.size());
    const test::DeviationPoint& p = f.points[static_cast<std::size_t>(index)];
    CHECK(p.outlier == 0);
    // Coordinates are written rounded to 0.1 um; the deviation as the cloud's float.
    for (int k = 0; k < 3; ++k) CHECK(std::abs(row[1 + k].get<double>() - p.xyz[k]) <= 0.5e-4 + 1e-9);
    CHECK(static_cast<float>(row[4].get<double>()) == p.deviation);
  }
}

TEST_CASE("report of a scan: the folder, report.json against the schema and the comparison, the same bytes twice") {
  const ScanReportFixture& f = fixture();
  INFO(f.report_out);
  REQUIRE(f.report_status == 1);  // FAIL, as the comparison
  const json r = json::parse(slurp(f.report + "/report.json"));
  const auto valid = test::validate_with_jsonschema(test::source_path("docs/report.schema.json"),
                                                    f.report + "/report.json", f.dir);
  INFO(valid.out);
  CHECK(valid.status == 0);
  CHECK(r["verdict"]["result"] == "FAIL");
  CHECK(r["verdict"]["evaluated"] == f.c["summary"]["evaluated"]);
  CHECK(r["verdict"]["out_of_tolerance"] == f.c["summary"]["out_of_tolerance"]);
  CHECK(r["deviations"]["profile"] == f.c["summary"]["profile"]);
  const json& s = r["scan"];
  CHECK(s["histogram"] == f.c["histogram"]);
  CHECK(s["points"]["read"] == f.c["points"]["read"]);
  CHECK(s["points"]["evaluated"] == f.c["points"]["kept"]);
  CHECK(s["points"]["removed"] == f.c["points"]["removed"]);
  CHECK(s["display"]["points"] == f.c["display"]["points"].size());
  CHECK(s["registration"]["transform"] == f.c["registration"]["transform"]);
  // The angle of the simulated turn, x_scanner = Rz Ry Rx x_part (5, -3, 170 deg).
  const double deg = 3.14159265358979323846 / 180;
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(170 * deg, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(-3 * deg, Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(5 * deg, Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  CHECK(std::abs(s["registration"]["rotation_deg"].get<double>() - Eigen::AngleAxisd(turn).angle() / deg) < 0.01);
  CHECK(r["options"]["comparison"]["loss"] == f.c["fit_options"]["loss"]);
  CHECK(r["points"].empty());  // a scan's points are in its deviation cloud
  CHECK_FALSE(std::filesystem::exists(f.report + "/results.qif"));

  // The page: the Scan section, and the 3D view's data holds the display sample.
  const std::string html = slurp(f.report + "/report.html");
  CHECK(html.find("<section id=\"scan\">") != std::string::npos);
  const std::string open = "<script type=\"application/json\" id=\"view3d-data\">";
  const std::size_t at = html.find(open);
  REQUIRE(at != std::string::npos);
  const json view = json::parse(html.substr(at + open.size(), html.find("</script>", at) - at - open.size()));
  CHECK(view["points"]["xyz"].size() == 3 * f.c["display"]["points"].size());

  // Twice: the same bytes, the timestamp apart.
  const auto again = run_furrow({"report", f.comparison, "--out", f.dir + "/again", "--title", "scan"});
  REQUIRE(again.status == 1);
  auto first = folder_files(f.report), second = folder_files(f.dir + "/again");
  REQUIRE(first.size() == second.size());
  const std::regex stamp("\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ");
  for (const auto& file : first) {
    // Named, not a structured binding: INFO captures in a lambda, and C++17
    // lambdas cannot capture structured bindings (clang refuses).
    const std::string& path = file.first;
    INFO(path);
    REQUIRE(second.count(path));
    CHECK(std::regex_replace(file.second, stamp, "T") == std::regex_replace(second[path], stamp, "T"));
  }
  // And the comparison itself, display sample and histogram included.
  const auto cmp = run_furrow({"compare", f.mould, "--scan", f.dir + "/scan.ply", "--out", f.dir + "/c2.json"});
  CHECK(cmp.status == 1);
  json c2 = json::parse(slurp(f.dir + "/c2.json"));
  json c1 = f.c;
  c1["sources"]["deviations"] = "";  // the second run wrote no cloud
  CHECK(c1 == c2);
}

TEST_CASE("report of a scan renders in headless Chromium: images load, the 3D view draws the sample") {
  const ScanReportFixture& f = fixture();
  if (!std::filesystem::exists(test::kChromium)) {
    FAIL_CHECK("the browser check needs /usr/bin/chromium, which is missing: run scripts/install-deps.sh");
    return;
  }
  const std::string html = slurp(f.report + "/report.html");
  std::size_t images = 0;
  for (std::size_t at = html.find("<img"); at != std::string::npos; at = html.find("<img", at + 1)) ++images;
  const std::string profile = f.dir + "/profile";
  std::filesystem::remove_all(profile);
  const std::string command = std::string("timeout 180 ") + test::kChromium +
                              " --headless=new --no-sandbox --disable-gpu --enable-unsafe-swiftshader"
                              " --use-angle=swiftshader --no-first-run --disable-background-networking"
                              " --disable-component-update --disable-sync --virtual-time-budget=4000"
                              " --window-size=1200,900 --user-data-dir=" +
                              test::shell_quote(profile) + " --dump-dom " +
                              test::shell_quote("file://" + std::filesystem::absolute(f.report + "/report.html").string());
  const auto r = test::run_shell(command, f.dir + "/dom.html");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("data-images-loaded=\"" + std::to_string(images) + "/" + std::to_string(images) + "\"") !=
        std::string::npos);
  CHECK(r.out.find("id=\"verdict-result\">FAIL<") != std::string::npos);
  std::smatch m;
  REQUIRE(std::regex_search(r.out, m, std::regex("<section id=\"view3d\"[^>]*\\bdata-view3d=\"([^\"]*)\"")));
  INFO(m[1].str());
  CHECK(m[1].str().rfind("drawn:", 0) == 0);
  REQUIRE(std::regex_search(r.out, m, std::regex("<section id=\"view3d\"[^>]*\\bdata-view3d-spheres=\"([^\"]*)\"")));
  CHECK(m[1].str() == std::to_string(f.c["display"]["points"].size()));
}

TEST_CASE("report of a scan: an older comparison without its sample, --compensation or a missing --db is exit 2, nothing written") {
  const ScanReportFixture& f = fixture();
  json old = f.c;
  old.erase("display");
  test::write_text(f.dir + "/old.json", old.dump());
  const auto r = run_furrow({"report", f.dir + "/old.json", "--out", f.dir + "/old"});
  CHECK(r.status == 2);
  CHECK(r.err.find("old.json") != std::string::npos);
  CHECK(r.err.find("compare the scan again") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(f.dir + "/old"));
  json tampered = f.c;
  tampered["histogram"]["counts"][20] = tampered["histogram"]["counts"][20].get<std::size_t>() + 1;
  test::write_text(f.dir + "/tampered.json", tampered.dump());
  const auto t = run_furrow({"report", f.dir + "/tampered.json", "--out", f.dir + "/tampered"});
  CHECK(t.status == 2);
  CHECK(t.err.find("summary.evaluated") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(f.dir + "/tampered"));
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--compensation", f.dir + "/comp.json"}, {"--db", f.dir + "/results.sqlite"}}) {
    std::vector<std::string> args = {"report", f.comparison, "--out", f.dir + "/refused"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto refused = run_furrow(args);
    INFO(refused.err);
    CHECK(refused.status == 2);
    // Named by the option, or by the database that is not there.
    CHECK(refused.err.find(extra[0] == "--db" ? extra[1] : extra[0]) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(f.dir + "/refused"));
  }
}
