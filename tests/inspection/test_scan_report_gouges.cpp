// A scan against a prediction, compared and reported as a user runs it: a
// simulated scan of the mould (0.3 mm raster, 4 um noise, turned 150 deg)
// with three planted dents 80 um deep (radius 4 mm, beyond the -50 um
// limit): one at the predicted z-map site G1 (the prediction expects it),
// two where nothing is predicted.
// Oracles: the planted dents (their centres on the surface and their
// depth, analytic); comparison.json of the same run for every number the
// report shows; python3-jsonschema for report.json; headless Chromium for
// the page.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <regex>

#include "base/json_fields.hpp"
#include "cli/report_checks.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
using namespace furrow::test;
using json = json_fields::json;

namespace {

constexpr double kDepth = 0.08;   // [mm] every dent
constexpr double kRadius = 4.0;   // [mm] of the raised-cosine dents
const Eigen::Vector2d kSite(0.35, 0.55);                                       // (u, v) of G1, face 0
const Eigen::Vector2d kLoose[2] = {Eigen::Vector2d(0.75, 0.3), Eigen::Vector2d(0.15, 0.8)};  // nothing predicted

struct Run {
  std::string dir, comparison, report;
  Part part = mould_part();
  SurfaceBump site;
  SurfaceBump loose[2];
  json c, r;
  int compare_status = -1, report_status = -1;
  std::string log;

  Run() {
    dir = scratch_dir("scan-report-gouges");
    comparison = dir + "/comparison.json";
    report = dir + "/report";
    const NurbsSurface& s = part.faces[0].surface();
    site = {s.point(kSite.x(), kSite.y()), kRadius, -kDepth};
    for (int k = 0; k < 2; ++k) loose[k] = {s.point(kLoose[k].x(), kLoose[k].y()), kRadius, -kDepth};
    // The prediction expects the dent at G1 and nothing else.
    Prediction p = field_prediction(part, [&](const Eigen::Vector2d& uv) {
      return site.offset_at(s.point(uv.x(), uv.y()));
    });
    add_zmap_site(p, part, kSite, {0.02, 0.02}, kDepth);
    write_prediction(p, dir + "/prediction.json");
    auto bump = [](const SurfaceBump& b) {
      char text[160];
      std::snprintf(text, sizeof text, "%.9g,%.9g,%.9g,%g,%g", b.centre.x(), b.centre.y(), b.centre.z(), b.radius,
                    b.height);
      return std::string(text);
    };
    const std::string mould = source_path("examples/parts/mould.json");
    const auto sim = run_furrow({"simulate-measurement", mould, "--scan", "--out", dir + "/scan.ply", "--stripe-pitch",
                                 "0.3", "--point-pitch", "0.3", "--scan-noise", "0.004", "--bump", bump(site), "--bump",
                                 bump(loose[0]), "--bump", bump(loose[1]), "--misalign", "5,-10,150,300,-120,80",
                                 "--seed", "7"});
    log += sim.out + sim.err;
    REQUIRE(sim.status == 0);
    const auto cmp = run_furrow({"compare", mould, "--scan", dir + "/scan.ply", "--prediction",
                                 dir + "/prediction.json", "--tolerance", "0.1", "--voxel", "2", "--deviations",
                                 dir + "/deviations.ply", "--out", comparison});
    log += cmp.out + cmp.err;
    compare_status = cmp.status;
    c = json::parse(slurp(comparison));
    const auto rep = run_furrow({"report", comparison, "--out", report, "--title", "scan with a prediction"});
    log += rep.out + rep.err;
    report_status = rep.status;
    r = json::parse(slurp(report + "/report.json"));
  }
};

const Run& run() {
  static const Run r;
  return r;
}

}  // namespace

