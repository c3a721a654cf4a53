#pragma once
// Candidate cells per voxel, for the closest-point search
// (closest_point.hpp): a lattice of cubes over the part's box, grown on
// every side, each holding the seed cells (seed_grid.hpp) that may hold the
// global foot of some point in the cube. A query in the lattice screens that
// short list instead of walking the box tree.
//
// Why: a point far off the surface (20 mm, or anywhere in the part's box)
// lies within the box distance of many cells, and walking the tree down to
// them cost half of such a query even when the answer's cell was known (a
// perfect hint). The list of a cube is computed once, by a walk for the
// whole cube, and serves every later point in it.
//
// The lists are conservative, so the answer is the same as the tree's: for
// a cube with centre c and half diagonal r, and any point q in it,
//   * the answer's distance is at most |c - s| + r for every kept surface
//     sample s (CellBounds::surface_point), so at most U, the least of those;
//   * a cell's box is at least its distance from c minus r from q, so a cell
//     whose box is farther than U + r from c cannot hold the answer;
//   * the cone-of-normals test of CellBounds, with every coordinate of q
//     allowed to differ from c's by r, is passed by the cell holding an
//     orthogonal foot of any q in the cube.
// A cell kept by both stays in the list; the query then screens it with q
// itself.
//
// Lists are built lazily, on the second query in a cube (building one costs
// a few tree walks, so a cube asked once is cheaper walked): points
// projected once cost what the walk costs, points projected again (every
// iteration of a registration) take the lists. Thread safety: a list is
// published with an atomic compare-and-swap; two threads that race on a
// cube compute the same list and one copy is dropped. Memory: a pointer and
// a byte per cube (at most kMaxVoxels) plus the lists built.
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace furrow {

class SeedGrid;

// A cube's candidate cells (indices into SeedGrid::cells()), or no list
// (`cells` null).
struct CandidateCells {
  const std::uint32_t* cells = nullptr;
  std::uint32_t count = 0;
  explicit operator bool() const { return cells != nullptr; }
  const std::uint32_t* begin() const { return cells; }
  const std::uint32_t* end() const { return cells + count; }
};

class CandidateVoxels {
 public:
  // The lattice over the grid's cells: about kVoxelsPerCell cubes per cell
  // (at most kMaxVoxels), over the cells' box grown on every side by a
  // quarter of its largest side.
  explicit CandidateVoxels(const SeedGrid& grid);
  ~CandidateVoxels();
  CandidateVoxels(const CandidateVoxels&) = delete;
  CandidateVoxels& operator=(const CandidateVoxels&) = delete;

  static constexpr double kVoxelsPerCell = 128;
  static constexpr std::size_t kMaxVoxels = std::size_t{1} << 20;

  static constexpr std::uint8_t kQueriesBeforeList = 1;

  // The cells (indices into SeedGrid::cells()) that may hold the global
  // foot of q, or null when q lies outside the lattice (or is not finite)
  // or its cube's list is not built yet: the caller then walks the tree.
  CandidateCells cells_near(const Eigen::Vector3d& q) const;

  double voxel_size() const { return size_; }
  std::size_t voxel_count() const { return count_; }

 private:
  // The cube's list as one block: its length, then the cells. One block
  // per cube, so a query follows one pointer.
  std::unique_ptr<std::uint32_t[]> build_list(std::size_t voxel) const;

  const SeedGrid* grid_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double size_ = 0;
  int n_[3] = {0, 0, 0};
  std::size_t count_ = 0;
  std::unique_ptr<std::atomic<const std::uint32_t*>[]> lists_;
  std::unique_ptr<std::atomic<std::uint8_t>[]> queries_;  // walks so far, up to kQueriesBeforeList
};

}  // namespace furrow
