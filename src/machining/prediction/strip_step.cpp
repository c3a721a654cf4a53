#include "machining/prediction/strip_step.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/scalar_search.hpp"

namespace furrow {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The error at S(lambda, c); +infinity where it is not defined (so that the
// minimisations pass it by).
class Strip {
 public:
  Strip(const Part& part, const SurfaceCurve& curve, const SweptEnvelope& envelope, const NormalErrorOptions& normal,
        const Eigen::Vector3d& direction)
      : part_(part), curve_(curve), envelope_(envelope), normal_(normal), direction_(direction) {}

  double operator()(double lambda, double c) {
    if (!section(lambda)) return kInf;
    ++evaluations;
    const SurfacePoint q = c == 0 ? base_ : surface_point(part_, base_.face, base_.uv + c * duv_);
    if (!q.valid || !(q.normal.z() >= 0) || !part_.faces[q.face].contains(q.uv.x(), q.uv.y())) return kInf;
    const NormalError e =
        normal_error([&](double x, double y) { return envelope_.height_at(x, y); }, q.point, q.normal, normal_);
    return e.reached ? e.error : kInf;
  }
  SurfacePoint point(double lambda, double c) {
    if (!section(lambda)) return {};
    return c == 0 ? base_ : surface_point(part_, base_.face, base_.uv + c * duv_);
  }

  int evaluations = 0;

 private:
  // The curve point at lambda and the (u, v) step of one millimetre across.
  bool section(double lambda) {
    if (lambda == lambda_) return ok_;
    lambda_ = lambda;
    ok_ = false;
    base_ = curve_(lambda);
    if (!base_.valid) return false;
    const SurfaceDerivatives sd = part_.faces[base_.face].surface().evaluate(base_.uv.x(), base_.uv.y(), 1);
    const Eigen::Vector3d n = base_.normal;
    const Eigen::Vector3d t = direction_ - direction_.dot(n) * n;
    if (!(t.norm() > 1e-12)) return false;
    const Eigen::Vector3d across = n.cross(t).normalized();
    Eigen::Matrix2d g;
    g << sd.Su.dot(sd.Su), sd.Su.dot(sd.Sv), sd.Su.dot(sd.Sv), sd.Sv.dot(sd.Sv);
    if (!(g.determinant() > 1e-24)) return false;
    duv_ = g.inverse() * Eigen::Vector2d(sd.Su.dot(across), sd.Sv.dot(across));
    ok_ = duv_.allFinite();
    return ok_;
  }

  const Part& part_;
  const SurfaceCurve& curve_;
  const SweptEnvelope& envelope_;
  NormalErrorOptions normal_;
  Eigen::Vector3d direction_;
  double lambda_ = std::numeric_limits<double>::quiet_NaN();
  bool ok_ = false;
  SurfacePoint base_;
  Eigen::Vector2d duv_ = Eigen::Vector2d::Zero();
};

}  // namespace

StripStepResult strip_step_error(const Part& part, const Cutter& cutter, const SurfaceCurve& curve,
                                 const FurrowStepResult& on_curve, const FurrowStepOptions& step_options,
                                 const StripStepOptions& options) {
  StripStepResult result;
  if (!on_curve.valid || !(on_curve.overcut.error < 0)) return result;
  const Eigen::Vector3d d = on_curve.tip1 - on_curve.tip0;
  const SweptEnvelope envelope(cutter, on_curve.tip0, on_curve.tip1, step_options.envelope);
  const NormalErrorOptions normal = with_height_bounds(
      step_options.normal, std::min(on_curve.tip0.z(), on_curve.tip1.z()), envelope.shadow_box());
  Strip strip(part, curve, envelope, normal, d);
  const SurfacePoint p0 = curve(0.0), p1 = curve(1.0);
  const double chord = std::max((p1.point - p0.point).norm(), 1e-12);
  const double width = options.half_width > 0 ? options.half_width : cutter.radius();
  const int samples = std::max(2, options.across_samples);
  const double cell = 2 * width / samples;
  const ScalarSearchOptions across_search{options.tolerance, options.max_iterations};
  const ScalarSearchOptions along_search{options.tolerance / chord, options.max_iterations};

  double lambda = on_curve.overcut.lambda, c = 0;
  double best = std::min(on_curve.overcut.error, strip(lambda, 0.0));
  result.valid = true;
  result.converged = false;
  for (int round = 0; round < options.max_rounds; ++round) {
    const double lambda_before = lambda, c_before = c;
    // Across: the first time over the whole width (the valley may lie off
    // the curve by more than a Brent bracket), then around the last point.
    double lo = c - cell, hi = c + cell;
    if (round == 0) {
      int arg = -1;
      double sampled = best;
      for (int k = 0; k <= samples; ++k) {
        const double ck = -width + k * cell;
        const double e = strip(lambda, ck);
        if (e < sampled) sampled = e, arg = k;
      }
      if (arg >= 0) lo = -width + (arg - 1) * cell, hi = -width + (arg + 1) * cell;
    }
    const ScalarSearchResult a = minimize_unimodal([&](double x) { return strip(lambda, x); }, lo, hi, across_search);
    if (a.value < best) best = a.value, c = a.x;
    // Along, across position held.
    const double la = std::max(0.0, lambda - options.along_bracket), lb = std::min(1.0, lambda + options.along_bracket);
    const ScalarSearchResult b = minimize_unimodal([&](double l) { return strip(l, c); }, la, lb, along_search);
    if (b.value < best) best = b.value, lambda = b.x;
    if (std::fabs(c - c_before) <= options.tolerance && std::fabs(lambda - lambda_before) * chord <= options.tolerance) {
      result.converged = true;
      break;
    }
  }
  result.overcut.error = best;
  result.overcut.lambda = lambda;
  result.overcut.offset = c;
  result.overcut.at = strip.point(lambda, c);
  result.evaluations = strip.evaluations;
  return result;
}

}  // namespace furrow
