#include "inspection/observability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace furrow {

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// H and G of the header in coordinates centred on the points' centroid c,
// rotations scaled by their RMS distance L from it: q = (L w, t + w x c).
// Only for conditioning: the generalised eigenvalues do not depend on it.
struct PointMetric {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double lever = 1;
  std::size_t count = 0;
  Matrix6 H = Matrix6::Zero(), G = Matrix6::Zero();
  std::vector<Eigen::Vector3d> x;

  PointMetric(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals) : x(points) {
    count = points.size();
    if (count == 0) return;
    for (const Eigen::Vector3d& p : points) centre += p;
    centre /= static_cast<double>(count);
    double s = 0;
    for (const Eigen::Vector3d& p : points) s += (p - centre).squaredNorm();
    lever = std::sqrt(s / static_cast<double>(count));
    // Identical points spread by rounding only: any positive scale serves.
    if (!(lever > 1e-9 * (1 + centre.norm()))) lever = 1;
    for (std::size_t i = 0; i < count; ++i) {
      const Eigen::Vector3d r = (points[i] - centre) / lever;
      Vector6 j;
      j << r.cross(normals[i]), normals[i];
      H += j * j.transpose();
      Eigen::Matrix<double, 3, 6> d;
      d << -skew(r), Eigen::Matrix3d::Identity();
      G += d.transpose() * d;
    }
  }
  // Origin parameters (w, t) -> scaled centred coordinates q.
  Matrix6 to_scaled() const {
    Matrix6 m = Matrix6::Zero();
    m.topLeftCorner<3, 3>() = lever * Eigen::Matrix3d::Identity();
    m.bottomLeftCorner<3, 3>() = -skew(centre);
    m.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity();
    return m;
  }
  Vector6 to_origin(const Vector6& q) const {
    const Eigen::Vector3d w = q.head<3>() / lever;
    Vector6 p;
    p << w, q.tail<3>() - w.cross(centre);
    return p;
  }
};

struct Spectrum {
  Eigen::VectorXd values;   // ascending
  Eigen::MatrixXd vectors;  // columns: motions in the coordinates of the basis, G-orthonormal
};

// H v = lambda G v over the motions `basis_scaled` (columns, scaled
// coordinates of `m`). Motions that move no point at all (G null: a turn
// about the line of collinear points, any turn about identical points)
// come first with lambda = 0 and unit length; the rest is solved on the
// subspace where G is positive definite, so no regularisation can invent a
// share for a motion that has no displacement.
Spectrum generalised(const Eigen::MatrixXd& basis_scaled, const PointMetric& m) {
  const Eigen::Index k = basis_scaled.cols();
  Spectrum out{Eigen::VectorXd::Zero(k), Eigen::MatrixXd::Zero(k, k)};
  if (k == 0) return out;
  // An orthonormal basis of the same motions first (the eigenvalues do not
  // depend on the basis): the allowed columns of a part far from the origin
  // are badly conditioned, its orthonormal basis is not.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(basis_scaled);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(basis_scaled.rows(), k);
  const Eigen::MatrixXd r = q.transpose() * basis_scaled;
  const Eigen::MatrixXd h = q.transpose() * m.H * q;
  const Eigen::MatrixXd g = q.transpose() * m.G * q;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eg(g);  // ascending
  const double top = eg.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::Index null = 0;
  while (null < k && !(eg.eigenvalues()(null) > 1e-10 * top)) ++null;
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(k, k);
  for (Eigen::Index c = 0; c < null; ++c) y.col(c) = eg.eigenvectors().col(c);
  if (null < k) {
    // Whitened on the rest: z = D^1/2 U^T y.
    const Eigen::MatrixXd u = eg.eigenvectors().rightCols(k - null);
    const Eigen::VectorXd inv_sqrt = eg.eigenvalues().tail(k - null).cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd w = u * inv_sqrt.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(w.transpose() * h * w);
    out.values.tail(k - null) = es.eigenvalues().cwiseMax(0.0);
    y.rightCols(k - null) = w * es.eigenvectors();
  }
  // Back to the coordinates of the given basis: basis_scaled = q r.
  out.vectors = r.triangularView<Eigen::Upper>().solve(y);
  return out;
}

// The flip that makes a unit vector's largest component positive, so that
// the same direction is always written the same way.
double canonical_sign(const Eigen::Vector3d& v) {
  Eigen::Index k = 0;
  v.cwiseAbs().maxCoeff(&k);
  return v(k) < 0 ? -1.0 : 1.0;
}

