// A scan against a prediction (inspection/scan_verification.hpp): a
// simulated scan of the mould (scan_simulation.hpp) with a 30 um dent cut at
// a predicted z-map gouge site, the same scan without it, and the scan
// cropped around the site. The oracle is the simulation's own record: every
// point's true deviation (the dent along the normal plus the normal share
// of the noise), averaged by brute force over the same neighbourhood the
// confirmation reads.
#include <doctest/doctest.h>

#include <cmath>

#include "base/json_fields.hpp"
#include "inspection/scan_simulation.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "stage/scan_compare_stage.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

const Eigen::Vector2d kSite(0.35, 0.55);  // (u, v) of the predicted gouge
constexpr double kDepth = 0.03;           // [mm]
constexpr double kRadius = 6.0;           // [mm] of the raised-cosine dent
constexpr double kNoise = 0.004;          // [mm] along the line of sight

struct Fixture {
  Part part = mould_part();
  SurfaceBump bump;
  Prediction prediction;
  SimulatedScan scan;  // without the dent
  ScannerModel model;
  CompareOptions options = compare_options(0.1);  // zone +-50 um: the dent lies inside it

  Fixture() {
    bump = {part.faces[0].surface().point(kSite.x(), kSite.y()), kRadius, -kDepth};
    // The prediction expects exactly the dent, and names its site.
    prediction = field_prediction(part, [&](const Eigen::Vector2d& uv) {
      return bump.offset_at(part.faces[0].surface().point(uv.x(), uv.y()));
    });
    add_zmap_site(prediction, part, kSite, {0.02, 0.02}, kDepth);
    model.stripe_pitch = model.point_pitch = 0.25;
    model.noise_sigma = kNoise;
    model.part_to_scanner.rotation_deg = {5, -10, 150};
    model.part_to_scanner.translation = {300, -120, 80};
    model.seed = 11;
    scan = simulate_scan(part, model);
  }

  // The scan's points with the dent cut (along the normal, as the
  // simulation plants bumps) or not, less those within `crop` mm of the
  // dent's centre; `truth` gets each kept point's true deviation.
  ScanCloud cloud(bool dented, double crop, std::vector<double>& truth, std::vector<Eigen::Vector3d>& nominal) const {
    ScanCloud c;
    c.file = "simulated.ply";
    c.format = "ply binary_little_endian";
    c.coordinate_type = "float64";
    truth.clear();
    nominal.clear();
    for (std::size_t k = 0; k < scan.points.size(); ++k) {
      if ((scan.nominal[k] - bump.centre).norm() < crop) continue;
      const double h = dented ? bump.offset_at(scan.nominal[k]) : 0.0;
      c.points.push_back(scan.points[k] + h * scan.normals[k]);
      truth.push_back(scan.true_deviation[k] + h);
      nominal.push_back(scan.nominal[k]);
    }
    c.read = c.points.size();
    return c;
  }

  ScanComparison compare(const ScanCloud& c) const {
    ScanPreprocessOptions po;
    po.voxel = 2;  // 2,000 fit points: a quarter of the default's registration time
    return compare_scan_stage(part, c, nullptr, &prediction, options, po);
  }
};

const ScanGougeSite& only_site(const ScanComparison& c) {
  REQUIRE(c.verification.has_value());
  REQUIRE(c.verification->sites.size() == 1);
  return c.verification->sites[0];
}

}  // namespace

