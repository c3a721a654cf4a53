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
// A curve may also pass through a pole between its ends (a meridian circle
// over the pole, a small circle through it): there the periodic parameter
// jumps by whatever the curve's turn makes it (half a period for a curve
// going straight over), which no continuity rule can choose. pole_passages()
// finds such parameters; the loop is then built from the pieces between
// them (cad_model_space_loop.hpp), each a ProjectedCurve whose ends at the
// passage are declared poles (`start_pole`, `end_pole`) and take the
// parameter of their own piece.
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
  // `start_pole`, `end_pole`: the curve's point at `from` (`to`) is a pole
  // (a passage found by pole_passages()), whatever the projection says.
  ProjectedCurve(Handle(Geom_Curve) curve, Handle(ShapeAnalysis_Surface) surface, double from, double to,
                 const Eigen::Vector2d& periods, bool start_pole = false, bool end_pole = false);

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
  bool start_pole_ = false, end_pole_ = false;  // declared pole ends
};

// Where the curve passes through a pole of the surface strictly between
// `from` and `to` (either order), in running order: the parameters at which
// the periodic parameter's circle through the curve's point is shortest,
// found on 64 samples and refined by golden-section search (at most 200
// steps), kept when that circle is shorter than 1e-6 mm (the point is then
// within 1.6e-7 mm of the axis) and the point is not one of the curve's
// ends (ProjectedCurve flags those itself). `periods` as for ProjectedCurve.
std::vector<double> pole_passages(const Handle(Geom_Curve)& curve, const Handle(ShapeAnalysis_Surface)& surface,
                                  double from, double to, const Eigen::Vector2d& periods);

}  // namespace furrow::cad
