// The far-spray rule of the scan module against PCL's own
// pcl::StatisticalOutlierRemoval, the second implementation: the module
// computes the class's rule in its parallel pass (scan_preprocess.hpp), and
// must fire on exactly the points the class removes.
#include <doctest/doctest.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/point_types.h>

#include <random>
#include <set>

#include "io/scan/scan_preprocess.hpp"

using namespace furrow;

TEST_CASE("scan far-spray rule flags what pcl StatisticalOutlierRemoval removes") {
  for (const int k : {8, 16}) {
    CAPTURE(k);
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(-30, 30), off(0.5, 4.0);
    std::normal_distribution<double> noise(0, 0.01);
    ScanCloud c;
    c.file = "cloud.ply";
    for (int i = 0; i < 20000; ++i) {
      const double x = u(rng), y = u(rng);
      double z = 0.01 * x * y + noise(rng);
      if (i % 97 == 0) z += off(rng);
      c.points.emplace_back(x + 700, y - 80, z + 40);
    }
    ScanPreprocessOptions o;
    o.outlier_neighbours = k;
    o.normal_neighbours = 12;
    const ScanPreprocessed s = preprocess_scan(c, o);
    // The class on the same float coordinates relative to the same origin.
    pcl::PointCloud<pcl::PointXYZ>::Ptr local(new pcl::PointCloud<pcl::PointXYZ>);
    for (const Eigen::Vector3d& p : c.points) {
      const Eigen::Vector3d d = p - s.origin;
      local->push_back(pcl::PointXYZ(static_cast<float>(d.x()), static_cast<float>(d.y()), static_cast<float>(d.z())));
    }
    pcl::StatisticalOutlierRemoval<pcl::PointXYZ> filter(true);
    filter.setInputCloud(local);
    filter.setMeanK(k);
    filter.setStddevMulThresh(o.outlier_sigmas);
    pcl::Indices kept;
    filter.filter(kept);
    std::set<std::size_t> removed;
    for (const auto i : *filter.getRemovedIndices()) removed.insert(static_cast<std::size_t>(i));
    std::set<std::size_t> flagged;
    for (std::size_t i = 0; i < s.statistical.size(); ++i)
      if (s.statistical[i]) flagged.insert(i);
    MESSAGE("k " << k << ": PCL removes " << removed.size() << ", the module's statistical rule fires on "
                 << flagged.size() << "; spray " << s.spray_far << " far, " << s.spray_near << " near");
    CHECK(removed.size() > 150);
    CHECK(flagged == removed);
    CHECK(s.statistical_count == flagged.size());
    // Far spray is spray the statistical rule also fires on.
    for (std::size_t i = 0; i < s.spray.size(); ++i)
      if (s.spray[i] == kSprayFar) CHECK(s.statistical[i]);
  }
}
