// The coarse alignment's point choice on files as CMMs and scanners write
// them: scan (raster) order, and blunders at any distance.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "geometry/closest_point.hpp"
#include "inspection/coarse_alignment.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/point_subsets.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

// Share of the full set's extent that the subset's extent covers, worst axis.
double coverage(const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& subset) {
  Eigen::AlignedBox3d all, some;
  for (const auto& p : points) all.extend(p);
  for (std::size_t i : subset) some.extend(points[i]);
  double worst = 1;
  for (int a = 0; a < 3; ++a)
    if (all.sizes()[a] > 1e-9) worst = std::min(worst, some.sizes()[a] / all.sizes()[a]);
  return worst;
}

// Smallest singular value ratio of the centred subset: 0 for points on a line.
double flatness(const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& subset) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t i : subset) c += points[i];
  c /= static_cast<double>(subset.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i : subset) cov += (points[i] - c) * (points[i] - c).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  return std::sqrt(es.eigenvalues()(1) / es.eigenvalues()(2));
}

}  // namespace

TEST_CASE("spread subset: raster-order points give a subset spread over the part, not one scan column") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const InspectionPlan plan = grid_plan(part, 400, 125, {"ball", 2});  // 50 000 points, line by line
  std::vector<Eigen::Vector3d> pts;
  for (const PlannedPoint& p : plan.points) pts.push_back(p.xyz);
  std::vector<std::size_t> every(pts.size());
  for (std::size_t k = 0; k < every.size(); ++k) every[k] = k;
  for (std::size_t max : {std::size_t(200), std::size_t(1000)}) {
    CAPTURE(max);
    const std::vector<std::size_t> s = spread_subset(pts, every, max);
    CHECK(s.size() <= max);
    CHECK(s.size() >= max / 2);
    CHECK(std::is_sorted(s.begin(), s.end()));
    CHECK(coverage(pts, s) > 0.9);
    CHECK(flatness(pts, s) > 0.2);  // a patch, not a line
    CHECK(spread_subset(pts, every, max) == s);  // deterministic
  }
  // Every n-th point, the old choice, is the degenerate one here.
  std::vector<std::size_t> strided;
  for (std::size_t k = 0; k < pts.size(); k += 250) strided.push_back(k);
  CHECK(flatness(pts, strided) < 0.05);
}

TEST_CASE("points near the bulk: blunders at any finite distance are left out, NaN too") {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) pts.push_back({double(i), double(j), 0.1 * i * j});
  const std::size_t good = pts.size();
  pts.push_back({1e4, 0, 0});
  pts.push_back({0, 1e39, 0});
  pts.push_back({-std::numeric_limits<double>::max(), 0, 0});
  pts.push_back({std::nan(""), 0, 0});
  const std::vector<std::size_t> kept = points_near_the_bulk(pts, 30);
  REQUIRE(kept.size() == good);
  for (std::size_t k = 0; k < good; ++k) CHECK(kept[k] == k);
}

TEST_CASE("coarse search: raster-order points with far blunders, part turned 180 degrees") {
  const Part part = read_part(test::source_path("examples/parts/mould.json"));
  const ClosestPointFinder finder(part);
  const InspectionPlan plan = grid_plan(part, 400, 125, {"ball", 2});
  SimulationOptions sim;
  sim.misalignment = {{2, -1.5, 183}, {150, -60, 20}};
  sim.noise_sigma = 0.002;
  sim.seed = 5;  // ids are written, but the global search does not use them; the order stays raster
  SimulatedMeasurement m = simulate_measurement(plan, sim);
  for (const Eigen::Vector3d& far : {Eigen::Vector3d(1e4, 0, 0), Eigen::Vector3d(0, 0, 1e39),
                                     Eigen::Vector3d(-1e300, 5, 5)}) {
    MeasuredPoint p;
    p.id = "far" + std::to_string(m.set.points.size());
    p.xyz = far;
    m.set.points.push_back(p);
  }
  const CoarseResult coarse = coarse_global_search(finder, m.set, CoarseOptions{});
  const Eigen::Isometry3d e = coarse.transform * sim.misalignment.part_to_cmm();  // identity when exact
  CHECK(Eigen::AngleAxisd(e.linear()).angle() < 0.5 * M_PI / 180);
  CHECK(coarse.median_distance < 0.05);
}
