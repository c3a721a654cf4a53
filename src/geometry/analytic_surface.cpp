// Recognition of elementary surfaces (contract and method in analytic_surface.hpp).
#include "geometry/analytic_surface.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "base/number_text.hpp"
#include "base/numbers.hpp"
#include <vector>

namespace furrow {

const char* to_string(AnalyticSurface::Type type) {
  switch (type) {
    case AnalyticSurface::Type::plane: return "plane";
    case AnalyticSurface::Type::cylinder: return "cylinder";
    case AnalyticSurface::Type::cone: return "cone";
    case AnalyticSurface::Type::sphere: return "sphere";
    case AnalyticSurface::Type::torus: return "torus";
  }
  return "?";
}

std::optional<AnalyticSurface::Type> analytic_type_from_string(const std::string& name) {
  for (const auto t : {AnalyticSurface::Type::plane, AnalyticSurface::Type::cylinder, AnalyticSurface::Type::cone,
                       AnalyticSurface::Type::sphere, AnalyticSurface::Type::torus})
    if (name == to_string(t)) return t;
  return std::nullopt;
}

namespace {

struct Sample {
  Eigen::Vector3d point, normal;
};

// Points (and unit normals where defined) at the cell centres of an n x n grid.
std::vector<Sample> samples(const NurbsSurface& s, int n, bool need_normals) {
  const ParameterDomain& d = s.domain();
  std::vector<Sample> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const SurfaceDerivatives g =
          s.evaluate(d.u0 + d.width_u() * (i + 0.5) / n, d.v0 + d.width_v() * (j + 0.5) / n, 1);
      const Eigen::Vector3d c = g.Su.cross(g.Sv);
      const double scale = g.Su.norm() * g.Sv.norm();
      if (need_normals && !(c.norm() > 1e-9 * scale)) continue;
      out.push_back({g.S, need_normals ? Eigen::Vector3d(c.normalized()) : Eigen::Vector3d::Zero()});
    }
  return out;
}

Eigen::Vector3d canonical(Eigen::Vector3d a) {
  a.normalize();
  Eigen::Index k;
  a.cwiseAbs().maxCoeff(&k);
  return a[k] < 0 ? Eigen::Vector3d(-a) : a;
}

Eigen::Vector3d centroid(const std::vector<Sample>& pts) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Sample& s : pts) c += s.point;
  return c / static_cast<double>(pts.size());
}

// Radius from the axis and height along it.
Eigen::Vector2d radius_height(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d d = p - origin;
  const double h = d.dot(axis);
  return {(d - h * axis).norm(), h};
}

std::optional<AnalyticSurface> fit_plane(const std::vector<Sample>& pts) {
  const Eigen::Vector3d c = centroid(pts);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Sample& s : pts) cov += (s.point - c) * (s.point - c).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  AnalyticSurface a;
  a.type = AnalyticSurface::Type::plane;
  a.origin = c;
  a.axis = canonical(eig.eigenvectors().col(0));
  return a;
}

std::optional<AnalyticSurface> fit_sphere(const std::vector<Sample>& pts) {
  // |x|^2 = 2 c.x + k, linear in (c, k); points relative to their centroid.
  const Eigen::Vector3d c0 = centroid(pts);
  Eigen::MatrixXd A(pts.size(), 4);
  Eigen::VectorXd b(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::Vector3d x = pts[k].point - c0;
    A.row(static_cast<Eigen::Index>(k)) << 2 * x.x(), 2 * x.y(), 2 * x.z(), 1;
    b[static_cast<Eigen::Index>(k)] = x.squaredNorm();
  }
  const Eigen::Vector4d sol = A.colPivHouseholderQr().solve(b);
  const double r2 = sol[3] + sol.head<3>().squaredNorm();
  if (!(r2 > 0)) return std::nullopt;
  AnalyticSurface a;
  a.type = AnalyticSurface::Type::sphere;
  a.origin = c0 + sol.head<3>();
  a.radius = std::sqrt(r2);
  return a;
}

