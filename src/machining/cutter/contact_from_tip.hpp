#pragma once
// The inverse of cutter_location.hpp: for a tool tip position over a part,
// the contact point(s) where the cutter touches the surface. Tool-path
// import uses it to turn G-code tips back into contact points and (u,v).
//
// The tip's xy fixes the axis; the cutter touches the surface wherever it is
// tangent to it with that axis, or where it sits on a face's edge. Three
// kinds of contact exist for the end mill of cutter.hpp:
//   corner       the corner arc touches: S_xy(u,v) + o_xy(n(u,v)) = T_xy, with
//                o(n) the tip offset of cutter_location.hpp, n_z > 0
//                (not a side contact, below);
//   flat_bottom  the flat bottom touches a point with a horizontal tangent
//                plane (n = +z) within R - r of the axis (a dome's top under
//                a flat or bull-nose cutter);
//   edge         the cutter sits on a side of a face's parameter rectangle
//                (the rim of a pocket, the far wall of a narrow trough): the
//                highest point of the side curve relative to the cutter's
//                lower envelope, found by a bracketed 1D search
//                (base/scalar_search.hpp) between side samples.
// Each contact implies a tip height `tip_z` (the cutter lowered at that xy
// until it touches there). Lowered from above, the cutter rests on the
// highest of them, so contacts are sorted by tip_z, highest first, and
// `gap` = T_z - contacts[0].tip_z: 0 for a tip on the cutter-location
// surface, > 0 when the tip is above it (air), < 0 when the cutter would cut
// in. Tangencies below the highest one are listed too: they show where the
// offset surface folds (a concave region tighter than the cutter).
//
// Method: each face is sampled once on a seed grid with the offset position
// S + o(n) of every seed; a query starts Newton iterations (exact Jacobian,
// the normal's derivative from the Weingarten equations; step halving on the
// residual; clamped to the parameter rectangle) from the seeds whose offset
// positions are nearest the tip in xy, from the seeds that stick up highest
// into the cutter's envelope (where a lowered cutter rests), and for flat
// bottoms from the highest seeds under the bottom disc; edges from their
// samples under the cutter that are local maxima. Converged solutions
// closer than `duplicate_distance` are merged. Starts that stall or hit the
// cap inside a face are counted as failed (a start that runs off the face's
// edge is not: its tangency is not on this face); with no contact and a
// failed start the status is not_converged.
// The seeded search alone can miss where the cutter rests (a narrow rise
// between seeds under a wide cutter). So every query then runs the bounded
// drop cutter of drop_cutter.hpp with the best height found as its start:
// it either proves that no part point rests the cutter higher (within its
// height_tolerance) or returns the point that does, which is polished by a
// corner Newton start from there (kept as it is when that converges lower:
// an edge, a trim curve, a flat bottom). So contacts[0].tip_z is the rest
// height within `bound.height_tolerance` whenever `complete` (points within
// `bound.radial_tolerance` of the shank radius graze: drop_cutter.hpp);
// hitting the bounded search's cell cap clears `complete` and sets
// `unresolved`, a height the cutter cannot rest above.
// The Newton searches do not treat trim curves as edges; the bounded search
// finds a cutter resting on one as a point kept by the trim, within its
// tolerance (listed as a corner or flat_bottom contact at that point).
// Side contacts (a vertical wall, n_z = 0 within the location options'
// vertical_tolerance: cutter_location.hpp) are not listed: the cutter's
// side there is vertical, so lowering the cutter slides it along the wall
// and the wall implies no tip height. For the same reason an edge point
// exactly at the shank radius R (within 1e-9 R, rounding) does not hold the
// cutter: the side grazes it (the wall's own top edge, beside a side
// contact); an edge that crosses into the disc holds it just inside, at the
// same height to first order. The cutter located at a side contact by
// cutter_location() rests on whatever else lies under it, or on nothing
// (no_contact): it does not cut into the wall it touches.
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "geometry/part.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/cutter/cutter_location.hpp"
#include "machining/cutter/drop_cutter.hpp"
#include "machining/cutter/face_seeds.hpp"

namespace furrow {

struct TipContactOptions {
  int seed_grid = 33;       // seed nodes per direction per face
  int max_starts = 3;       // Newton starts per query and seed kind (distinct places)
  int max_iterations = 40;  // per start
  double tolerance = 1e-9;  // [mm] xy residual of a corner contact at convergence
  double duplicate_distance = 1e-6;  // [mm] contacts closer than this are one
  // Samples per face side for edge contacts: an edge is seen where one of
  // its samples lies under the cutter (so keep the spacing below the radius).
  int edge_samples = 129;
  // The search along a side stops below this fraction of its parameter
  // range (or after scalar_search's 200 iterations).
  double edge_tolerance = 1e-13;
  CutterLocationOptions location;
  DropCutterOptions bound;  // the bounded search run after the Newton starts
};

enum class ContactKind : unsigned char { corner, flat_bottom, edge };
const char* to_string(ContactKind kind);

struct TipContact {
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // contact point [mm]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // part normal there
  ContactKind kind = ContactKind::corner;
  double tip_z = 0;  // tip height at which the cutter touches here [mm]
  int iterations = 0;
};

enum class TipContactStatus : unsigned char {
  found,          // at least one contact
  not_converged,  // no contact, and some Newton start hit the iteration cap
  no_contact,     // no tangency under the cutter (e.g. the tip is off the part)
};
const char* to_string(TipContactStatus status);

struct TipContactResult {
  TipContactStatus status = TipContactStatus::no_contact;
  std::vector<TipContact> contacts;  // highest tip_z first
  double gap = 0;                    // tip.z - contacts[0].tip_z [mm]; 0 if none
  int starts = 0;                    // Newton starts tried
  int failed_starts = 0;             // of which stalled or hit the cap inside a face
  int cells = 0;                     // cells bounded by the bounded search
  // False when the bounded search hit its cell cap: a higher rest than
  // contacts[0] is then possible, up to `unresolved` [mm] (-infinity when complete).
  bool complete = true;
  double unresolved = -std::numeric_limits<double>::infinity();
};

class TipContactFinder {
 public:
  // Keeps references to `part` and `cutter`: both must outlive the finder.
  TipContactFinder(const Part& part, const Cutter& cutter, const TipContactOptions& options = {});
  TipContactResult find(const Eigen::Vector3d& tip) const;

 private:
  struct Seed {
    std::size_t face;
    Eigen::Vector2d uv;
    Eigen::Vector3d point;
    Eigen::Vector2d offset_xy;  // S_xy + o_xy(n): where the axis is for this contact
    bool corner;                // n_z > vertical tolerance: a corner contact is possible
  };
  const Part& part_;
  const Cutter& cutter_;
  TipContactOptions options_;
  std::vector<Seed> seeds_;
  struct EdgeSample {
    double t;
    Eigen::Vector3d point;
  };
  struct Edge {
    std::size_t face;
    unsigned side;  // DomainSide of compound_border.hpp
    std::vector<EdgeSample> samples;
  };
  std::vector<Edge> edges_;
  double seed_spacing_ = 0;  // largest distance between neighbouring seeds [mm]
  DropCutter drop_;
};

}  // namespace furrow
