#include "geometry/local_foot_point.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace furrow {

namespace {

// Point, first and second derivatives of a surface restricted to N parameters
// (the box solve uses N = 2: (u,v); the segment solve N = 1: t).
template <int N>
struct Jet {
  Eigen::Vector3d S;
  Eigen::Matrix<double, 3, N> J;
  Eigen::Matrix<double, 3, N * N> D2;  // column i*N + j = d2S / dxi dxj
};

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
template <int N>
using Mat = Eigen::Matrix<double, N, N>;

// Smallest eigenvalue of a symmetric N x N matrix and its unit eigenvector.
template <int N>
std::pair<double, Vec<N>> lowest_eigen(const Mat<N>& m) {
  if constexpr (N == 1) {
    return {m(0, 0), Vec<N>::Ones()};
  } else {
    Eigen::SelfAdjointEigenSolver<Mat<N>> es;
    es.computeDirect(m);
    return {es.eigenvalues()(0), es.eigenvectors().col(0)};
  }
}

// The smallest eigenvalue alone, in closed form: the common case (a positive
// definite Hessian) needs nothing else.
template <int N>
double lowest_eigenvalue(const Mat<N>& m) {
  if constexpr (N == 1) {
    return m(0, 0);
  } else {
    const double half_trace = 0.5 * (m(0, 0) + m(1, 1)), half_gap = 0.5 * (m(0, 0) - m(1, 1));
    return half_trace - std::sqrt(half_gap * half_gap + m(0, 1) * m(0, 1));
  }
}

// Newton direction on the free parameters (zero on the held ones, which are
// masked out with a unit row and column). Uses the full Hessian where it is
// positive definite, the shifted Hessian where it is indefinite and
// Gauss-Newton where it is semi-definite; when that direction is negligible
// although the Hessian has negative curvature (q sits on a maximum or saddle
// of the distance, e.g. opposite a concave wall), it returns the
// negative-curvature direction instead, so the solve leaves it.
template <int N>
Vec<N> descent_direction(Mat<N> H, Mat<N> JtJ, Vec<N> g, const std::array<bool, N>& free,
                         const Vec<N>& box_size, const Eigen::Matrix<double, 3, N>& J,
                         double step_tolerance, bool& negative_curvature) {
  negative_curvature = false;
  const double scale = JtJ.trace();
  if (!(scale > 0)) return Vec<N>::Zero();  // collapsed to a point: nothing to move
  for (int i = 0; i < N; ++i) {
    if (free[i]) continue;
    H.row(i).setZero();
    H.col(i).setZero();
    JtJ.row(i).setZero();
    JtJ.col(i).setZero();
    H(i, i) = JtJ(i, i) = scale;
    g(i) = 0;
  }
  if (lowest_eigenvalue<N>(H) > 1e-10 * scale) return H.inverse() * (-g);  // closed form for N <= 2
  const auto [lambda_min, lowest] = lowest_eigen<N>(H);
  // Not positive definite (q beyond a centre of curvature): shift the
  // Hessian until its lowest eigenvalue is 1e-3 of the scale (Hessian
  // modification, Nocedal & Wright 3.4). Gauss-Newton would ignore the
  // curvature term r . S'' that dominates here and crawl in steps of
  // micrometres along an almost flat valley until the iteration cap.
  Mat<N> M = lambda_min < 0 ? Mat<N>(H + (1e-3 * scale - lambda_min) * Mat<N>::Identity())
                            : Mat<N>(JtJ + 1e-12 * scale * Mat<N>::Identity());
  Vec<N> step = M.inverse() * (-g);
  for (int i = 0; i < N; ++i)
    if (!free[i]) step(i) = 0;
  if ((J * step).norm() <= 10 * step_tolerance && lambda_min < -1e-10 * scale) {
    Vec<N> dir = lowest;
    if (dir.dot(g) > 0) dir = -dir;
    // A quarter of the box along that direction; the line search shortens it.
    const double reach = dir.cwiseAbs().cwiseQuotient(box_size).maxCoeff();
    if (reach > 0) {
      step = 0.25 * dir / reach;
      negative_curvature = true;
    }
  }
  return step;
}

// Length of the residual's projection on the free tangent directions [mm]:
// zero at a stationary point (parameters held at a bound are left out).
template <int N>
double tangential_residual(const Eigen::Matrix<double, 3, N>& J, const Eigen::Vector3d& r,
                           const Vec<N>& x, const Vec<N>& lo, const Vec<N>& hi) {
  double sum = 0;
  for (int i = 0; i < N; ++i) {
    const double len = J.col(i).norm();
    if (!(len > 0)) continue;
    const double gi = J.col(i).dot(r) / len;
    if ((x(i) <= lo(i) && gi > 0) || (x(i) >= hi(i) && gi < 0)) continue;
    sum += gi * gi;
  }
  return std::sqrt(sum);
}

// Projected Newton with active set and Armijo backtracking on
// phi = |S(x) - q|^2 / 2 over lo <= x <= hi. Returns the final parameters;
// fills everything but `uv` of `out`.
template <int N, class Evaluate, class PointAt>
Vec<N> projected_newton(const Evaluate& evaluate, const PointAt& point_at, const Eigen::Vector3d& q,
                        Vec<N> x, const Vec<N>& lo, const Vec<N>& hi,
                        const ClosestPointOptions& opt, LocalFoot& out) {
  x = x.cwiseMax(lo).cwiseMin(hi);
  Jet<N> jet = evaluate(x);
  Eigen::Vector3d r = jet.S - q;
  double phi = 0.5 * r.squaredNorm();
  const Vec<N> box_size = (hi - lo).cwiseMax(Vec<N>::Constant(1e-300));
  out.converged = false;
  out.iterations = 0;
  for (int it = 1; it <= opt.max_newton_iterations; ++it) {
    out.iterations = it;
    const Vec<N> g = jet.J.transpose() * r;
    const Mat<N> JtJ = jet.J.transpose() * jet.J;
    Mat<N> H = JtJ;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) H(i, j) += r.dot(jet.D2.col(i * N + j));
    std::array<bool, N> free{};
    bool any_free = false;
    for (int i = 0; i < N; ++i) {
      const bool held =
          lo(i) >= hi(i) || (x(i) <= lo(i) && g(i) > 0) || (x(i) >= hi(i) && g(i) < 0);
      free[i] = !held;
      any_free = any_free || free[i];
    }
    if (!any_free) {  // Karush-Kuhn-Tucker point at a corner
      out.converged = true;
      break;
    }
    bool negative_curvature = false;
    const Vec<N> delta = descent_direction<N>(H, JtJ, g, free, box_size, jet.J, opt.step_tolerance,
                                              negative_curvature);
    const double full_step = (jet.J * delta).norm();
    if (!negative_curvature && full_step <= opt.step_tolerance) {
      // Take this last, tiny step too: after it the error is of order its square.
      // Only the point is needed: the derivatives change by ~1e-11 relative.
      x = (x + delta).cwiseMax(lo).cwiseMin(hi);
      jet.S = point_at(x);
      r = jet.S - q;
      out.converged = true;
      break;
    }
    double t = 1;
    bool accepted = false;
    double moved = 0;
    for (int h = 0; h <= opt.max_line_search_halvings; ++h, t *= 0.5) {
      const Vec<N> xn = (x + t * delta).cwiseMax(lo).cwiseMin(hi);
      if (xn == x) break;
      const Jet<N> trial = evaluate(xn);
      const Eigen::Vector3d rn = trial.S - q;
      const double phin = 0.5 * rn.squaredNorm();
      bool sufficient = negative_curvature ? phin < phi : phin <= phi + 1e-4 * g.dot(xn - x);
      if (!sufficient && !negative_curvature && t == 1) {
        // Close to the minimum the decrease of phi drowns in its rounding
        // (phi ~ d^2 / 2 cannot resolve foot moves below ~sqrt(eps) d), so a
        // full Newton step is also accepted when it halves the tangential
        // residual and phi stays within rounding.
        // phi's rounding comes from r = S - q, whose error scales with |S|, |q|.
        const double floor = 64 * std::numeric_limits<double>::epsilon() *
                             (r.norm() * (jet.S.norm() + q.norm()) + phi);
        sufficient = phin <= phi + floor && tangential_residual<N>(trial.J, rn, xn, lo, hi) <=
                                                0.5 * tangential_residual<N>(jet.J, r, x, lo, hi);
      }
      if (sufficient) {
        moved = (trial.S - jet.S).norm();
        x = xn;
        jet = trial;
        r = rn;
        phi = phin;
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      // No representable step decreases phi: at the rounding floor of a
      // minimum (a short full step), or - along negative curvature - at a
      // point that no direction improves.
      out.converged = negative_curvature || full_step <= opt.stall_tolerance;
      break;
    }
    if (t == 1 && !negative_curvature && moved <= opt.step_tolerance) {
      out.converged = true;
      break;
    }
  }
  out.point = jet.S;
  out.squared_distance = r.squaredNorm();
  if constexpr (N == 2) {
    out.su = jet.J.col(0);
    out.sv = jet.J.col(1);
  }
  return x;
}

}  // namespace

