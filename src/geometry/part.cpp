#include "geometry/part.hpp"

namespace furrow {

Face::Face(std::string name, NurbsSurface surface, Trim trim, bool reversed,
           std::string source_type)
    : name_(std::move(name)),
      surface_(std::move(surface)),
      trim_(std::move(trim)),
      reversed_(reversed),
      source_type_(std::move(source_type)),
      derivative_scale_(typical_derivative_scale(surface_)) {}

bool Face::contains(double u, double v) const {
  const ParameterDomain& d = surface_.domain();
  if (!(u >= d.u0 && u <= d.u1 && v >= d.v0 && v <= d.v1)) return false;
  return trim_.contains({u, v});
}

DifferentialGeometry Face::geometry(double u, double v) const {
  return differential_geometry(surface_.evaluate(u, v, 2), reversed_, derivative_scale_);
}

DifferentialGeometry Face::geometry(const SurfaceDerivatives& d) const {
  return differential_geometry(d, reversed_, derivative_scale_);
}

Eigen::AlignedBox3d Part::control_box() const {
  Eigen::AlignedBox3d box;
  for (const Face& f : faces) box.extend(f.surface().control_box());
  return box;
}

std::optional<std::size_t> Part::find_face(const std::string& name) const {
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (faces[i].name() == name) return i;
  return std::nullopt;
}

}  // namespace furrow
