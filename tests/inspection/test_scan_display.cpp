// The display sample and histogram of a scan (inspection/scan_display.hpp)
// against a brute force written here from the contract: the voxels of the
// reported edge over the evaluated points (grid at their bounding box's
// lowest corner), the worst |deviation| of each (earlier point on a tie),
// and bins recounted over every evaluated point. On a hand-built comparison:
// a wavy 140 x 110 point sheet, turned and moved, with spray and off-part
// points whose large deviations must never be shown or counted.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "inspection/scan_comparison.hpp"
#include "inspection/scan_display.hpp"

using namespace furrow;

namespace {

struct Sheet {
  ScanCloud cloud;
  ScanComparison c;
};

Sheet make_sheet() {
  Sheet s;
  const int nu = 140, nv = 110;
  s.c.pre.origin = Eigen::Vector3d(1000, -2000, 500);
  s.c.registration.transform = Eigen::Translation3d(3, -4, 5) * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double x = 0.5 * i, y = 0.45 * j;
      s.cloud.points.emplace_back(x + 1000, y - 2000, 500 + 3 * std::sin(x / 9) * std::cos(y / 7));
      const std::size_t k = s.cloud.points.size() - 1;
      ScanPointStatus status = ScanPointStatus::evaluated;
      if (k % 97 == 5) status = ScanPointStatus::spray_far;
      else if (k % 89 == 7) status = ScanPointStatus::spray_near;
      else if (k % 83 == 3) status = ScanPointStatus::off_part;
      s.c.status.push_back(status);
      // A smooth field with noise-like ripple, ties on purpose (values repeat),
      // and a 60 um dent of 2 mm radius; not evaluated points carry 1 mm.
      const double r = std::hypot(x - 30, y - 25);
      double d = 0.004 * std::round(std::sin(0.37 * static_cast<double>(k)) * 4) / 4 - (r < 2 ? 0.06 : 0.0);
      if (status != ScanPointStatus::evaluated) d = (k % 2 ? 1.0 : -1.0);
      s.c.deviation.push_back(static_cast<float>(d));
    }
  s.c.tolerance = ToleranceZone::make(0.05, 0.025, "test");
  return s;
}

Eigen::Vector3d part_frame(const Sheet& s, std::size_t i) {
  return s.c.registration.transform * (s.cloud.points[i] - s.c.pre.origin);
}

}  // namespace

TEST_CASE("scan display sample: under the cap, every evaluated point is the worst of its voxel") {
  const Sheet s = make_sheet();
  const std::size_t cap = 600;
  const ScanDisplay d = scan_display(s.c, s.cloud, cap);
  REQUIRE(d.voxel > 0);
  CHECK(d.points.size() <= cap);
  CHECK(d.points.size() > cap / 3);  // the grid grew to the cap, not far beyond it

  // Brute force: voxels of edge d.voxel at the evaluated points' lowest corner.
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < s.cloud.points.size(); ++i)
    if (s.c.status[i] == ScanPointStatus::evaluated) box.extend(part_frame(s, i));
  std::map<std::tuple<long, long, long>, std::size_t> worst;
  for (std::size_t i = 0; i < s.cloud.points.size(); ++i) {
    if (s.c.status[i] != ScanPointStatus::evaluated) continue;
    const Eigen::Vector3d p = part_frame(s, i);
    const auto key = std::make_tuple(static_cast<long>(std::floor((p.x() - box.min().x()) / d.voxel)),
                                     static_cast<long>(std::floor((p.y() - box.min().y()) / d.voxel)),
                                     static_cast<long>(std::floor((p.z() - box.min().z()) / d.voxel)));
    const auto it = worst.find(key);
    if (it == worst.end() || std::fabs(s.c.deviation[i]) > std::fabs(s.c.deviation[it->second])) worst[key] = i;
  }
  std::set<std::size_t> expected;
  for (const auto& [key, i] : worst) expected.insert(i);
  CHECK(std::set<std::size_t>(d.index.begin(), d.index.end()) == expected);
  CHECK(d.index.size() == expected.size());

  for (std::size_t k = 0; k < d.index.size(); ++k) {
    const std::size_t i = d.index[k];
    if (k) CHECK(d.index[k - 1] < i);  // the cloud's order
    CHECK(s.c.status[i] == ScanPointStatus::evaluated);
    CHECK((d.points[k] - part_frame(s, i)).cwiseAbs().maxCoeff() <= 0.5e-4 + 1e-9);
    CHECK(d.deviation[k] == s.c.deviation[i]);
  }
  // The dent's floor is in the sample: the worst reading of the cloud survives.
  float deepest = 0, shown = 0;
  for (std::size_t i = 0; i < s.cloud.points.size(); ++i)
    if (s.c.status[i] == ScanPointStatus::evaluated) deepest = std::min(deepest, s.c.deviation[i]);
  for (float v : d.deviation) shown = std::min(shown, v);
  CHECK(deepest < -0.06f);
  CHECK(shown == deepest);
}

TEST_CASE("scan display sample: at or over the count of evaluated points, all of them, no grid") {
  const Sheet s = make_sheet();
  std::size_t evaluated = 0;
  for (ScanPointStatus st : s.c.status) evaluated += st == ScanPointStatus::evaluated;
  for (std::size_t cap : {evaluated, evaluated + 1, std::size_t{50000}}) {
    const ScanDisplay d = scan_display(s.c, s.cloud, cap);
    CHECK(d.voxel == 0);
    CHECK(d.points.size() == evaluated);
  }
  // One under: a grid, and the cap holds.
  const ScanDisplay d = scan_display(s.c, s.cloud, evaluated - 1);
  CHECK(d.voxel > 0);
  CHECK(d.points.size() <= evaluated - 1);
  // A cap of one point: still held.
  CHECK(scan_display(s.c, s.cloud, 1).points.size() == 1);
}

TEST_CASE("scan histogram: bins over every evaluated point and the zone, recounted") {
  const Sheet s = make_sheet();
  const ScanHistogram h = scan_histogram(s.c);
  REQUIRE(h.edges.size() == static_cast<std::size_t>(kScanHistogramBins) + 1);
  REQUIRE(h.counts.size() == static_cast<std::size_t>(kScanHistogramBins));
  CHECK(h.edges.front() < s.c.tolerance.lower());
  CHECK(h.edges.back() > s.c.tolerance.upper());
  std::vector<std::size_t> recount(h.counts.size(), 0);
  for (std::size_t i = 0; i < s.c.status.size(); ++i) {
    if (s.c.status[i] != ScanPointStatus::evaluated) continue;
    const double v = s.c.deviation[i];
    REQUIRE(v >= h.edges.front());
    REQUIRE(v <= h.edges.back());
    std::size_t k = 0;
    while (k + 1 < h.counts.size() && v >= h.edges[k + 1]) ++k;
    ++recount[k];
  }
  CHECK(recount == h.counts);
  for (std::size_t k = 1; k < h.edges.size(); ++k) CHECK(h.edges[k] > h.edges[k - 1]);
}
