#pragma once
// Where probe points may go in one region: the admissible set and the
// region's sampled geometry.
//
// A (u, v) of the region's face is admissible when
//   - it is inside the region (the even-odd test over the region's uv border
//     loops, the same test as RegionMap::region_at),
//   - it is kept by the face's trim and inside its parameter domain,
//   - the surface point is at least `border` mm from every edge of the
//     region (its border loops in xyz and the face's trim loops, sampled on
//     the surface) plus a margin covering how far those polylines may be from
//     the true edge curves (edge_distance.hpp: straight-line distance, a
//     lower bound of the distance on the surface),
//   - when a contact check is set (set_contact_check: the narrow-region rule
//     of docs/cmm.md, ball_contact.hpp), it passes.
// Points on a predicted gouge site are admissible on the site's terms
// (admissible_on_site): in the region and the trim, `border` mm from the
// face's own edges (parameter-rectangle boundary and trim loops) but not
// from the borders between curvature regions, which are lines of the
// classification, not of the part: a gouge predicted next to such a border
// must still be measured.
//
// The region is also sampled on a G x G grid of cells over its uv box (cell
// centres): area element, the larger principal curvature |k|max and, when a
// risk map is given, the predicted |error|. These give the region's area,
// curvature variation and mean risk for the allocation, and the densities
// of the area warps the sampling strategies map through.
//
// Units: mm, mm^2, 1/mm. Thread safety: const members may run concurrently.
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/part.hpp"
#include "partition/region_map.hpp"
#include "planning/area_warp.hpp"
#include "planning/edge_distance.hpp"
#include "planning/risk_map.hpp"

namespace furrow {

struct RegionDomainOptions {
  double border = 2;  // clearance from region edges [mm], >= 0
  // Extra clearance for the difference between the edge polylines and the
  // true edge curves: regions.json keeps border polylines within 1 um of
  // the surface curve (partition.hpp kDefaultChordTolerance); each edge of a
  // trim loop's uv polygon is cut here into the fewest chords, at most
  // `trim_samples_per_edge`, that keep its image within half this margin.
  double edge_margin = 2e-3;
  int trim_samples_per_edge = 64;
  // The face's parameter-rectangle boundary, sampled with this many chords
  // per side for the face-edge clearance of gouge-site points.
  int boundary_samples_per_side = 256;
  // Warp grid cells per direction: from the partition grid cells in the
  // region's uv box, clamped to [min_cells, max_cells].
  int min_cells = 8;
  int max_cells = 64;
};

// One cell of the region's sample grid.
struct DomainCell {
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  double area = 0;       // area of the cell on the surface [mm^2] (midpoint rule)
  double kappa = 0;      // max(|k1|, |k2|) [1/mm]; 0 at degenerate points
  double k1 = 0, k2 = 0; // principal curvatures [1/mm]
  double risk = 0;       // predicted |error| [mm], 0 without a risk map
  bool inside = false;   // the centre is inside the region (and the trim)
};

struct DomainStatistics {
  double area = 0;                 // sum of inside cells' areas [mm^2]
  double curvature_spread = 0;     // area-weighted std. dev. of (k1, k2): sqrt(var k1 + var k2) [1/mm]
  double mean_kappa = 0;           // area-weighted mean of |k|max [1/mm]
  double mean_risk = 0;            // area-weighted mean predicted |error| [mm]
};

class RegionDomain {
 public:
  // Precondition: `map` belongs to `part` (check_belongs_to) and `region_id`
  // is one of its regions. `risk` may be null. The part and map must outlive
  // the domain.
  RegionDomain(const Part& part, const RegionMap& map, int region_id, const RegionDomainOptions& options,
               const RiskMap* risk = nullptr);
  ~RegionDomain();
  RegionDomain(RegionDomain&&) noexcept;
  RegionDomain& operator=(RegionDomain&&) noexcept;

  int region_id() const { return region_id_; }
  int face_index() const { return region_->face; }
  const Region& region() const { return *region_; }
  const Face& face() const { return *face_; }
  const RegionDomainOptions& options() const { return options_; }

  // Inside the region and the face's trim (no clearance).
  bool inside(const Eigen::Vector2d& uv) const;
  // Straight-line distance from a surface point to the region's nearest edge
  // when below `reach`, else +infinity.
  double edge_distance(const Eigen::Vector3d& xyz, double reach) const;
  // Admissible (see above). On success returns the edge distance, capped at
  // `border + margin + 1` mm, and sets *xyz to the surface point.
  std::optional<double> admissible(const Eigen::Vector2d& uv, Eigen::Vector3d* xyz = nullptr) const;
  // The same with the clearance taken from the face's edges only (see above).
  std::optional<double> admissible_on_site(const Eigen::Vector2d& uv, Eigen::Vector3d* xyz = nullptr) const;
  // Straight-line distance from a surface point to the face's own edges
  // when below `reach`, else +infinity.
  double face_edge_distance(const Eigen::Vector3d& xyz, double reach) const;
  // Required straight-line distance to the edges: border + edge_margin.
  double required_edge_distance() const { return options_.border + options_.edge_margin; }

  // A further test of every admissible point (uv, surface point), run after
  // the edge clearance; it must be safe to call from several threads.
  using ContactCheck = std::function<bool(const Eigen::Vector2d& uv, const Eigen::Vector3d& xyz)>;
  void set_contact_check(ContactCheck check) { contact_check_ = std::move(check); }
  bool contact_checked() const { return static_cast<bool>(contact_check_); }

  const std::vector<DomainCell>& cells() const { return cells_; }
  int grid_cells() const { return grid_; }
  const DomainStatistics& statistics() const { return stats_; }
  // Surface length of the region's uv box along u and v [mm] (mean over the
  // grid rows/columns): the aspect strata are shaped by.
  double length_u() const { return length_u_; }
  double length_v() const { return length_v_; }

  // Warp carrying uniform density in [0, 1)^2 to density
  // area * (1 + kappa_weight * kappa / kappa_ref) * (risk_weight * risk + risk_floor)
  // over the region's uv box; cells outside the region get the region's mean
  // factor (their mass stays proportional to their area, so a point set
  // restricted to the region stays evenly spread and is not drawn outside).
  AreaWarp warp(double kappa_weight, double kappa_ref, double risk_weight, double risk_floor) const;
  AreaWarp area_warp() const { return warp(0, 1, 0, 1); }

 private:
  std::optional<double> admissible_against(const EdgeDistance& edges, const Eigen::Vector2d& uv,
                                           Eigen::Vector3d* xyz) const;

  int region_id_ = 0;
  const Region* region_ = nullptr;
  const Face* face_ = nullptr;
  RegionDomainOptions options_;
  std::unique_ptr<EdgeDistance> edges_;       // region borders and trim loops
  std::unique_ptr<EdgeDistance> face_edges_;  // parameter-rectangle boundary and trim loops
  ContactCheck contact_check_;                // empty: none
  int grid_ = 8;
  std::vector<DomainCell> cells_;  // u-major: cells_[i * grid_ + j]
  DomainStatistics stats_;
  double length_u_ = 0, length_v_ = 0;
};

}  // namespace furrow
