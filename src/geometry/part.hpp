#pragma once
// A part: the free-form faces to inspect, each a NURBS patch with an optional
// trim and an orientation flag. Everything is in millimetres.
//
// Face::normal-related calls honour `reversed`, so the normal always points
// out of the material (docs/architecture.md); code should go through Face rather than the
// bare surface whenever orientation matters.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "geometry/analytic_surface.hpp"
#include "geometry/differential_geometry.hpp"
#include "geometry/nurbs_surface.hpp"
#include "geometry/trim.hpp"

namespace furrow {

class Face {
 public:
  Face(std::string name, NurbsSurface surface, Trim trim = {}, bool reversed = false,
       std::string source_type = {});

  const std::string& name() const { return name_; }
  const NurbsSurface& surface() const { return surface_; }
  const Trim& trim() const { return trim_; }
  bool reversed() const { return reversed_; }
  // Original surface type when imported from CAD ("plane", "b-spline", ...);
  // empty for native JSON faces.
  const std::string& source_type() const { return source_type_; }
  const ParameterDomain& domain() const { return surface_.domain(); }
  // The elementary surface the patch exactly is, when known (recognised at
  // CAD import or given in the part file): metadata for people and reports;
  // geometry always comes from the NURBS (analytic_surface.hpp).
  const std::optional<AnalyticSurface>& analytic() const { return analytic_; }
  void set_analytic(std::optional<AnalyticSurface> analytic) { analytic_ = std::move(analytic); }
  // Whether the side of the material was established by topology at CAD
  // import: the face bounds a solid of the file or a shell that sewed closed
  // (docs/formats.md "Orientation"). Then a face whose normals point down is
  // an underside, not a face turned into the material. False where nothing
  // established it: an open shell (oriented by a rule or left as the file
  // had it), a face no sewing joined, a native face whose file does not say.
  bool orientation_established() const { return orientation_established_; }
  void set_orientation_established(bool established) { orientation_established_ = established; }

  // Inside the parameter rectangle and kept by the trim.
  bool contains(double u, double v) const;

  DifferentialGeometry geometry(double u, double v) const;
  DifferentialGeometry geometry(const SurfaceDerivatives& d) const;

 private:
  std::string name_;
  NurbsSurface surface_;
  Trim trim_;
  bool reversed_ = false;
  std::string source_type_;
  std::optional<AnalyticSurface> analytic_;
  bool orientation_established_ = false;
  double derivative_scale_ = 1;
};

struct Part {
  std::vector<Face> faces;
  // Units the part file was written in ("mm" or "inch"); geometry is always mm.
  std::string source_units = "mm";

  // Box of all control nets (contains every face).
  Eigen::AlignedBox3d control_box() const;
  // Index of the face with that name, or nullopt.
  std::optional<std::size_t> find_face(const std::string& name) const;
};

}  // namespace furrow
