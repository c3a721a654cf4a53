// Grazing points and incidence weights of a scan (io/scan/scan_preprocess.hpp
// step 5, docs/scan.md "Line of sight" and "Weights") on a simulated scan of
// the mould seen obliquely, whose noise grows with incidence as the
// documented model says (ScannerModel::noise_grows_with_incidence: normal
// sigma = sigma0 / cos(incidence)). Oracles, both from the simulation
// alone: its nominal normals and view direction (a brute-force count of the
// points beyond the limit), and the placement it planted the part at in the
// scanner's frame.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "base/numbers.hpp"
#include "geometry/closest_point.hpp"
#include "inspection/scan_comparison.hpp"
#include "inspection/scan_simulation.hpp"
#include "verification_fixture.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr double kLimit = 75;  // [deg] the comparison's largest incidence (the default)

struct Fixture {
  Part part = mould_part();
  ScannerModel model;
  SimulatedScan scan;
  Eigen::Vector3d view;       // the view direction in the scanner's frame
  Eigen::Isometry3d truth;    // scanner frame -> part frame, as planted
  CompareOptions options = compare_options(0.1);

  Fixture(std::uint32_t seed, double pitch) {
    // Looking 62 degrees off the mould's axis, so that its slopes are seen
    // from some 25 degrees to beyond 80.
    model.view = Eigen::Vector3d(0, std::sin(radians(62)), -std::cos(radians(62)));
    model.stripe_pitch = model.point_pitch = pitch;
    model.max_incidence_deg = 86;  // the scanner itself keeps points up to 86 degrees
    model.noise_sigma = 0.004;
    model.noise_grows_with_incidence = true;
    model.part_to_scanner.rotation_deg = {10, -20, 140};
    model.part_to_scanner.translation = {250, 90, -60};
    model.seed = seed;
    scan = simulate_scan(part, model);
    const Eigen::Isometry3d to_scanner = model.part_to_scanner.part_to_cmm();
    view = to_scanner.linear() * model.view;
    truth = to_scanner.inverse();
  }

  ScanCloud cloud(bool with_normals) const {
    ScanCloud c;
    c.file = "oblique.ply";
    c.format = "ply binary_little_endian";
    c.coordinate_type = "float64";
    c.points = scan.points;
    if (with_normals)
      for (const Eigen::Vector3d& n : scan.normals) c.normals.push_back(n.cast<float>());
    c.read = c.points.size();
    return c;
  }

  // The brute-force oracle: the simulation's nominal normal against its
  // view, per point.
  std::vector<bool> grazing_truth(double& closest_to_limit) const {
    std::vector<bool> out;
    closest_to_limit = 90;
    for (const Eigen::Vector3d& n : scan.normals) {
      const double angle = degrees(std::acos(std::min(1.0, std::abs(n.dot(view)))));
      closest_to_limit = std::min(closest_to_limit, std::abs(angle - kLimit));
      out.push_back(angle > kLimit);
    }
    return out;
  }

  // The RMS, over the scan's points, of the distance between where a
  // transform and the planted one put them [mm].
  double placement_error(const Eigen::Isometry3d& t) const {
    double sum = 0;
    for (const Eigen::Vector3d& p : scan.points) sum += (t * p - truth * p).squaredNorm();
    return std::sqrt(sum / static_cast<double>(scan.points.size()));
  }
};

}  // namespace