// Describes the motions spanned by `weak` (columns, scaled coordinates of
// `m`): pure translations first, then rotations (each the screw about an
// axis, nearest the centroid), normalised to 1 mm RMS displacement.
std::vector<WeakDirection> canonical_directions(const Eigen::MatrixXd& weak, const PointMetric& m,
                                                double largest, bool from_points) {
  std::vector<WeakDirection> out;
  if (weak.cols() == 0) return out;
  // G-orthonormal columns first.
  Eigen::MatrixXd gq = weak.transpose() * m.G * weak;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eg(gq);
  const double floor = 1e-12 * std::max(1.0, eg.eigenvalues().cwiseAbs().maxCoeff());
  Eigen::MatrixXd q = weak * eg.eigenvectors();
  for (Eigen::Index k = 0; k < q.cols(); ++k) {
    const double s = eg.eigenvalues()(k);
    q.col(k) /= s > floor ? std::sqrt(s) : q.col(k).norm();
  }
  // Combinations without rotation are translations.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(q.topRows(3), Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  // A combination whose rotation moves the points by less than about 5 % of
  // its displacement reads as a translation (a nearly flat face slides).
  const double rotation_floor = 0.05 / std::sqrt(static_cast<double>(std::max<std::size_t>(1, m.count)));
  const Eigen::MatrixXd combos = q * svd.matrixV();
  std::vector<Eigen::Index> order;
  for (Eigen::Index k = combos.cols() - 1; k >= 0; --k) order.push_back(k);  // zero singular values last in V
  const double rms_scale = std::sqrt(static_cast<double>(std::max<std::size_t>(1, m.count)));
  for (Eigen::Index k : order) {
    const bool translation = k >= sv.size() || sv(k) <= rotation_floor;
    Vector6 s = combos.col(k) * rms_scale;  // 1 mm RMS displacement
    if (translation) s.head<3>().setZero();
    WeakDirection d;
    d.translation = translation;
    d.from_points = from_points;
    // A motion that moves no point (a turn about the line of collinear
    // points) is not seen at all: ratio and information 0, not 0/0.
    const double g = s.dot(m.G * s);
    const double h = std::max(0.0, s.dot(m.H * s));
    const bool moves = g > 1e-9 * static_cast<double>(std::max<std::size_t>(1, m.count));
    d.information = moves ? h : 0.0;
    d.ratio = moves && largest > 0 ? std::min(1.0, (h / g) / largest) : 0.0;
    const Eigen::Vector3d t_c = s.tail<3>();
    if (translation) {
      const double len = t_c.norm();
      d.direction = len > 0 ? Eigen::Vector3d(t_c / len) : Eigen::Vector3d::UnitX();
      const double sign = canonical_sign(d.direction);
      d.direction *= sign;
      s *= sign;
      d.axis_point = m.centre;
    } else {
      const Eigen::Vector3d w = s.head<3>() / m.lever;
      const double ww = w.squaredNorm();
      const double sign = canonical_sign(w);
      s *= sign;
      d.direction = sign * w / std::sqrt(ww);
      d.pitch = w.dot(t_c) / ww;  // invariant under the flip
      d.axis_point = m.centre + w.cross(t_c) / ww;
      double lever2 = 0;
      for (const Eigen::Vector3d& p : m.x) lever2 += d.direction.cross(p - d.axis_point).squaredNorm();
      d.lever = std::sqrt(lever2 / static_cast<double>(std::max<std::size_t>(1, m.count)));
    }
    d.parameters = m.to_origin(s);
    out.push_back(d);
  }
  return out;
}

std::string vec(const Eigen::Vector3d& v, int digits) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.*f, %.*f, %.*f)", digits, v.x() == 0 ? 0.0 : v.x(), digits,
                v.y() == 0 ? 0.0 : v.y(), digits, v.z() == 0 ? 0.0 : v.z());
  std::string s = buf;
  // "-0.00" reads as a sign that means nothing.
  for (std::size_t at; (at = s.find("-0.")) != std::string::npos &&
                       s.find_first_not_of("0.", at + 1) == s.find_first_of(",)", at + 1);)
    s.erase(at, 1);
  return s;
}

}  // namespace

std::string WeakDirection::describe() const {
  if (translation) return "translation along " + vec(direction, 2);
  std::string s = "rotation about the axis through " + vec(axis_point, 3) + " mm along " + vec(direction, 2);
  if (std::abs(pitch) > 1e-4) {  // below: round-off of a plain rotation
    char buf[64];
    std::snprintf(buf, sizeof buf, ", advancing %.4g mm per radian", pitch);
    s += buf;
  }
  return s;
}