TEST_CASE("unexplained overcuts of a scan: two dents nothing predicted are two clusters at the dents") {
  const Run& f = run();
  INFO(f.log);
  REQUIRE(f.compare_status == 1);  // out of tolerance at three dents, G1 confirmed
  const json& u = f.c["unexplained"];
  REQUIRE(u.size() == 2);
  CHECK(f.c["summary"]["unexplained_overcuts"] == 2);
  const double noise = f.c["verification"]["noise"].get<double>();
  for (const json& cluster : u) {
    const Eigen::Vector3d centre = json_fields::vector3(cluster["centroid"], "centroid");
    const Eigen::Vector3d deepest = json_fields::vector3(cluster["xyz"], "xyz");
    // Which planted dent: the nearer; it must be the only one near.
    const double d0 = (centre - f.loose[0].centre).norm(), d1 = (centre - f.loose[1].centre).norm();
    const SurfaceBump& dent = d0 < d1 ? f.loose[0] : f.loose[1];
    const double depth = cluster["depth"].get<double>(), u1 = cluster["uncertainty"].get<double>();
    MESSAGE(cluster["id"].get<std::string>() << ": " << cluster["points"] << " points, centre "
                                              << (centre - dent.centre).norm() << " mm from the dent's, deepest "
                                              << (deepest - dent.centre).norm() << " mm off, depth " << depth * 1e3
                                              << " um over " << cluster["read_points"] << " points (u " << u1 * 1e3
                                              << " um, noise " << noise * 1e3 << " um)");
    CHECK(std::max(d0, d1) > 20);  // the two clusters are the two dents, not one of them twice
    // The points below -50 um form a disc about 1.7 mm across around the
    // dent's centre: their mean foot lies at it, to the raster's pitch.
    CHECK((centre - dent.centre).norm() < 0.3);
    CHECK((deepest - dent.centre).norm() < 1.5);
    CHECK(cluster["points"].get<std::size_t>() > 30);
    CHECK(cluster["read_points"].get<std::size_t>() >= 5);
    // The depth to the noise level: the deepest local mean lies a few of its
    // sigmas below the floor, 2 um shallower for the local mean's spread
    // over the cosine's floor and the registration's share.
    CHECK(std::abs(depth - kDepth) < 4 * u1 + 0.002);
    CHECK(std::abs(u1 - noise / std::sqrt(cluster["read_points"].get<double>())) < 1e-12);
    const Eigen::Vector3d lo = json_fields::vector3(cluster["extent"]["min"], "min");
    const Eigen::Vector3d hi = json_fields::vector3(cluster["extent"]["max"], "max");
    CHECK(((dent.centre - lo).array() > 0).all());
    CHECK(((hi - dent.centre).array() > 0).all());
    CHECK((hi - lo).head<2>().maxCoeff() < 2 * kRadius);
  }
  CHECK(u[0]["id"] == "U1");
  CHECK(u[1]["id"] == "U2");
  CHECK(u[0]["depth"].get<double>() >= u[1]["depth"].get<double>());
  // The dent at the predicted site is as deep, out of tolerance too, and
  // explained: G1 confirmed, no cluster there.
  REQUIRE(f.c["gouge_sites"].size() == 1);
  CHECK(f.c["gouge_sites"][0]["status"] == "CONFIRMED");
  CHECK(std::abs(f.c["gouge_sites"][0]["measured_depth"].get<double>() - kDepth) <
        4 * f.c["gouge_sites"][0]["uncertainty"].get<double>() + 0.002);
  for (const json& cluster : u)
    CHECK((json_fields::vector3(cluster["centroid"], "centroid") - f.site.centre).norm() > 10);
}

