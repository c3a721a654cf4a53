#include "geometry/candidate_voxels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/seed_grid.hpp"

namespace furrow {

CandidateVoxels::CandidateVoxels(const SeedGrid& grid) : grid_(&grid) {
  const Eigen::AlignedBox3d& cells_box = grid.nodes()[0].box;
  const Eigen::Vector3d sides = cells_box.sizes();
  const double margin = 0.25 * sides.maxCoeff();
  const Eigen::Vector3d lo = cells_box.min().array() - margin, extent = sides.array() + 2 * margin;
  const double target = std::min(kVoxelsPerCell * static_cast<double>(grid.cells().size()),
                                 static_cast<double>(kMaxVoxels));
  if (!(extent.minCoeff() > 0) || !std::isfinite(extent.prod())) return;  // no lattice: the tree serves
  size_ = std::cbrt(extent.prod() / target);
  // Rounding up may exceed the target by the lattice's surface; shrink the
  // cubes until the count fits the cap.
  for (;;) {
    std::size_t count = 1;
    for (int a = 0; a < 3; ++a) {
      n_[a] = std::max(1, static_cast<int>(std::ceil(extent(a) / size_)));
      count *= static_cast<std::size_t>(n_[a]);
    }
    if (count <= kMaxVoxels) {
      count_ = count;
      break;
    }
    size_ *= 1.1;
  }
  origin_ = lo;
  lists_ = std::make_unique<std::atomic<const std::uint32_t*>[]>(count_);
  queries_ = std::make_unique<std::atomic<std::uint8_t>[]>(count_);
  for (std::size_t k = 0; k < count_; ++k) {
    lists_[k].store(nullptr, std::memory_order_relaxed);
    queries_[k].store(0, std::memory_order_relaxed);
  }
}

CandidateVoxels::~CandidateVoxels() {
  for (std::size_t k = 0; k < count_; ++k) delete[] lists_[k].load(std::memory_order_relaxed);
}

CandidateCells CandidateVoxels::cells_near(const Eigen::Vector3d& q) const {
  if (count_ == 0) return {};
  std::size_t voxel = 0;
  for (int a = 0; a < 3; ++a) {
    const double t = (q(a) - origin_(a)) / size_;
    // Also false for NaN: such points go to the tree, which answers them as before.
    if (!(t >= 0 && t < n_[a])) return {};
    voxel = voxel * static_cast<std::size_t>(n_[a]) + static_cast<std::size_t>(t);
  }
  std::atomic<const std::uint32_t*>& slot = lists_[voxel];
  const std::uint32_t* block = slot.load(std::memory_order_acquire);
  if (!block) {
    // The first queries in a cube walk the tree: a list costs a few walks
    // and pays only when the cube is asked again. (The count is a hint: a
    // lost increment between racing threads only builds the list a query
    // later.)
    std::atomic<std::uint8_t>& seen = queries_[voxel];
    const std::uint8_t count = seen.load(std::memory_order_relaxed);
    if (count < kQueriesBeforeList) {
      seen.store(static_cast<std::uint8_t>(count + 1), std::memory_order_relaxed);
      return {};
    }
    std::unique_ptr<std::uint32_t[]> built = build_list(voxel);
    const std::uint32_t* expected = nullptr;
    if (slot.compare_exchange_strong(expected, built.get(), std::memory_order_acq_rel)) {
      block = built.release();
    } else {
      block = expected;  // another thread published the same list first
    }
  }
  return {block + 1, block[0]};
}

std::unique_ptr<std::uint32_t[]> CandidateVoxels::build_list(std::size_t voxel) const {
  int index[3];
  for (int a = 2; a >= 0; --a) {
    index[a] = static_cast<int>(voxel % static_cast<std::size_t>(n_[a]));
    voxel /= static_cast<std::size_t>(n_[a]);
  }
  const Eigen::Vector3d c = origin_ + size_ * (Eigen::Vector3d(index[0], index[1], index[2]).array() + 0.5).matrix();
  // Half diagonal, grown a little: c and the cube's corners are rounded.
  const double r = size_ * (0.5 * std::sqrt(3.0)) * (1 + 1e-9);
  const auto& nodes = grid_->nodes();
  const auto& bounds = grid_->bounds();

  // A walk of the box tree for the whole cube: nodes farther than U + r
  // from c are skipped, U being the least |c - s| + r seen so far (it only
  // falls, so what it skips the final U would skip too).
  struct Kept {
    double lower;  // the cell's box distance from c, minus r
    std::uint32_t cell;
  };
  std::vector<Kept> kept;
  double upper = std::numeric_limits<double>::infinity();
  // Nearer child first, so that U falls early.
  std::int32_t stack[128];
  double reach[128];  // the node's box distance from c
  int top = 0;
  stack[top] = 0;
  reach[top++] = std::sqrt(nodes[0].box.squaredExteriorDistance(c));
  while (top > 0) {
    --top;
    if (reach[top] - r > upper) continue;
    const SeedNode& node = nodes[static_cast<std::size_t>(stack[top])];
    if (node.left >= 0) {
      const double dl = std::sqrt(nodes[static_cast<std::size_t>(node.left)].box.squaredExteriorDistance(c));
      const double dr = std::sqrt(nodes[static_cast<std::size_t>(node.right)].box.squaredExteriorDistance(c));
      const bool left_first = dl <= dr;
      stack[top] = left_first ? node.right : node.left;
      reach[top++] = left_first ? dr : dl;
      stack[top] = left_first ? node.left : node.right;
      reach[top++] = left_first ? dl : dr;
      continue;
    }
    for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
      const CellBounds& cell = bounds[k];
      upper = std::min(upper, (cell.surface_point - c).norm() + r);
      const Eigen::Vector3d local = cell.axes * (c - cell.centre);
      const double lower = (local.cwiseAbs() - cell.half_extent).cwiseMax(0.0).norm() - r;
      if (lower <= upper && cell.may_hold_foot_near(c, r)) kept.push_back({lower, k});
    }
  }
  std::uint32_t count = 0;
  for (const Kept& k : kept) count += k.lower <= upper;
  auto block = std::make_unique<std::uint32_t[]>(count + 1);
  block[0] = count;
  std::uint32_t* out = block.get() + 1;
  for (const Kept& k : kept)
    if (k.lower <= upper) *out++ = k.cell;
  return block;
}

}  // namespace furrow