// Circle fit in 2-D (x, y): x^2 + y^2 = 2 a x + 2 b y + c.
std::optional<Eigen::Vector3d> fit_circle(const std::vector<Eigen::Vector2d>& xy) {
  Eigen::MatrixXd A(xy.size(), 3);
  Eigen::VectorXd b(xy.size());
  for (std::size_t k = 0; k < xy.size(); ++k) {
    A.row(static_cast<Eigen::Index>(k)) << 2 * xy[k].x(), 2 * xy[k].y(), 1;
    b[static_cast<Eigen::Index>(k)] = xy[k].squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
  const double r2 = s[2] + s[0] * s[0] + s[1] * s[1];
  if (!(r2 > 0)) return std::nullopt;
  return Eigen::Vector3d(s[0], s[1], std::sqrt(r2));
}

std::optional<AnalyticSurface> fit_cylinder(const std::vector<Sample>& pts) {
  Eigen::Matrix3d nn = Eigen::Matrix3d::Zero();
  for (const Sample& s : pts) nn += s.normal * s.normal.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(nn);
  const Eigen::Vector3d axis = canonical(eig.eigenvectors().col(0));
  const Eigen::Vector3d c = centroid(pts);
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  std::vector<Eigen::Vector2d> xy;
  for (const Sample& s : pts) xy.emplace_back((s.point - c).dot(e1), (s.point - c).dot(e2));
  const std::optional<Eigen::Vector3d> circle = fit_circle(xy);
  if (!circle) return std::nullopt;
  AnalyticSurface a;
  a.type = AnalyticSurface::Type::cylinder;
  a.axis = axis;
  a.origin = c + (*circle)[0] * e1 + (*circle)[1] * e2;
  a.radius = (*circle)[2];
  return a;
}

// The axis of a surface of revolution: every normal line meets it. With
// Plücker coordinates (d, m = x X d) two lines meet when d1.m2 + d2.m1 = 0,
// which is linear in the axis's (m_a, a): the smallest eigenvector of the
// 6 x 6 normal matrix.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> revolution_axis(const std::vector<Sample>& pts) {
  const Eigen::Vector3d c = centroid(pts);
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  for (const Sample& s : pts) {
    Eigen::Matrix<double, 6, 1> row;
    row << s.normal, (s.point - c).cross(s.normal);
    M += row * row.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(M);
  const Eigen::Matrix<double, 6, 1> v = eig.eigenvectors().col(0);
  const Eigen::Vector3d m = v.head<3>(), d = v.tail<3>();
  if (!(d.norm() > 1e-6)) return std::nullopt;
  const Eigen::Vector3d point = c + d.cross(m) / d.squaredNorm();
  return std::make_pair(point, canonical(d));
}

std::optional<AnalyticSurface> fit_cone(const std::vector<Sample>& pts, const Eigen::Vector3d& p0,
                                        const Eigen::Vector3d& axis) {
  // r = alpha + beta h
  Eigen::MatrixXd A(pts.size(), 2);
  Eigen::VectorXd b(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::Vector2d rh = radius_height(pts[k].point, p0, axis);
    A.row(static_cast<Eigen::Index>(k)) << 1, rh.y();
    b[static_cast<Eigen::Index>(k)] = rh.x();
  }
  const Eigen::Vector2d s = A.colPivHouseholderQr().solve(b);
  if (!(std::abs(s[1]) > 1e-9)) return std::nullopt;
  AnalyticSurface a;
  a.type = AnalyticSurface::Type::cone;
  a.axis = axis;
  a.origin = p0 - (s[0] / s[1]) * axis;
  a.half_angle = std::atan(std::abs(s[1]));
  return a;
}

std::optional<AnalyticSurface> fit_torus(const std::vector<Sample>& pts, const Eigen::Vector3d& p0,
                                         const Eigen::Vector3d& axis) {
  std::vector<Eigen::Vector2d> rh;
  for (const Sample& s : pts) rh.push_back(radius_height(s.point, p0, axis));
  const std::optional<Eigen::Vector3d> circle = fit_circle(rh);
  if (!circle || !((*circle)[0] > 0)) return std::nullopt;
  AnalyticSurface a;
  a.type = AnalyticSurface::Type::torus;
  a.axis = axis;
  a.origin = p0 + (*circle)[1] * axis;
  a.radius = (*circle)[0];
  a.minor_radius = (*circle)[2];
  return a;
}

// The candidate with its deviation over the check samples, if within tolerance.
std::optional<AnalyticSurface> accept(std::optional<AnalyticSurface> a, const std::vector<Sample>& check,
                                      double tolerance) {
  if (!a) return std::nullopt;
  double worst = 0;
  for (const Sample& s : check) {
    const double d = analytic_distance(*a, s.point);
    if (!(d <= tolerance)) return std::nullopt;
    worst = std::max(worst, d);
  }
  a->deviation = worst;
  return a;
}

}  // namespace