double WeakDirection::sigma_mm(double sigma) const {
  if (!(information > 0) || !(ratio >= kUnseenRatio)) return std::numeric_limits<double>::infinity();
  return sigma / std::sqrt(information);
}

MotionBasis free_parameter_basis(const std::array<bool, 6>& free) {
  MotionBasis b(6, std::count(free.begin(), free.end(), true));
  b.setZero();
  Eigen::Index c = 0;
  for (int k = 0; k < 6; ++k)
    if (free[k]) b(k, c++) = 1;
  return b;
}

Observability analyse_observability(const std::vector<Eigen::Vector3d>& x,
                                    const std::vector<Eigen::Vector3d>& n, const MotionBasis& allowed,
                                    double weak_ratio) {
  Observability o;
  o.weak_ratio = weak_ratio;
  o.allowed = allowed;
  o.constrained = MotionBasis(6, 0);
  if (allowed.cols() == 0) return o;
  const PointMetric m(x, n);
  const Eigen::MatrixXd scaled = m.to_scaled() * allowed;
  const Spectrum sp = generalised(scaled, m);
  const double largest = sp.values.size() > 0 ? sp.values.maxCoeff() : 0.0;
  std::vector<Eigen::Index> weak, strong;
  for (Eigen::Index k = 0; k < sp.values.size(); ++k) {
    const double ratio = largest > 0 ? sp.values(k) / largest : 0.0;
    o.ratios.push_back(ratio);
    (largest > 0 && ratio >= weak_ratio ? strong : weak).push_back(k);
  }
  o.constrained = MotionBasis(6, static_cast<Eigen::Index>(strong.size()));
  for (std::size_t c = 0; c < strong.size(); ++c) {
    const Vector6 p = allowed * sp.vectors.col(strong[c]);
    o.constrained.col(static_cast<Eigen::Index>(c)) = p / p.norm();
  }
  Eigen::MatrixXd w(6, static_cast<Eigen::Index>(weak.size()));
  for (std::size_t c = 0; c < weak.size(); ++c) w.col(static_cast<Eigen::Index>(c)) = scaled * sp.vectors.col(weak[c]);
  o.weak = canonical_directions(w, m, largest, false);
  std::stable_sort(o.weak.begin(), o.weak.end(),
                   [](const WeakDirection& a, const WeakDirection& b) { return a.ratio < b.ratio; });
  return o;
}

void mark_weak_by_points(Observability& points, const std::vector<Eigen::Vector3d>& point_x,
                         const std::vector<Eigen::Vector3d>& point_n, const std::vector<Eigen::Vector3d>& surface_x,
                         const std::vector<Eigen::Vector3d>& surface_n) {
  if (points.weak.empty() || surface_x.empty()) return;
  const PointMetric surface(surface_x, surface_n);
  const Spectrum all = generalised(surface.to_scaled() * points.allowed, surface);
  const double surface_largest = all.values.size() > 0 ? all.values.maxCoeff() : 0.0;
  if (!(surface_largest > 0)) return;
  // The weak subspace in the surface's coordinates, split by what the
  // surface sees of it.
  Eigen::MatrixXd w(6, static_cast<Eigen::Index>(points.weak.size()));
  for (std::size_t c = 0; c < points.weak.size(); ++c)
    w.col(static_cast<Eigen::Index>(c)) = surface.to_scaled() * points.weak[c].parameters;
  const Spectrum within = generalised(w, surface);
  const PointMetric measured(point_x, point_n);
  const Eigen::MatrixXd to_measured = measured.to_scaled();
  Eigen::MatrixXd of_surface(6, 0), of_points(6, 0);
  for (Eigen::Index k = 0; k < within.values.size(); ++k) {
    Eigen::MatrixXd& to = within.values(k) / surface_largest >= points.weak_ratio ? of_points : of_surface;
    to.conservativeResize(6, to.cols() + 1);
    to.col(to.cols() - 1) = to_measured * surface.to_origin(w * within.vectors.col(k));
  }
  if (of_points.cols() == 0) return;
  // Described again over the measured points, each kind on its own.
  const Spectrum sp = generalised(to_measured * points.allowed, measured);
  const double largest = sp.values.size() > 0 ? sp.values.maxCoeff() : 0.0;
  std::vector<WeakDirection> weak = canonical_directions(of_surface, measured, largest, false);
  for (WeakDirection& d : canonical_directions(of_points, measured, largest, true)) weak.push_back(d);
  points.weak = std::move(weak);
}

}  // namespace furrow
