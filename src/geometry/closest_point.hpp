#pragma once
// Closest point on a Part: the foot point of a query point on the nearest
// face, found globally, not just locally.
//
// Why global: a CMM point near the axis of a concave cylinder, near the
// evolute of a dimple, beyond a face edge or over a sharp edge between faces
// has several local minima of the distance; plain Newton from one seed can
// converge to a wrong one and nobody notices. Here every face is cut into
// small (u,v) cells (seed_grid.hpp), each with conservative bounding volumes;
// a query walks a box tree nearest-first (or, inside a lattice around the
// part, reads its cube's list of candidate cells: candidate_voxels.hpp),
// screening the cells whose bounding
// volume could still hold something nearer than the best foot so far or the
// nearest cell middle seen, then solves the box-constrained problem in the
// candidates by increasing lower bound while one could still beat the best
// foot (branch and bound). The answer is
// therefore the minimum over all cells, up to the assumption that the
// distance has one local minimum per cell (cells are a fraction of a knot
// span; see ClosestPointOptions). Typical cost: 1 to 2 cells and 3 Newton steps,
// 0.5 us per point near the mould example's surface, 1 us 20 mm off it
// (bench_projection).
//
// Within a cell: projected Newton on (u,v) with an active set (a parameter at
// its bound whose gradient pushes outward is fixed, so on a domain edge the
// search continues along the edge), Armijo backtracking, and Gauss-Newton
// instead of Newton where the Hessian is not positive definite (points past
// the centre of curvature). Trimmed faces: cells wholly trimmed away are
// dropped; in a cell cut by a trim loop, a minimum that falls into the
// trimmed-away part is replaced by the minimum along the loop's segments in
// that cell (1-D Newton per segment), i.e. the foot lies on the trim boundary.
//
// Units: millimetres, part coordinates. Thread safety: a ClosestPointFinder is
// immutable after construction; project() may be called from many threads.
// Non-convergence is reported in the result (converged == false), never
// thrown; the returned foot is then the best point found.
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/part.hpp"

namespace furrow {

struct ClosestPointOptions {
  // Seed cells per knot span per direction, and bounds on the cells per
  // direction of a face. Smaller cells make "one minimum per cell" safer and
  // cost memory (about 200 bytes a cell) and query time near flat regions.
  int cells_per_span = 2;
  int min_cells = 8;
  int max_cells = 256;
  // Newton iterations per local solve (a cell, or a trim segment).
  int max_newton_iterations = 50;
  // Backtracking halvings before a step is declared impossible.
  int max_line_search_halvings = 40;
  // A local solve has converged when a (projected) Newton step moves the
  // surface point less than this [mm]. Newton converges quadratically, so the
  // foot is then exact to far below this.
  double step_tolerance = 1e-11;
  // When no step decreases the distance any more (rounding floor), the solve
  // still counts as converged if the last full step was shorter than this [mm]
  // (the accuracy promised for a converged foot point).
  double stall_tolerance = 1e-9;
  // Samples along each trim segment (clipped to a cell) that seed its 1-D solve.
  int trim_samples_per_segment = 4;
  // Candidate cells per voxel of a lattice around the part
  // (candidate_voxels.hpp): a query in the lattice screens its cube's short
  // list instead of walking the box tree, which halves the cost of points
  // off the surface. The answer is the same either way.
  bool candidate_voxels = true;
};

// Where on the face the foot point lies.
enum class FootLocation {
  interior,     // stationary point: q - foot is along the normal
  domain_edge,  // on the parameter rectangle's boundary (the point is beyond the edge)
  trim_edge,    // on a trim loop (the unconstrained minimum is trimmed away)
};
const char* to_string(FootLocation location);

struct ClosestPoint {
  std::size_t face = 0;                               // index into Part::faces
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();       // foot parameters
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // foot point S(u,v) [mm]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, out of the material
  double distance = 0;                                // |q - point| [mm]
  double signed_distance = 0;  // distance, negative when q is inside the material
                               // ((q - point) . normal < 0)
  FootLocation location = FootLocation::interior;
  bool converged = false;  // the local solve that produced the foot converged
  int iterations = 0;      // Newton iterations of that solve
  int cells_examined = 0;  // local solves run for this query (cost indicator)
};

class SeedGrid;
class CandidateVoxels;

// Loops of projections run in parallel from this many points on (OpenMP
// `if` clause). Below it the threads' wake-up costs more than the work, and
// on a loaded machine OpenMP's spinning threads slow the few-point
// registrations (dozens of fits of 8 to 100 points) many times over.
constexpr std::size_t kParallelProjections = 512;

class ClosestPointFinder {
 public:
  // Builds the seed cells of every face (cost: ~25 surface evaluations per
  // cell). The part must outlive the finder. Throws InputError for an
  // inconsistent option (non-positive counts or tolerances) or a part whose
  // faces are all trimmed away.
  explicit ClosestPointFinder(const Part& part, ClosestPointOptions options = {});
  ~ClosestPointFinder();
  ClosestPointFinder(ClosestPointFinder&&) noexcept;
  ClosestPointFinder& operator=(ClosestPointFinder&&) noexcept;

  const Part& part() const { return *part_; }
  // The part's control box (Part::control_box) as it was at construction:
  // it contains the part, so its exterior distance bounds the part's from
  // below. Kept because callers that march along segments ask for it per
  // segment, and Part::control_box walks every face.
  const Eigen::AlignedBox3d& control_box() const { return control_box_; }
  const ClosestPointOptions& options() const { return options_; }
  std::size_t cell_count() const;

  // Global closest point over all faces.
  ClosestPoint project(const Eigen::Vector3d& q) const;
  // Same answer, faster when `hint` (a previous foot of a nearby query, e.g.
  // the same measured point one registration iteration earlier) is close: its
  // cell is solved first, which tightens the bound at once. The result is
  // still the global minimum; a bad hint only costs time.
  ClosestPoint project(const Eigen::Vector3d& q, const ClosestPoint& hint) const;

  // Feet of `points` in their order, each search hinted by the foot of the
  // point before: measured points usually come in scan or probe-path order,
  // so the previous foot is a near-perfect first bound. Every answer is
  // still the global minimum (equal to project(q) within the solver's
  // tolerance); a jump between distant points only costs one cell solve.
  std::vector<ClosestPoint> project_in_order(const std::vector<Eigen::Vector3d>& points) const;

  // Global closest point over every face except `face`: what touches a
  // point of that face from elsewhere (a neighbouring face across an edge).
  // Empty when the part has no other face left after trimming.
  std::optional<ClosestPoint> project_to_other_faces(const Eigen::Vector3d& q, std::size_t face) const;

 private:
  static constexpr std::size_t kNoFace = static_cast<std::size_t>(-1);
  ClosestPoint search(const Eigen::Vector3d& q, const ClosestPoint* hint, std::size_t excluded = kNoFace) const;

  const Part* part_;
  Eigen::AlignedBox3d control_box_;
  ClosestPointOptions options_;
  std::unique_ptr<SeedGrid> grid_;
  std::unique_ptr<CandidateVoxels> voxels_;  // over grid_'s cells
};

}  // namespace furrow
