#include "io/cad/cad_parameter_map.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

namespace {

// Fractions of the rectangle tried for the reference lines, centre first.
constexpr double kReferenceFractions[] = {0.5, 0.37, 0.63, 0.21, 0.79, 0.09, 0.91};
// Grid of the initial scan for the reference point.
constexpr int kReferenceScan = 17;

double lerp(double a, double b, double f) { return a + f * (b - a); }

}  // namespace

ParameterMap::ParameterMap(const NurbsSurface& nurbs, Evaluator original,
                           const ParameterDomain& bounds, const ParameterMapOptions& options)
    : nurbs_(&nurbs), original_(std::move(original)), bounds_(bounds), options_(options) {
  choose_reference();
  seed(true);
  seed(false);
}

// Picks (u_ref, v_ref) where neither direction of the original collapses (not
// on a pole or apex line), then finds its (s_ref, t_ref) by a coarse scan of
// the NURBS and damped Gauss-Newton.
void ParameterMap::choose_reference() {
  const double hu = 1e-4 * bounds_.width_u(), hv = 1e-4 * bounds_.width_v();
  double best_quality = -1;
  for (double fu : kReferenceFractions) {
    for (double fv : kReferenceFractions) {
      const double u = lerp(bounds_.u0, bounds_.u1, fu), v = lerp(bounds_.v0, bounds_.v1, fv);
      const double du = (original_(u + hu, v) - original_(u - hu, v)).norm();
      const double dv = (original_(u, v + hv) - original_(u, v - hv)).norm();
      const double quality = std::min(du, dv) / std::max({du, dv, 1e-300});
      if (quality > best_quality) {
        best_quality = quality;
        u_ref_ = u;
        v_ref_ = v;
      }
      if (quality > 1e-3) break;
    }
    if (best_quality > 1e-3) break;
  }

  const Eigen::Vector3d target = original_(u_ref_, v_ref_);
  const ParameterDomain& d = nurbs_->domain();
  Eigen::Vector2d x(d.u0, d.v0);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kReferenceScan; ++i)
    for (int j = 0; j < kReferenceScan; ++j) {
      const Eigen::Vector2d c(lerp(d.u0, d.u1, (i + 0.5) / kReferenceScan),
                              lerp(d.v0, d.v1, (j + 0.5) / kReferenceScan));
      const double dist = (nurbs_->point(c.x(), c.y()) - target).squaredNorm();
      if (dist < best) {
        best = dist;
        x = c;
      }
    }
  // Levenberg-Marquardt on |N(s,t) - target|^2, clamped to the domain.
  double lambda = 1e-3;
  SurfaceDerivatives e = nurbs_->evaluate(x.x(), x.y(), 1);
  double residual = (e.S - target).norm();
  for (int it = 0; it < options_.max_iterations && residual > 1e-3 * options_.tolerance; ++it) {
    Eigen::Matrix<double, 3, 2> J;
    J << e.Su, e.Sv;
    Eigen::Matrix2d A = J.transpose() * J;
    A.diagonal() *= 1 + lambda;
    const Eigen::Vector2d step = A.ldlt().solve(-J.transpose() * (e.S - target));
    const Eigen::Vector2d next(std::clamp(x.x() + step.x(), d.u0, d.u1),
                               std::clamp(x.y() + step.y(), d.v0, d.v1));
    const SurfaceDerivatives trial = nurbs_->evaluate(next.x(), next.y(), 1);
    const double trial_residual = (trial.S - target).norm();
    if (trial_residual < residual) {
      const bool stalled = (next - x).norm() <= 1e-15 * (d.width_u() + d.width_v());
      x = next;
      e = trial;
      residual = trial_residual;
      lambda = std::max(lambda * 0.1, 1e-12);
      if (stalled) break;
    } else {
      lambda *= 10;
      if (lambda > 1e12) break;
    }
  }
  s_ref_ = x.x();
  t_ref_ = x.y();
  worst_residual_ = std::max(worst_residual_, residual);
  if (!(residual <= options_.tolerance)) ++failures_;
}

// Known pairs at the reference and at both ends of the rectangle. Whether the
// conversion runs the direction forwards or backwards is read from the
// tangents at the reference point (at a full period the two ends are the same
// point, so the ends alone cannot tell).
void ParameterMap::seed(bool along_u) {
  Line& line = along_u ? u_line_ : v_line_;
  const double x_ref = along_u ? u_ref_ : v_ref_, p_ref = along_u ? s_ref_ : t_ref_;
  line.known[x_ref] = p_ref;

  const double x0 = along_u ? bounds_.u0 : bounds_.v0, x1 = along_u ? bounds_.u1 : bounds_.v1;
  const double h = 1e-4 * (x1 - x0);
  const Eigen::Vector3d forward = along_u ? original_(u_ref_ + h, v_ref_) - original_(u_ref_ - h, v_ref_)
                                          : original_(u_ref_, v_ref_ + h) - original_(u_ref_, v_ref_ - h);
  Eigen::Vector3d tangent;
  line_point(along_u, p_ref, &tangent);
  const bool increasing = forward.dot(tangent) >= 0;
  const ParameterDomain& d = nurbs_->domain();
  const double p0 = along_u ? d.u0 : d.v0, p1 = along_u ? d.u1 : d.v1;
  const double ends[2][2] = {{x0, increasing ? p0 : p1}, {x1, increasing ? p1 : p0}};
  for (const auto& end : ends) {
    const Eigen::Vector3d target = along_u ? original_(end[0], v_ref_) : original_(u_ref_, end[0]);
    if ((line_point(along_u, end[1], nullptr) - target).norm() <= options_.tolerance)
      line.known[end[0]] = end[1];
  }
}