TEST_CASE("report of a scan with a prediction: the comparison's sites, clusters and statistics, report.json valid") {
  const Run& f = run();
  INFO(f.log);
  REQUIRE(f.report_status == 1);
  const auto valid = validate_with_jsonschema(source_path("docs/report.schema.json"), f.report + "/report.json", f.dir);
  INFO(valid.out);
  CHECK(valid.status == 0);
  // The numbers are the comparison's, member for member.
  CHECK(f.r["prediction"] == f.c["prediction_comparison"]);
  CHECK(f.r["gouges"]["sites"] == f.c["gouge_sites"]);
  CHECK(f.r["gouges"]["unexplained"] == f.c["unexplained"]);
  CHECK(f.r["verdict"]["gouge_sites"]["confirmed"] == 1);
  CHECK(f.r["verdict"]["gouge_sites"]["predicted"] == 1);
  CHECK(f.r["verdict"]["unexplained_overcuts"] == 2);
  CHECK(f.r["verdict"]["prediction_verdict"] == f.c["prediction_comparison"]["overall"]["verdict"]);
  CHECK(f.r["options"]["comparison"]["gouges"] == f.c["verification"]["gouges"]);
  CHECK(std::filesystem::exists(f.report + "/figures/gouge_sites.png"));

  // The page: the site's row with its status and its reading, the clusters.
  const std::string html = slurp(f.report + "/report.html");
  const std::size_t gouges = html.find("<section id=\"gouges\">");
  REQUIRE(gouges != std::string::npos);
  const std::string section = html.substr(gouges, html.find("</section>", gouges) - gouges);
  const json& g1 = f.c["gouge_sites"][0];
  auto um1 = [](double mm) {
    char t[32];
    std::snprintf(t, sizeof t, "%.1f", mm * 1000);
    return std::string(t);
  };
  CHECK(std::regex_search(section, std::regex("<td>G1</td>.*CONFIRMED.*" + um1(-g1["measured_depth"].get<double>()) +
                                              ".*<td>#" + std::to_string(g1["deepest"].get<std::size_t>()) + "</td>")));
  for (const json& cluster : f.c["unexplained"])
    CHECK(std::regex_search(section, std::regex("<td>" + cluster["id"].get<std::string>() + "</td>.*UNEXPLAINED.*" +
                                                um1(-cluster["depth"].get<double>()))));
  // The 3D view marks the site and the clusters where comparison.json puts them.
  const std::string open = "<script type=\"application/json\" id=\"view3d-data\">";
  const std::size_t at = html.find(open);
  REQUIRE(at != std::string::npos);
  const json view = json::parse(html.substr(at + open.size(), html.find("</script>", at) - at - open.size()));
  REQUIRE(view["markers"].size() == 3);
  CHECK(view["markers"][0]["label"] == "G1");
  CHECK(view["markers"][0]["status"] == "CONFIRMED");
  for (int k = 0; k < 2; ++k) {
    const json& m = view["markers"][1 + k];
    CHECK(m["label"] == f.c["unexplained"][k]["id"]);
    const Eigen::Vector3d xyz = json_fields::vector3(f.c["unexplained"][k]["xyz"], "xyz");
    for (int i = 0; i < 3; ++i) CHECK(std::abs(m["at"][i].get<double>() - xyz[i]) <= 0.0005 + 1e-9);  // written to 1 um
  }
}

TEST_CASE("report of a scan with a prediction renders in headless Chromium with its markers") {
  const Run& f = run();
  if (!std::filesystem::exists(kChromium)) {
    FAIL_CHECK("the browser check needs /usr/bin/chromium, which is missing: run scripts/install-deps.sh");
    return;
  }
  const std::string html = slurp(f.report + "/report.html");
  std::size_t images = 0;
  for (std::size_t at = html.find("<img"); at != std::string::npos; at = html.find("<img", at + 1)) ++images;
  const std::string profile = f.dir + "/profile";
  std::filesystem::remove_all(profile);
  const std::string command = std::string("timeout 180 ") + kChromium +
                              " --headless=new --no-sandbox --disable-gpu --enable-unsafe-swiftshader"
                              " --use-angle=swiftshader --no-first-run --disable-background-networking"
                              " --disable-component-update --disable-sync --virtual-time-budget=4000"
                              " --window-size=1200,900 --user-data-dir=" +
                              shell_quote(profile) + " --dump-dom " +
                              shell_quote("file://" + std::filesystem::absolute(f.report + "/report.html").string());
  const auto r = run_shell(command, f.dir + "/dom.html");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("data-images-loaded=\"" + std::to_string(images) + "/" + std::to_string(images) + "\"") !=
        std::string::npos);
  std::smatch m;
  REQUIRE(std::regex_search(r.out, m, std::regex("<section id=\"view3d\"[^>]*\\bdata-view3d=\"([^\"]*)\"")));
  INFO(m[1].str());
  CHECK(m[1].str().rfind("drawn:", 0) == 0);
  REQUIRE(std::regex_search(r.out, m, std::regex("<section id=\"view3d\"[^>]*\\bdata-view3d-markers=\"([^\"]*)\"")));
  CHECK(m[1].str() == "3");
}
