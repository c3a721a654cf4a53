#include "partition/region_statistics.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace furrow {

namespace {

struct Accumulator {
  double sum = 0, min = 0, max = 0;
  void add(double value, double weight, bool first) {
    sum += value * weight;
    min = first ? value : std::min(min, value);
    max = first ? value : std::max(max, value);
  }
  ValueStats stats(double area) const { return {area > 0 ? sum / area : 0.0, min, max}; }
};

struct RegionSums {
  Accumulator K, H, k1, k2;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  float best_depth = -1;
  int best_cell_i = 0, best_cell_j = 0;
};

// Distance of every cell from the nearest cell outside its region, in cells.
cv::Mat depth_inside_regions(const RegionLabels& labels) {
  const int nu = labels.nu, nv = labels.nv;
  cv::Mat inner(nu, nv, CV_8U, cv::Scalar(0));
  for (int i = 1; i + 1 < nu; ++i) {
    auto* row = inner.ptr<unsigned char>(i);
    for (int j = 1; j + 1 < nv; ++j) {
      const int r = labels.at(i, j);
      if (r >= 0 && labels.at(i - 1, j) == r && labels.at(i + 1, j) == r &&
          labels.at(i, j - 1) == r && labels.at(i, j + 1) == r)
        row[j] = 255;
    }
  }
  cv::Mat depth;
  cv::distanceTransform(inner, depth, cv::DIST_L2, cv::DIST_MASK_5, CV_32F);
  return depth;
}

}  // namespace

std::vector<Region> region_statistics(const RegionLabels& labels,
                                      const std::vector<unsigned char>& cell_class,
                                      const CurvatureField& field, int face_index, int first_id) {
  const auto n = static_cast<std::size_t>(labels.count());
  std::vector<Region> regions(n);
  std::vector<RegionSums> sums(n);
  for (std::size_t r = 0; r < n; ++r) {
    regions[r].id = first_id + static_cast<int>(r);
    regions[r].face = face_index;
    regions[r].curvature_class = labels.region_class[r];
    regions[r].merged_components = labels.components[r];
    regions[r].area = 0;
  }
  const cv::Mat depth = depth_inside_regions(labels);
  for (int i = 0; i < labels.nu; ++i) {
    const float* depth_row = depth.ptr<float>(i);
    for (int j = 0; j < labels.nv; ++j) {
      const int l = labels.at(i, j);
      if (l < 0) continue;
      const std::size_t k = static_cast<std::size_t>(i) * labels.nv + j;
      const CurvatureSample& s = field.samples[k];
      Region& reg = regions[static_cast<std::size_t>(l)];
      RegionSums& acc = sums[static_cast<std::size_t>(l)];
      const bool first = reg.cells == 0;
      ++reg.cells;
      reg.area += s.area;
      if (cell_class[k] != static_cast<unsigned char>(reg.curvature_class)) reg.absorbed_area += s.area;
      acc.moment += s.area * s.point;
      acc.K.add(s.K, s.area, first);
      acc.H.add(s.H, s.area, first);
      acc.k1.add(s.k1, s.area, first);
      acc.k2.add(s.k2, s.area, first);
      reg.xyz_box.extend(s.point);
      if (depth_row[j] > acc.best_depth) {
        acc.best_depth = depth_row[j];
        acc.best_cell_i = i;
        acc.best_cell_j = j;
      }
    }
  }
  for (std::size_t r = 0; r < n; ++r) {
    Region& reg = regions[r];
    const RegionSums& acc = sums[r];
    reg.centroid = reg.area > 0 ? Eigen::Vector3d(acc.moment / reg.area)
                                : Eigen::Vector3d(reg.xyz_box.center());
    reg.K = acc.K.stats(reg.area);
    reg.H = acc.H.stats(reg.area);
    reg.k1 = acc.k1.stats(reg.area);
    reg.k2 = acc.k2.stats(reg.area);
    reg.interior_uv = field.uv(acc.best_cell_i, acc.best_cell_j);
    reg.interior_xyz = field.at(acc.best_cell_i, acc.best_cell_j).point;
  }
  return regions;
}

}  // namespace furrow