Eigen::Vector3d ParameterMap::line_point(bool along_u, double p, Eigen::Vector3d* tangent) const {
  const SurfaceDerivatives e =
      along_u ? nurbs_->evaluate(p, t_ref_, tangent ? 1 : 0) : nurbs_->evaluate(s_ref_, p, tangent ? 1 : 0);
  if (tangent) *tangent = along_u ? e.Su : e.Sv;
  return e.S;
}

// Gauss-Newton along one reference line: minimises |C(p) - target|^2 with
// C(p) = N(p, t_ref) or N(s_ref, p), clamped to the domain.
double ParameterMap::newton(bool along_u, const Eigen::Vector3d& target, double start,
                            double* residual) const {
  const ParameterDomain& d = nurbs_->domain();
  const double lo = along_u ? d.u0 : d.v0, hi = along_u ? d.u1 : d.v1;
  double p = std::clamp(start, lo, hi);
  Eigen::Vector3d tangent;
  Eigen::Vector3d c = line_point(along_u, p, &tangent);
  for (int it = 0; it < options_.max_iterations; ++it) {
    const Eigen::Vector3d r = c - target;
    const double tt = tangent.squaredNorm();
    if (r.norm() <= 1e-3 * options_.tolerance || !(tt > 0)) break;
    const double next = std::clamp(p - r.dot(tangent) / tt, lo, hi);
    if (std::abs(next - p) <= 1e-15 * (hi - lo)) break;
    p = next;
    c = line_point(along_u, p, &tangent);
  }
  *residual = (c - target).norm();
  return p;
}

double ParameterMap::solve(bool along_u, double x) {
  std::map<double, double>& known = (along_u ? u_line_ : v_line_).known;
  const auto above = known.lower_bound(x);
  if (above != known.end() && above->first == x) return above->second;
  double start;
  if (above == known.end()) {
    start = std::prev(above)->second;
  } else if (above == known.begin()) {
    start = above->second;
  } else {
    const auto below = std::prev(above);
    start = lerp(below->second, above->second, (x - below->first) / (above->first - below->first));
  }

  const Eigen::Vector3d target = along_u ? original_(x, v_ref_) : original_(u_ref_, x);
  double residual = 0;
  double p = newton(along_u, target, start, &residual);
  if (!(residual <= options_.tolerance)) {
    // Restart from the closest of evenly spaced points; ties go to the one
    // nearest the interpolated start, so a periodic twin is not preferred.
    const ParameterDomain& d = nurbs_->domain();
    const double lo = along_u ? d.u0 : d.v0, hi = along_u ? d.u1 : d.v1;
    double best_start = start, best = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= options_.scan_samples; ++k) {
      const double q = lerp(lo, hi, static_cast<double>(k) / std::max(options_.scan_samples, 1));
      const double dist = (line_point(along_u, q, nullptr) - target).norm();
      if (dist < best * (1 - 1e-12) ||
          (dist <= best * (1 + 1e-12) && std::abs(q - start) < std::abs(best_start - start))) {
        best = dist;
        best_start = q;
      }
    }
    double retry_residual = 0;
    const double retry = newton(along_u, target, best_start, &retry_residual);
    if (retry_residual < residual) {
      p = retry;
      residual = retry_residual;
    }
  }
  worst_residual_ = std::max(worst_residual_, residual);
  if (!(residual <= options_.tolerance)) ++failures_;
  known.emplace_hint(above, x, p);
  return p;
}

Eigen::Vector2d ParameterMap::operator()(double u, double v) {
  if (is_identity()) return {u, v};
  return {solve(true, u), solve(false, v)};
}

double max_deviation(const NurbsSurface& nurbs, ParameterMap& map,
                     const ParameterMap::Evaluator& original, const ParameterDomain& bounds,
                     int n) {
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double u = lerp(bounds.u0, bounds.u1, static_cast<double>(i) / (n - 1));
      const double v = lerp(bounds.v0, bounds.v1, static_cast<double>(j) / (n - 1));
      const Eigen::Vector2d st = map(u, v);
      worst = std::max(worst, (nurbs.point(st.x(), st.y()) - original(u, v)).norm());
    }
  }
  return worst;
}

}  // namespace furrow