namespace {

// The box solve over anything with NurbsSurface's evaluate(u, v, order).
template <class Surface>
LocalFoot box_solve(const Surface& surface, const Eigen::Vector3d& q, const Eigen::Vector2d& seed,
                    const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                    const ClosestPointOptions& options) {
  auto evaluate = [&](const Vec<2>& x) {
    const SurfaceDerivatives d = surface.evaluate(x(0), x(1), 2);
    Jet<2> jet;
    jet.S = d.S;
    jet.J << d.Su, d.Sv;
    jet.D2 << d.Suu, d.Suv, d.Suv, d.Svv;
    return jet;
  };
  auto point_at = [&](const Vec<2>& x) { return surface.point(x(0), x(1)); };
  LocalFoot out;
  out.uv = projected_newton<2>(evaluate, point_at, q, seed, lo, hi, options, out);
  return out;
}

}  // namespace

LocalFoot foot_point_in_box(const NurbsSurface& surface, const Eigen::Vector3d& q,
                            const Eigen::Vector2d& seed, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi, const ClosestPointOptions& options) {
  return box_solve(surface, q, seed, lo, hi, options);
}

LocalFoot foot_point_in_box(const BezierPatch& patch, const Eigen::Vector3d& q,
                            const Eigen::Vector2d& seed, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi, const ClosestPointOptions& options) {
  return box_solve(patch, q, seed, lo, hi, options);
}

