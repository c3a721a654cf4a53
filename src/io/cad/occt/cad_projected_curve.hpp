#pragma once
// A boundary edge's curve in a periodic surface's parameters, found from its
// 3-D curve alone (docs/formats.md "CAD import", "IGES boundaries").
//
// Why: an IGES boundary given only in model space (type 142 without a
// parameter-space curve) gets its pcurves from OpenCASCADE's projection,
// which on a periodic surface may land each piece in another period or run
// the pole edges round the wrong side; the importer then builds the loop
// itself (cad_model_space_loop.hpp) from these curves.
//
// uv(t) projects the curve's point at t onto the surface (ShapeAnalysis_Surface,
// exact for elementary surfaces) and puts each periodic parameter in the
// period that keeps the curve continuous: nearest to a reference polyline of
// samples taken along the whole edge when it was built. Where the point is
// a pole of the surface (the periodic parameter's circle shrinks to a point,
// below 1e-7 mm long) that parameter is undefined and the reference gives it,
// so a meridian reaching a pole keeps its longitude up to the pole.
//
// Units: parameters as the surface has them; `t` the curve's own parameter.
// Never fails: a curve all of whose samples are poles is flagged `collapsed`.
#include <Geom_Curve.hxx>
#include <ShapeAnalysis_Surface.hxx>

#include <Eigen/Core>
#include <vector>

namespace furrow::cad {

class ProjectedCurve {
 public:
  // `periods`: the surface's period along u and v, 0 where not periodic.
  // The curve runs from `from` to `to` (either order).
  ProjectedCurve(Handle(Geom_Curve) curve, Handle(ShapeAnalysis_Surface) surface, double from, double to,
                 const Eigen::Vector2d& periods);

  Eigen::Vector2d uv(double t) const;
  const Eigen::Vector2d& start() const { return samples_.front().uv; }
  const Eigen::Vector2d& end() const { return samples_.back().uv; }
  bool starts_at_pole() const { return samples_.front().pole; }
  bool ends_at_pole() const { return samples_.back().pole; }
  bool collapsed() const { return collapsed_; }
  // Box of the curve's (u,v) from dense samples: {u0, v0, u1, v1}.
  Eigen::Vector4d box() const;

 private:
  struct Sample {
    double t;
    Eigen::Vector2d uv;
    bool pole;
  };
  // The surface's (u,v) of the curve point at t in the surface's own period,
  // and whether it is a pole.
  Eigen::Vector2d raw(double t, bool& pole) const;
  Eigen::Vector2d reference(double t) const;

  Handle(Geom_Curve) curve_;
  Handle(ShapeAnalysis_Surface) surface_;
  Eigen::Vector2d periods_;
  std::vector<Sample> samples_;  // in running order, unwrapped
  bool collapsed_ = false;
};

}  // namespace furrow::cad
