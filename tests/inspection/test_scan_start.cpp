// The coarse start of a scan's registration (inspection/scan_registration.hpp,
// io/scan/scan_feature_start.hpp): PCL's FPFH + SampleConsensusPrerejective
// against the global search. The oracle is the planted misalignment of a
// simulated scan (scan_simulation.hpp): the part placed in the scanner's
// frame by a known rigid motion, which the registration must undo.
#include <doctest/doctest.h>

#include <cmath>

#include "base/json_fields.hpp"
#include "inspection/scan_comparison_file.hpp"
#include "inspection/scan_simulation.hpp"
#include "inspection/surface_sampling.hpp"
#include "stage/scan_compare_stage.hpp"
#include "support/weak_shapes.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

struct Planted {
  Part part;
  ScannerModel model;
  ScanCloud cloud;
  Eigen::Isometry3d scanner_to_part = Eigen::Isometry3d::Identity();
};

// A simulated scan of `part` turned and moved into the scanner's frame, as
// a file without normals would give it (so they are estimated).
Planted planted_scan(Part part, double pitch, const Eigen::Vector3d& rotation_deg, const Eigen::Vector3d& move) {
  Planted p;
  p.part = std::move(part);
  p.model.stripe_pitch = p.model.point_pitch = pitch;
  p.model.noise_sigma = 0.004;
  p.model.part_to_scanner.rotation_deg = rotation_deg;
  p.model.part_to_scanner.translation = move;
  p.model.seed = 7;
  const SimulatedScan scan = simulate_scan(p.part, p.model);
  p.cloud.file = "simulated.ply";
  p.cloud.format = "ply binary_little_endian";
  p.cloud.coordinate_type = "float64";
  p.cloud.points = scan.points;
  p.cloud.read = scan.points.size();
  p.scanner_to_part = p.model.part_to_scanner.part_to_cmm().inverse();
  return p;
}

// The mould turned 150 degrees in the scanner's frame and moved, 0.5 mm
// raster (about 30 000 points), compared once for all the cases below.
struct MouldCase {
  Planted planted = planted_scan(mould_part(), 0.5, {5, -10, 150}, {300, -120, 80});
  ScanPreprocessOptions pre_options;
  ScanComparison best;
  MouldCase() {
    pre_options.voxel = 2;  // about 2 000 fit points
    pre_options.start = ScanStart::best;
    best = compare_scan_stage(planted.part, planted.cloud, nullptr, nullptr, compare_options(0.1), pre_options);
  }
};

const MouldCase& mould_case() {
  static const MouldCase c;
  return c;
}

// Rotation [rad] between two transforms, and the largest displacement
// between them over the points given [mm].
double rotation_between(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}
double largest_displacement(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                            const std::vector<Eigen::Vector3d>& points) {
  double worst = 0;
  for (const Eigen::Vector3d& p : points) worst = std::max(worst, (a * p - b * p).norm());
  return worst;
}

}  // namespace

TEST_CASE("scan start: the feature start alone places a mould scan turned 150 degrees within the fit's basin") {
  const MouldCase& m = mould_case();
  const ScanStartRecord& s = m.best.start;
  REQUIRE(s.feature.found);
  // The feature start maps the local frame (the scanner's less the
  // cloud's centroid) to the part; the truth is the planted motion.
  const Eigen::Isometry3d truth = m.planted.scanner_to_part * Eigen::Translation3d(m.best.pre.origin);
  std::vector<Eigen::Vector3d> fit_points;
  for (const std::size_t i : m.best.pre.fit) fit_points.push_back(m.planted.cloud.points[i] - m.best.pre.origin);
  const double rotation = rotation_between(s.feature.transform, truth);
  const double moved = largest_displacement(s.feature.transform, truth, fit_points);
  MESSAGE("feature start: rotation error " << rotation << " rad, largest displacement " << moved << " mm, spacing "
                                        << s.feature.used.spacing << " mm, inlier share " << s.feature.inlier_share);
  // Within a few of its own spacings (2.1 mm here): what a placement of
  // thinned points by their features resolves ...
  CHECK(rotation < 0.05);
  CHECK(moved < 3 * s.feature.used.spacing);
  // ... and inside the basin of the fit: started there, the fit reaches the
  // minimum the global search's start reaches (the same cost over the same
  // points, to the tie's 1e-6).
  REQUIRE(s.global.ok);
  REQUIRE(s.features.ok);
  CHECK(std::abs(s.features.cost - s.global.cost) <= 1e-6 * s.global.cost);
}