LocalFoot foot_point_on_segment(const NurbsSurface& surface, const Eigen::Vector3d& q,
                                const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                const ClosestPointOptions& options) {
  const Eigen::Vector2d e = b - a;
  auto evaluate = [&](const Vec<1>& t) {
    const Eigen::Vector2d uv = a + t(0) * e;
    const SurfaceDerivatives d = surface.evaluate(uv.x(), uv.y(), 2);
    Jet<1> jet;
    jet.S = d.S;
    jet.J = d.Su * e.x() + d.Sv * e.y();
    jet.D2 = d.Suu * (e.x() * e.x()) + 2.0 * d.Suv * (e.x() * e.y()) + d.Svv * (e.y() * e.y());
    return jet;
  };
  auto point_at = [&](const Vec<1>& t) {
    const Eigen::Vector2d uv = a + t(0) * e;
    return surface.point(uv.x(), uv.y());
  };
  const int samples = std::max(1, options.trim_samples_per_segment);
  double best_t = 0, best = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= samples; ++k) {
    const double t = static_cast<double>(k) / samples;
    const Eigen::Vector2d uv = a + t * e;
    const double d2 = (surface.point(uv.x(), uv.y()) - q).squaredNorm();
    if (d2 < best) {
      best = d2;
      best_t = t;
    }
  }
  LocalFoot out;
  const Vec<1> t = projected_newton<1>(evaluate, point_at, q, Vec<1>(best_t), Vec<1>(0.0),
                                       Vec<1>(1.0), options, out);
  out.uv = a + t(0) * e;
  return out;
}

}  // namespace furrow