TEST_CASE("scan gouge confirmation: the predicted dent cut, not cut, and not seen") {
  static const Fixture f;  // simulated once for the three subcases
  REQUIRE(f.scan.points.size() > 100000);
  std::vector<double> truth;
  std::vector<Eigen::Vector3d> nominal;

  SUBCASE("cut: CONFIRMED, its depth read to the noise level, the part fails") {
    const ScanCloud cloud = f.cloud(true, 0, truth, nominal);
    const ScanComparison c = f.compare(cloud);
    const ScanGougeSite& g = only_site(c);
    const GougeSiteCheck& s = g.check;
    CHECK(s.status == GougeSiteStatus::confirmed);
    CHECK(g.anchors_seen == 1);
    REQUIRE(s.measured_depth.has_value());
    // The oracle: the true deviations of the evaluated points within the
    // read radius of the deepest point, by brute force over the cloud.
    const std::size_t j = *s.deepest;
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < cloud.points.size(); ++k)
      if (c.status[k] == ScanPointStatus::evaluated && c.foot_face[k] == s.face_index &&
          s.search_box.contains(c.foot_uv[k]) &&
          (c.transform * cloud.points[k] - c.transform * cloud.points[j]).norm() <= kScanReadRadius) {
        sum += truth[k];
        ++count;
      }
    CHECK(count == g.read_points);
    const double true_mean = sum / static_cast<double>(count);
    MESSAGE("read depth " << *s.measured_depth * 1e3 << " um over " << g.read_points << " points (u "
                          << *s.uncertainty * 1e3 << " um, noise " << c.verification->noise * 1e3
                          << " um); true mean there " << -true_mean * 1e3 << " um; deepest spot "
                          << (nominal[j] - f.bump.centre).norm() << " mm from the dent's centre");
    // What the scan reads there is what is there, but for the registration,
    // which absorbs a little of the dent (the robust loss is quadratic to
    // half the tolerance): measured 0.51 um.
    CHECK(std::abs(*s.measured_depth + true_mean) < 0.001);
    // And the dent's depth to the noise level: the deepest of the local
    // means lies a few of their sigmas below the floor.
    CHECK(std::abs(*s.measured_depth - kDepth) < 4 * *s.uncertainty + 0.0005);
    CHECK(*s.uncertainty < kNoise);
    CHECK((nominal[j] - f.bump.centre).norm() < 2.0);
    CHECK(*s.threshold == doctest::Approx(0.025).epsilon(1e-12));  // half the lower limit beats 3 sigma
    // At the predicted deepest point the prediction (the dent itself, to
    // the cells' resolution) agrees with what the scan reads.
    REQUIRE(s.predicted_error.has_value());
    // (the cells' bilinear means over 1 mm smooth the dent's floor by 1 um)
    CHECK(std::abs(*s.predicted_error + kDepth) < 0.002);
    REQUIRE(s.depth_consistent.has_value());
    CHECK(*s.depth_consistent);
    // In tolerance everywhere, failed by the confirmed gouge alone.
    CHECK(c.summary.out_of_tolerance == 0);
    CHECK(c.summary.confirmed_gouges == 1);
    CHECK(c.summary.verdict == Verdict::fail);
    // The prediction is the part as cut: explained.
    CHECK(c.verification->compared.overall.explained());
    CHECK(c.verification->compared.overall.count == c.evaluated);
  }
  SUBCASE("not cut: NOT CONFIRMED, and the part passes") {
    const ScanCloud cloud = f.cloud(false, 0, truth, nominal);
    const ScanComparison c = f.compare(cloud);
    const GougeSiteCheck& s = only_site(c).check;
    CHECK(s.status == GougeSiteStatus::not_confirmed);
    REQUIRE(s.measured_depth.has_value());
    CHECK(std::abs(*s.measured_depth) < 4 * *s.uncertainty);  // nominal, to the noise
    REQUIRE(s.depth_consistent.has_value());
    CHECK_FALSE(*s.depth_consistent);  // 30 um predicted where the part is nominal
    CHECK(c.summary.verdict == Verdict::pass);
  }
  SUBCASE("cropped around the site: NOT MEASURED, never a pass") {
    // 3 mm around the centre hidden: the site's box (2 mm each way, 1 mm
    // margin) still holds points, but not where the gouge was predicted.
    const ScanCloud cloud = f.cloud(false, 3.0, truth, nominal);
    const ScanComparison c = f.compare(cloud);
    const ScanGougeSite& g = only_site(c);
    CHECK(g.check.points.size() > 20);
    CHECK(g.anchors_seen == 0);
    CHECK(g.check.status == GougeSiteStatus::not_measured);
    CHECK(c.summary.verdict == Verdict::inconclusive);
    REQUIRE(c.summary.inconclusive.size() == 1);
    INFO(c.summary.inconclusive[0].text);
    CHECK(c.summary.inconclusive[0].kind == "gouge_not_measured");
    CHECK(c.summary.inconclusive[0].subject == "G1");
  }
}

TEST_CASE("compare --scan --prediction: a confirmed gouge exits 1 and is written with its reading") {
  // As a user runs it: the scan simulated by the command (a 30 um dent of
  // radius 6 mm planted at the predicted site with --bump), the prediction
  // as prediction.json.
  const std::string dir = scratch_dir("cli-scan-prediction");
  const Fixture f;
  write_prediction(f.prediction, dir + "/prediction.json");
  const Eigen::Vector3d& at = f.bump.centre;
  const std::string bump =
      std::to_string(at.x()) + "," + std::to_string(at.y()) + "," + std::to_string(at.z()) + ",6,-0.03";
  const std::string mould = source_path("examples/parts/mould.json");
  REQUIRE(run_furrow({"simulate-measurement", mould, "--scan", "--out", dir + "/scan.ply", "--stripe-pitch", "0.3",
                      "--point-pitch", "0.3", "--scan-noise", "0.004", "--bump", bump, "--misalign",
                      "5,-10,150,300,-120,80", "--seed", "7"})
              .status == 0);
  const auto r = run_furrow({"compare", mould, "--scan", dir + "/scan.ply", "--prediction", dir + "/prediction.json",
                             "--tolerance", "0.1", "--voxel", "2", "--out", dir + "/c.json"});
  INFO(r.out << r.err);
  CHECK(r.status == 1);
  CHECK(r.out.find("gouge sites: 1 confirmed, 0 not confirmed, 0 not measured") != std::string::npos);
  CHECK(r.out.find("0 out") != std::string::npos);  // failed by the gouge alone
  const json_fields::json c = json_fields::json::parse(slurp(dir + "/c.json"));
  CHECK(c["sources"]["prediction"] == dir + "/prediction.json");
  CHECK(c["summary"]["confirmed_gouges"] == 1);
  CHECK(c["summary"]["verdict"] == "FAIL");
  REQUIRE(c["gouge_sites"].size() == 1);
  const auto& g = c["gouge_sites"][0];
  CHECK(g["id"] == "G1");
  CHECK(g["status"] == "CONFIRMED");
  CHECK(g["anchors_seen"] == 1);
  const double depth = g["measured_depth"].get<double>(), u = g["uncertainty"].get<double>();
  MESSAGE("command line: read " << depth * 1e3 << " um over " << g["read_points"] << " points, u " << u * 1e3 << " um");
  CHECK(std::abs(depth - kDepth) < 4 * u + 0.001);
  CHECK(g["depth_consistent"] == true);
  CHECK(c["prediction_comparison"]["overall"]["verdict"] == "explained");
}