TEST_CASE("scan incidence: the grazing points are exactly those the simulation's normals and view put beyond the limit") {
  const Fixture f(3, 0.4);
  REQUIRE(f.scan.points.size() > 20000);
  double margin = 0;
  const std::vector<bool> truth = f.grazing_truth(margin);
  // The file's normals are floats: no point so near the limit that their
  // rounding (about 1e-7 rad, 6e-6 degrees) could move it across.
  REQUIRE(margin > 2e-5);
  std::size_t expected = 0;
  for (const bool g : truth) expected += g;
  // Enough on both sides for the count to mean something.
  REQUIRE(expected > 500);  // of some 25 000
  REQUIRE(expected < f.scan.points.size() / 2);

  ScanPreprocessOptions po;
  po.start = ScanStart::global;  // the start is not what is tested here
  po.view_direction = -3.0 * f.view;  // any length, either sense: the incidence is sign-free
  po.incidence_weights = true;
  const ScanPreprocessed pre = preprocess_scan(f.cloud(true), po);
  CHECK(pre.view == ScanViewKind::direction);
  CHECK(pre.view_source == "option");
  CHECK(pre.grazing_count == expected);
  std::size_t disagree = 0, spray_and_grazing = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    disagree += pre.grazing[i] != truth[i];
    spray_and_grazing += pre.grazing[i] && pre.spray[i];
  }
  CHECK(disagree == 0);
  CHECK(spray_and_grazing == 0);  // a grazing point is grazing, whatever else
  CHECK(pre.no_normal == 0);
  // No fit point is grazing, and each weighs cos(incidence) of its own normal.
  REQUIRE(pre.fit_weights.size() == pre.fit.size());
  for (std::size_t k = 0; k < pre.fit.size(); ++k) {
    const std::size_t i = pre.fit[k];
    CHECK_FALSE(truth[i]);
    const double expected_weight = std::abs(f.scan.normals[i].dot(f.view));
    CHECK(std::abs(pre.fit_weights[k] - expected_weight) < 1e-6);
  }

  // The comparison: grazing points are their own status, not evaluated.
  const ClosestPointFinder finder(f.part);
  const ScanComparison c = compare_scan(finder, f.cloud(true), pre, po, nullptr, f.options);
  std::size_t status_grazing = 0;
  for (std::size_t i = 0; i < c.status.size(); ++i) {
    status_grazing += c.status[i] == ScanPointStatus::grazing;
    if (truth[i]) CHECK(c.status[i] == ScanPointStatus::grazing);
  }
  CHECK(status_grazing == expected);
  CHECK(c.grazing == expected);
  CHECK(c.evaluated + c.grazing + c.off_part + pre.spray_count == c.points);

  // Without the file's normals (estimated by PCL from 16 neighbours) the
  // rule sees the same surface through noisy estimates: measured 0.9 % of
  // the points on the other side of the limit (all near it); bound 2 %.
  const ScanPreprocessed estimated = preprocess_scan(f.cloud(false), po);
  CHECK(estimated.normals_estimated);
  std::size_t flipped = 0;
  double worst_flip = 0;
  for (std::size_t i = 0; i < truth.size(); ++i)
    if (estimated.grazing[i] != truth[i]) {
      ++flipped;
      const double angle = degrees(std::acos(std::min(1.0, std::abs(f.scan.normals[i].dot(f.view)))));
      worst_flip = std::max(worst_flip, std::abs(angle - kLimit));
    }
  MESSAGE("estimated normals: " << flipped << " of " << truth.size() << " points on the other side, the farthest "
                                << worst_flip << " deg from the limit; grazing " << estimated.grazing_count
                                << " vs " << expected);
  CHECK(flipped < truth.size() / 50);

  // Without a view nothing is rejected or weighted.
  const ScanPreprocessed blind = preprocess_scan(f.cloud(true), ScanPreprocessOptions{});
  CHECK(blind.view == ScanViewKind::none);
  CHECK(blind.grazing.empty());
  CHECK(blind.grazing_count == 0);
  CHECK(blind.fit_weights.empty());
}

TEST_CASE("scan incidence: the fit weighted by cos(incidence) and the unweighted one both land on the planted placement") {
  // Measured while building this (four seeds, 0.8 mm raster, RMS over the
  // scan of the distance to the planted placement): weighted 1.10, 1.53,
  // 2.35, 2.25 um, unweighted 1.73, 1.21, 2.17, 1.85 um - the weights did
  // not bring the fit nearer on this scan, and it needed 50-52 outer
  // iterations (the default cap is 50), hence incidence_weights off by
  // default (docs/scan.md "Weights"). What holds, and is checked: both fits
  // converge (the weighted one given 400 outer iterations) within 4 um RMS
  // of the planted placement, a third of the noise at normal incidence.
  Fixture f(5, 1.0);
  f.options.registration.max_outer_iterations = 400;
  const ClosestPointFinder finder(f.part);
  const ScanCloud cloud = f.cloud(true);
  ScanPreprocessOptions weighted;
  weighted.view_direction = f.view;
  weighted.incidence_weights = true;
  weighted.start = ScanStart::global;  // both fits from the same start
  ScanPreprocessOptions unweighted = weighted;
  unweighted.incidence_weights = false;
  const ScanComparison a = compare_scan(finder, cloud, preprocess_scan(cloud, weighted), weighted, nullptr, f.options);
  const ScanComparison b = compare_scan(finder, cloud, preprocess_scan(cloud, unweighted), unweighted, nullptr, f.options);
  INFO("weighted: " << a.registration.status << " after " << a.registration.outer_iterations
                    << " outer iterations; unweighted: " << b.registration.status << " after "
                    << b.registration.outer_iterations);
  REQUIRE(a.summary.alignment == "ok");
  REQUIRE(b.summary.alignment == "ok");
  CHECK(a.pre.fit == b.pre.fit);  // the weights change nothing else
  CHECK_FALSE(a.pre.fit_weights.empty());
  CHECK(b.pre.fit_weights.empty());
  const double ea = f.placement_error(a.transform), eb = f.placement_error(b.transform);
  MESSAGE(cloud.points.size() << " points, " << a.pre.fit.size() << " in the fit; placement error (RMS over the "
                              << "scan) weighted " << ea * 1000 << " um in " << a.registration.outer_iterations
                              << " outer iterations, unweighted " << eb * 1000 << " um in "
                              << b.registration.outer_iterations);
  CHECK(ea < 0.004);
  CHECK(eb < 0.004);
}
