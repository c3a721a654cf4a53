#pragma once
// Contact points on the border of a face (DESIGN.md "Cutter geometry",
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
// Borders are found geometrically, so faces need not share parametrisations:
// a point on a side of its face's parameter rectangle (u or v at a domain
// end) is matched with the closest point of another face's domain sides
// within `distance_tolerance`. Borders along trim curves are not detected
// (the point is then treated as interior).
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

#include "geometry/part.hpp"
#include "machining/domain_sides.hpp"
#include "machining/local_gouge.hpp"

namespace furrow {

struct BorderOptions {
  // (u,v) within this fraction of the domain width of a side lies on it.
  double side_tolerance = 1e-9;
  // A point of another face's side this close [mm] is the same point.
  double distance_tolerance = 1e-3;
  // Normals differing more than this [degrees] make the edge a crease.
  double crease_angle_deg = 0.5;
  // Samples per side for seeding, and the 1-D Newton cap per side.
  int side_samples = 64;
  int max_iterations = 30;
};

// Unit tangent directions across each side in `sides` (at most two, a
// corner), perpendicular to the edge and pointing into the face. Returns the
// count.
int inward_directions(const SurfaceDerivatives& d, const Eigen::Vector3d& normal, unsigned sides,
                      std::array<Eigen::Vector3d, 2>& out);

struct BorderNeighbour {
  bool found = false;
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  double distance = 0;  // [mm]
  // False when the 1-D search on some side near the point stopped at
  // max_iterations or on a non-positive second derivative before it
  // converged: a neighbour there may have been missed (then `found` is
  // false and the point is treated as a free edge).
  bool converged = true;
};

// Finds, for a point on a face's border, the matching point on another
// face's border. Holds a reference to the part.
class BorderLocator {
 public:
  explicit BorderLocator(const Part& part, const BorderOptions& options = {});
  const BorderOptions& options() const { return options_; }
  const Part& part() const { return part_; }
  // The closest point within distance_tolerance on a domain side of a face
  // other than `face`; found = false when there is none.
  BorderNeighbour neighbour(std::size_t face, const Eigen::Vector3d& point) const;

 private:
  struct SideSample {
    double t;
    Eigen::Vector3d point;
  };
  struct Side {
    std::size_t face;
    unsigned side;
    std::vector<SideSample> samples;
    double spacing;  // largest distance between consecutive samples [mm]
  };
  const Part& part_;
  BorderOptions options_;
  std::vector<Side> sides_;
};

// Everything a gouge check needs at one contact point of a part.
struct ContactSurfaces {
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  DifferentialGeometry geometry;
  unsigned sides = 0;  // domain sides the point lies on (0: interior)
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
