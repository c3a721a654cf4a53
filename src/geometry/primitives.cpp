#include "geometry/primitives.hpp"

#include <cmath>

#include "base/error.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

// Straight segment as a degree-1 curve (used as a profile or an extrusion).
RationalCurve2d make_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  RationalCurve2d c;
  c.degree = 1;
  c.knots = {0, 0, 1, 1};
  c.points = {a, b};
  c.weights = {1, 1};
  return c;
}

// Tensor product of a rational arc (u, in the x-y plane of `frame_u`) and a
// 2-D profile (v): point_ij = r_j * arc_i + z_j * axis, weights multiplied.
// With arc points on the unit circle this is exactly a surface of revolution.
NurbsSurface sweep(const RationalCurve2d& unit_arc, const RationalCurve2d& profile,
                   const Eigen::Vector3d& ex, const Eigen::Vector3d& ey, const Eigen::Vector3d& axis) {
  std::vector<std::vector<Eigen::Vector3d>> net(unit_arc.points.size());
  std::vector<std::vector<double>> weights(unit_arc.points.size());
  for (std::size_t i = 0; i < unit_arc.points.size(); ++i) {
    const Eigen::Vector3d dir = unit_arc.points[i].x() * ex + unit_arc.points[i].y() * ey;
    for (std::size_t j = 0; j < profile.points.size(); ++j) {
      net[i].push_back(profile.points[j].x() * dir + profile.points[j].y() * axis);
      weights[i].push_back(unit_arc.weights[i] * profile.weights[j]);
    }
  }
  return NurbsSurface(unit_arc.degree, profile.degree, unit_arc.knots, profile.knots, net, weights,
                      "primitive");
}

}  // namespace

RationalCurve2d make_circular_arc(double radius, double a0, double a1) {
  const double sweep_angle = a1 - a0;
  if (!(radius > 0) || !(std::fabs(sweep_angle) > 0) || std::fabs(sweep_angle) > 2 * kPi + 1e-12)
    throw InputError("circular arc: need radius > 0 and 0 < |a1 - a0| <= 2 pi");
  const int pieces = static_cast<int>(std::ceil(std::fabs(sweep_angle) / (kPi / 2) - 1e-9));
  const double step = sweep_angle / pieces;
  const double w_mid = std::cos(step / 2);
  RationalCurve2d c;
  c.knots = {0, 0, 0};
  for (int k = 1; k < pieces; ++k) {
    c.knots.push_back(static_cast<double>(k) / pieces);
    c.knots.push_back(static_cast<double>(k) / pieces);
  }
  c.knots.insert(c.knots.end(), {1, 1, 1});
  for (int k = 0; k < pieces; ++k) {
    const double t0 = a0 + k * step;
    const double tm = t0 + step / 2;
    if (k == 0) {
      c.points.emplace_back(radius * std::cos(t0), radius * std::sin(t0));
      c.weights.push_back(1);
    }
    // Middle control point: intersection of the end tangents.
    const double r_mid = radius / w_mid;
    c.points.emplace_back(r_mid * std::cos(tm), r_mid * std::sin(tm));
    c.weights.push_back(w_mid);
    const double t1 = a0 + (k + 1) * step;
    c.points.emplace_back(radius * std::cos(t1), radius * std::sin(t1));
    c.weights.push_back(1);
  }
  return c;
}

NurbsSurface make_revolution(const RationalCurve2d& profile, double phi0, double phi1) {
  return sweep(make_circular_arc(1.0, phi0, phi1), profile, Eigen::Vector3d::UnitX(),
               Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ());
}

NurbsSurface make_cylinder(double radius, double length, double a0, double a1) {
  if (!(length > 0)) throw InputError("cylinder: length must be positive");
  // Revolve about y: the unit arc lives in the x-z plane, the "profile" is the
  // segment r = radius, height y in [0, length].
  return sweep(make_circular_arc(1.0, a0, a1), make_segment({radius, 0.0}, {radius, length}),
               Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
}

NurbsSurface make_sphere(double radius, double phi0, double phi1, double lat0, double lat1) {
  if (!(lat0 >= -kPi / 2 - 1e-12 && lat1 <= kPi / 2 + 1e-12 && lat1 > lat0))
    throw InputError("sphere: latitudes must satisfy -pi/2 <= lat0 < lat1 <= pi/2");
  // Profile: meridian arc, points (cos lat, sin lat) * radius in (r, z).
  return make_revolution(make_circular_arc(radius, lat0, lat1), phi0, phi1);
}

NurbsSurface make_torus(double major, double minor, double phi0, double phi1, double psi0,
                        double psi1) {
  if (!(major > 0 && minor > 0)) throw InputError("torus: radii must be positive");
  RationalCurve2d profile = make_circular_arc(minor, psi0, psi1);
  for (auto& p : profile.points) p.x() += major;
  return make_revolution(profile, phi0, phi1);
}

NurbsSurface make_plane(const Eigen::Vector3d& origin, const Eigen::Vector3d& e_u,
                        const Eigen::Vector3d& e_v) {
  return make_bilinear(origin, origin + e_u, origin + e_v, origin + e_u + e_v);
}

NurbsSurface make_bilinear(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10,
                           const Eigen::Vector3d& p01, const Eigen::Vector3d& p11) {
  return NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{p00, p01}, {p10, p11}}, {}, "primitive");
}

NurbsSurface transformed(const NurbsSurface& s, const Eigen::Isometry3d& motion) {
  std::vector<std::vector<Eigen::Vector3d>> net(s.num_u(), std::vector<Eigen::Vector3d>(s.num_v()));
  std::vector<std::vector<double>> weights(s.num_u(), std::vector<double>(s.num_v()));
  for (int i = 0; i < s.num_u(); ++i)
    for (int j = 0; j < s.num_v(); ++j) {
      net[i][j] = motion * s.control_point(i, j);
      weights[i][j] = s.weight(i, j);
    }
  return NurbsSurface(s.degree_u(), s.degree_v(), s.knots_u(), s.knots_v(), net,
                      s.is_rational() ? weights : std::vector<std::vector<double>>{}, "transformed");
}

}  // namespace furrow
