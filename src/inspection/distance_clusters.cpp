#include "inspection/distance_clusters.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <map>
#include <numeric>

namespace furrow {

namespace {

std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<std::vector<std::size_t>> distance_clusters(const std::vector<Eigen::Vector3d>& points,
                                                        double distance) {
  const std::size_t n = points.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  if (n > 1) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    for (const Eigen::Vector3d& p : points)
      cloud->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud(cloud);
    // Float coordinates: search a little wider, decide in double.
    const double search = distance * (1 + 1e-5) + 1e-5;
    std::vector<int> found;
    std::vector<float> squared;
    for (std::size_t i = 0; i < n; ++i) {
      tree.radiusSearch(cloud->points[i], search, found, squared);
      for (int k : found) {
        const std::size_t j = static_cast<std::size_t>(k);
        if (j <= i || (points[i] - points[j]).norm() > distance) continue;
        const std::size_t a = root(parent, i), b = root(parent, j);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // Roots are the smallest member of their tree, so map order = first member.
  std::map<std::size_t, std::vector<std::size_t>> by_root;
  for (std::size_t i = 0; i < n; ++i) by_root[root(parent, i)].push_back(i);
  std::vector<std::vector<std::size_t>> clusters;
  for (auto& [r, members] : by_root) clusters.push_back(std::move(members));
  return clusters;
}

}  // namespace furrow
