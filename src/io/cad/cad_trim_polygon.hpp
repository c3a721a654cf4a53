#pragma once
// Trim polygons from a face's boundary curves, in the NURBS's (s,t).
//
// Furrow's Trim is polygonal (trim.hpp), CAD boundaries are curves. Each curve
// is cut into polygon edges whose chord sag, measured in 3-D at the curve's
// parameter midpoint (distance from the curve point to the polygon point
// nearest to it in (s,t)), is at most `chord_tolerance`, and whose (s,t) sag is
// at most `uv_tolerance` of the domain's width or height. The count per curve
// is chosen from a coarse pass (sag falls with the square of the count), so
// polygon edges come out nearly even, then checked edge by edge and halved
// where still needed.
//
// An inscribed polygon loses the sliver between chord and arc on every edge
// (2/3 of sag times chord), always on the same side: a disc of radius R comes
// out short by 4/3 sag/R of its area. Each vertex is therefore moved toward the
// curve's outside by 2/3 of the length-weighted sag of its two edges, which
// balances the slivers (the polygon then crosses the curve; it stays within
// about 2/3 of the sag on either side) and makes area and containment unbiased.
// Straight pieces (zero sag) do not move, so loops along the domain's edges and
// iso-lines stay exact.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "geometry/nurbs_surface.hpp"
#include "geometry/trim.hpp"

namespace furrow {

struct TrimPolygonOptions {
  double chord_tolerance = 1e-5;  // [mm] largest 3-D chord sag
  double uv_tolerance = 1e-4;     // largest (s,t) sag as a fraction of the domain's width/height
  int max_subdivisions = 24;      // halvings of a polygon edge before giving up on the tolerance
};

// One boundary curve of a wire, in running order: its (s,t) at parameter x
// for x from `from` to `to` (either order). A collapsed curve (a pole or apex
// seen in the parameter plane) is straight and needs no sampling.
struct BoundaryCurve {
  std::function<Eigen::Vector2d(double)> st;
  double from = 0, to = 1;
  bool collapsed = false;
};

class TrimPolygonBuilder {
 public:
  // `surface` must outlive the builder.
  TrimPolygonBuilder(const NurbsSurface& surface, const TrimPolygonOptions& options);

  // The closed polygon of one wire (its curves joined end to end), balanced,
  // with vertices on straight runs removed. May have fewer than 3 vertices
  // for a degenerate wire.
  UvLoop loop(const std::vector<BoundaryCurve>& wire);

  // Largest chord sag measured on any accepted polygon edge [mm], and whether
  // every edge met the tolerances before max_subdivisions stopped it.
  double worst_sag() const { return worst_sag_; }
  bool tolerance_met() const { return met_; }

 private:
  struct Sample {
    double x;
    Eigen::Vector2d st;
  };
  struct Sag {
    double mm = 0, uv = 0;                            // 3-D and relative (s,t) sag
    Eigen::Vector2d vector = Eigen::Vector2d::Zero();  // from the chord to the curve, (s,t)
  };
  Sag measure(const BoundaryCurve& c, const Sample& a, const Sample& b, Sample& mid) const;
  void refine(const BoundaryCurve& c, const Sample& a, const Sample& b, int depth);
  void push(const Eigen::Vector2d& st, const Eigen::Vector2d& sag);
  bool same(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

  const NurbsSurface& surface_;
  TrimPolygonOptions options_;
  Eigen::Array2d scale_;
  std::vector<Eigen::Vector2d> vertices_;
  std::vector<Eigen::Vector2d> sags_;  // sags_[i]: sag vector of the edge ending at vertices_[i]
  double worst_sag_ = 0;
  bool met_ = true;
};

// True when `loops` is a single loop running around the domain rectangle
// (a closed periodic face, a face bounded by iso-lines): no trim is needed.
bool is_domain_rectangle(const std::vector<UvLoop>& loops, const ParameterDomain& domain);

}  // namespace furrow