TEST_CASE("scan start: the kept registration recovers the planted transform to the noise level and names its start") {
  const MouldCase& m = mould_case();
  const ScanStartRecord& s = m.best.start;
  CHECK(m.best.summary.alignment == "ok");
  std::vector<Eigen::Vector3d> fit_points;
  for (const std::size_t i : m.best.pre.fit) fit_points.push_back(m.planted.cloud.points[i]);
  const double rotation = rotation_between(m.best.transform, m.planted.scanner_to_part);
  const double moved = largest_displacement(m.best.transform, m.planted.scanner_to_part, fit_points);
  MESSAGE("registration: rotation error " << rotation << " rad, largest displacement " << moved << " mm, kept "
                                         << s.chosen << ", costs " << s.global.cost << " / " << s.features.cost);
  // 4 um noise along the line of sight over 2 000 fit points: the placement
  // is known far better than one point; no fit point is moved by as much
  // as the noise.
  CHECK(moved < 0.004);
  CHECK(rotation < 1e-4);
  // The winner follows the stated rule from the recorded figures: a
  // converged fit with the lower cost, a tie (1e-6) to the global search.
  const bool features_win = s.features.ok && s.features.cost < s.global.cost &&
                            std::abs(s.features.cost - s.global.cost) > 1e-6 * s.global.cost;
  CHECK(s.chosen == (features_win ? "features" : "global"));
  CHECK(m.best.registration.coarse.method == (features_win ? CoarseMethod::features : CoarseMethod::global_search));
  // ... and comparison.json says it.
  const nlohmann::json doc = nlohmann::json::parse(scan_comparison_json(m.best, ScanComparisonSources{}));
  const nlohmann::json& start = doc.at("registration").at("start");
  CHECK(start.at("mode") == "best");
  CHECK(start.at("chosen") == s.chosen);
  CHECK(start.at("global").at("cost").get<double>() == s.global.cost);
  CHECK(start.at("features").at("cost").get<double>() == s.features.cost);
  CHECK(start.at("feature_start").at("found") == true);
}

TEST_CASE("scan start: two feature starts of one scan give the same transform bit for bit") {
  const MouldCase& m = mould_case();
  FeatureStartInput in;
  in.scan = "simulated.ply";
  in.scan_normals_estimated = true;
  in.voxel = m.pre_options.voxel;
  for (std::size_t k = 0; k < m.best.pre.fit.size(); ++k) {
    in.scan_points.push_back(m.planted.cloud.points[m.best.pre.fit[k]] - m.best.pre.origin);
    in.scan_normals.push_back(m.best.pre.fit_normals[k]);
  }
  Eigen::AlignedBox3d box;
  for (const SurfaceSample& s : sample_part_surface(m.planted.part, 20000)) {
    in.part_points.push_back(s.point);
    in.part_normals.push_back(s.normal);
    box.extend(s.point);
  }
  in.part_size = box.diagonal().norm();
  FeatureStartOptions options;
  options.iterations = 10000;  // a fifth of the default: the draws repeat or not whatever their number
  const FeatureStart a = feature_start(in, options);
  const FeatureStart b = feature_start(in, options);
  REQUIRE(a.found);
  REQUIRE(b.found);
  CHECK(a.transform.matrix() == b.transform.matrix());
  CHECK(a.inlier_share == b.inlier_share);
}

TEST_CASE("scan start: a plane the features cannot place keeps the global search's answer and says so") {
  // A flat 100 x 60 mm plate: every point's FPFH is a plane's.
  const Part plate = one_face("plane", make_plane({-50, -30, 0}, {100, 0, 0}, {0, 60, 0}));
  const Planted p = planted_scan(plate, 1.0, {0, 0, 150}, {40, 25, -10});
  ScanPreprocessOptions po;
  po.voxel = 2;
  po.start = ScanStart::features;
  const CompareOptions options = compare_options(0.1);
  const ScanComparison features = compare_scan_stage(plate, p.cloud, nullptr, nullptr, options, po);
  po.start = ScanStart::global;
  const ScanComparison global = compare_scan_stage(plate, p.cloud, nullptr, nullptr, options, po);
  const ScanStartRecord& s = features.start;
  INFO(s.feature.status);
  CHECK_FALSE(s.feature.found);
  CHECK(s.feature.status.find("plane-like") != std::string::npos);
  CHECK(s.chosen == "global");
  CHECK(s.why.find("feature start found no placement") != std::string::npos);
  CHECK_FALSE(s.features.ran);
  CHECK(s.global.ran);
  // The global search's answer, bit for bit.
  CHECK(features.transform.matrix() == global.transform.matrix());
  const nlohmann::json doc = nlohmann::json::parse(scan_comparison_json(features, ScanComparisonSources{}));
  CHECK(doc.at("registration").at("start").at("chosen") == "global");
  CHECK(doc.at("registration").at("start").at("feature_start").at("found") == false);
}
