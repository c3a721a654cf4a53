#pragma once
// Contact points on the border of a face (docs/architecture.md "Cutter geometry",
// compound surfaces).
//
// At a contact point on the common edge of two faces the part is not one
// smooth surface: on one side of the edge it curves like face A, on the other
// like face B. A tangent direction that points into A sees A's curvature, one
// that points into B sees B's, so each face is compared with the cutter only
// over its own half of the directions (the half-plane bounded by the edge
// tangent, on its side; a quarter at a face corner). The ranges and the
// largest excess are the union over both. At a free edge (no neighbour) the
// face is compared over the directions into it only: beyond it there is no
// part to gouge.
//
// A point is on its face's border when it lies on a side of the face's
// parameter rectangle or on one of its trim loops (kTrimEdge; the inward
// direction then comes from the loop edge's tangent and the side the trim
// keeps). Borders are found geometrically, so faces need not share
// parametrisations: the neighbour is the global closest point of the other
// faces (ClosestPointFinder, trims respected) when it lies within
// `distance_tolerance` and on that face's own border. The finder reports
// whether its local solve converged; a neighbour search that did not is
// reported (BorderNeighbour::converged), never hidden.
//
// Tangent continuity: if the two faces' normals differ by more than
// `crease_angle_deg` the edge is a crease, where curvatures do not describe
// the contact. A convex crease (the faces fall away from each other) is
// checked on the point's own face only; a concave crease cannot be touched
// without cutting into the other face and is reported as
// GougeStatus::concave_crease. Otherwise the cutter is located with the mean
// of the two normals.
//
// Horizontal contacts of a flat-bottomed cutter (cutter_curvature.hpp) on a
// border: the axis may lie on either side of the contact; both placements
// (the flat bottom over this face or away from it) are checked and the one
// with the smaller excess is reported, as a CAM system free to choose would.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/closest_point.hpp"
#include "geometry/part.hpp"
#include "geometry/domain_sides.hpp"
#include "machining/gouge/local_gouge.hpp"

namespace furrow {

// Bit of ContactSurfaces::sides for a point on a trim loop (the domain
// sides are DomainSide bits).
constexpr unsigned kTrimEdge = 16;

struct BorderOptions {
  // (u,v) within this fraction of the domain width of a side or a trim loop
  // lies on it.
  double side_tolerance = 1e-9;
  // A point of another face's border this close [mm] is the same point.
  double distance_tolerance = 1e-3;
  // Normals differing more than this [degrees] make the edge a crease.
  double crease_angle_deg = 0.5;
  // The neighbour search (its iteration caps and tolerances).
  ClosestPointOptions closest;
};

// Where (u,v) lies on its face's border: the sides (DomainSide bits, and
// kTrimEdge) and the unit tangent directions across them pointing into the
// face (at most two, a corner; a third side is dropped). A side whose
// opposite side meets it in space (within distance_tolerance, at this
// point) is a seam of a closed face, not a border, and is left out.
struct BorderDirections {
  unsigned sides = 0;
  std::array<Eigen::Vector3d, 2> inward{};
  int count = 0;
};
BorderDirections border_directions(const Face& face, const Eigen::Vector2d& uv, const SurfaceDerivatives& d,
                                   const Eigen::Vector3d& normal, const BorderOptions& options);

struct BorderNeighbour {
  bool found = false;
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  double distance = 0;  // [mm]
  // False when the closest-point solve that decided the neighbour did not
  // converge: a neighbour may have been missed (then `found` is false and
  // the point is treated as a free edge).
  bool converged = true;
};

// Finds, for a point on a face's border, the matching point on another
// face's border. Holds a reference to the part and its own closest-point
// finder (built once: a few surface evaluations per seed cell).
class BorderLocator {
 public:
  explicit BorderLocator(const Part& part, const BorderOptions& options = {});
  const BorderOptions& options() const { return options_; }
  const Part& part() const { return part_; }
  // The closest point of a face other than `face`, when it lies within
  // distance_tolerance and on that face's border; found = false otherwise.
  BorderNeighbour neighbour(std::size_t face, const Eigen::Vector3d& point) const;

 private:
  const Part& part_;
  BorderOptions options_;
  ClosestPointFinder finder_;
};

// Everything a gouge check needs at one contact point of a part.
struct ContactSurfaces {
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  DifferentialGeometry geometry;
  unsigned sides = 0;  // DomainSide bits and kTrimEdge the point lies on (0: interior)
  std::array<Eigen::Vector3d, 2> inward{};
  int inward_count = 0;
  bool has_neighbour = false;
  std::size_t neighbour_face = 0;
  Eigen::Vector2d neighbour_uv = Eigen::Vector2d::Zero();
  DifferentialGeometry neighbour_geometry;
  std::array<Eigen::Vector3d, 2> neighbour_inward{};
  int neighbour_inward_count = 0;
  double crease_angle = 0;  // [rad] between the faces' normals
  bool crease = false;      // crease_angle above the option's
  bool concave_crease = false;
  bool border_search_converged = true;  // BorderNeighbour::converged
};

ContactSurfaces contact_surfaces(const BorderLocator& locator, std::size_t face,
                                 const Eigen::Vector2d& uv);

// The gouge check at a contact point, border rules included.
LocalGouge check_contact(const Cutter& cutter, const ContactSurfaces& contact,
                         const GougeOptions& options = {});

}  // namespace furrow