namespace {
std::string number(double x) { return general(std::abs(x) < 1e-12 ? 0.0 : x, 9); }
std::string vector_text(const Eigen::Vector3d& v) {
  return "(" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + ")";
}
}  // namespace

std::string describe(const AnalyticSurface& s) {
  std::string text = to_string(s.type);
  switch (s.type) {
    case AnalyticSurface::Type::plane: return text + ", normal " + vector_text(s.axis) + " through " + vector_text(s.origin);
    case AnalyticSurface::Type::cylinder: text += ", radius " + number(s.radius) + " mm"; break;
    case AnalyticSurface::Type::sphere: return text + ", radius " + number(s.radius) + " mm, centre " + vector_text(s.origin);
    case AnalyticSurface::Type::cone:
      return text + ", half angle " + number(degrees(s.half_angle)) + " deg, apex " +
             vector_text(s.origin) + ", axis " + vector_text(s.axis);
    case AnalyticSurface::Type::torus:
      text += ", radii " + number(s.radius) + " and " + number(s.minor_radius) + " mm";
      break;
  }
  return text + ", axis " + vector_text(s.axis) + " through " + vector_text(s.origin);
}

double analytic_distance(const AnalyticSurface& s, const Eigen::Vector3d& p) {
  switch (s.type) {
    case AnalyticSurface::Type::plane: return std::abs((p - s.origin).dot(s.axis));
    case AnalyticSurface::Type::sphere: return std::abs((p - s.origin).norm() - s.radius);
    case AnalyticSurface::Type::cylinder: return std::abs(radius_height(p, s.origin, s.axis).x() - s.radius);
    case AnalyticSurface::Type::cone: {
      // In the meridian half-plane the cone is two rays from the apex at
      // +-half_angle from the axis; the distance is to the nearer ray.
      const Eigen::Vector2d rh = radius_height(p, s.origin, s.axis);
      const Eigen::Vector2d p2(rh.x(), rh.y());
      double best = p2.norm();
      for (const double sign : {1.0, -1.0}) {
        const Eigen::Vector2d ray(std::sin(s.half_angle), sign * std::cos(s.half_angle));
        const double t = p2.dot(ray);
        if (t > 0) best = std::min(best, (p2 - t * ray).norm());
      }
      return best;
    }
    case AnalyticSurface::Type::torus: {
      const Eigen::Vector2d rh = radius_height(p, s.origin, s.axis);
      return std::abs(std::hypot(rh.x() - s.radius, rh.y()) - s.minor_radius);
    }
  }
  return INFINITY;
}

std::optional<AnalyticSurface> recognise_analytic(const NurbsSurface& surface, double tolerance) {
  const std::vector<Sample> fit = samples(surface, kAnalyticFitGrid, true);
  if (fit.size() < static_cast<std::size_t>(kAnalyticFitGrid * kAnalyticFitGrid / 2)) return std::nullopt;
  const std::vector<Sample> check = samples(surface, kAnalyticCheckGrid, false);
  if (auto a = accept(fit_plane(fit), check, tolerance)) return a;
  if (auto a = accept(fit_sphere(fit), check, tolerance)) return a;
  if (auto a = accept(fit_cylinder(fit), check, tolerance)) return a;
  if (const auto axis = revolution_axis(fit)) {
    if (auto a = accept(fit_cone(fit, axis->first, axis->second), check, tolerance)) return a;
    if (auto a = accept(fit_torus(fit, axis->first, axis->second), check, tolerance)) return a;
  }
  return std::nullopt;
}

}  // namespace furrow
