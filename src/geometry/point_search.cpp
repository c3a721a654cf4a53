#include "geometry/point_search.hpp"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace furrow {

namespace {

// nanoflann's dataset interface over the owned points.
struct Dataset {
  const std::vector<Eigen::Vector3d>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Dataset>, Dataset, 3,
                                                  std::size_t>;

bool finite(const Eigen::Vector3d& p) { return p.allFinite(); }

void sort_by_distance(std::vector<PointNeighbour>& found) {
  std::sort(found.begin(), found.end(), [](const PointNeighbour& a, const PointNeighbour& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.index < b.index;
  });
}

}  // namespace

struct PointSearch::Tree {
  std::vector<Eigen::Vector3d> points;
  Dataset dataset;
  Index index;
  explicit Tree(std::vector<Eigen::Vector3d> p)
      : points(std::move(p)), dataset{&points}, index(3, dataset, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

PointSearch::PointSearch(std::vector<Eigen::Vector3d> points) {
  for (const Eigen::Vector3d& p : points)
    if (!finite(p)) throw std::invalid_argument("PointSearch: a point has a non-finite coordinate");
  tree_ = std::make_unique<Tree>(std::move(points));
}

PointSearch::~PointSearch() = default;
PointSearch::PointSearch(PointSearch&&) noexcept = default;
PointSearch& PointSearch::operator=(PointSearch&&) noexcept = default;

std::size_t PointSearch::size() const { return tree_->points.size(); }
const Eigen::Vector3d& PointSearch::point(std::size_t i) const { return tree_->points[i]; }

std::vector<PointNeighbour> PointSearch::nearest(const Eigen::Vector3d& q, std::size_t k) const {
  std::vector<PointNeighbour> out;
  if (tree_->points.empty() || k == 0 || !finite(q)) return out;
  // One more than asked, so that a tie at the k-th place is broken by index
  // whatever order the tree met the tied points in.
  const std::size_t want = std::min(tree_->points.size(), k + 1);
  std::vector<std::size_t> index(want);
  std::vector<double> squared(want);
  const std::size_t found = tree_->index.knnSearch(q.data(), want, index.data(), squared.data());
  out.reserve(found);
  for (std::size_t m = 0; m < found; ++m) out.push_back({index[m], std::sqrt(squared[m])});
  sort_by_distance(out);
  if (out.size() > k) out.resize(k);
  return out;
}

PointNeighbour PointSearch::nearest(const Eigen::Vector3d& q) const {
  const std::vector<PointNeighbour> one = nearest(q, 1);
  if (one.empty()) return {tree_->points.size(), std::numeric_limits<double>::infinity()};
  return one.front();
}

std::vector<PointNeighbour> PointSearch::within(const Eigen::Vector3d& q, double radius) const {
  std::vector<PointNeighbour> out;
  if (tree_->points.empty() || !finite(q) || !(radius >= 0)) return out;
  std::vector<std::pair<std::size_t, double>> found;
  // nanoflann's L2_Simple radius is squared; widen by one ulp-ish so that a
  // point at exactly `radius` is kept, then decide on the true distance.
  const double r2 = radius * radius * (1 + 1e-12);
  tree_->index.radiusSearch(q.data(), r2, found, nanoflann::SearchParams(32, 0, false));
  out.reserve(found.size());
  for (const auto& [i, d2] : found) {
    const double d = (tree_->points[i] - q).norm();
    if (d <= radius) out.push_back({i, d});
  }
  sort_by_distance(out);
  return out;
}

}  // namespace furrow
