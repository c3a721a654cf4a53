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

namespace {

// The first search across a section: the error at samples + 1 evenly
// spaced offsets over [-width, width]. Returns the index of the smallest
// (the first one, on ties) and sets `value`; -1 when none is defined.
int smallest_sample(Strip& strip, double lambda, double width, int samples, double& value) {
  const double cell = 2 * width / samples;
  int arg = -1;
  value = kInf;
  for (int k = 0; k <= samples; ++k) {
    const double e = strip(lambda, -width + k * cell);
    if (e < value) value = e, arg = k;
  }
  return arg;
}

// The overcut: from the curve's smallest error, alternating Brent searches
// across and along until the point settles (the header).
StripExtreme deepest(Strip& strip, const FurrowStepResult& on_curve, double width, double chord,
                     const StripStepOptions& options, bool& converged) {
  const int samples = std::max(2, options.across_samples);
  const double cell = 2 * width / samples;
  const ScalarSearchOptions across_search{options.tolerance, options.max_iterations};
  const ScalarSearchOptions along_search{options.tolerance / chord, options.max_iterations};
  double lambda = on_curve.overcut.lambda, c = 0;
  double best = std::min(on_curve.overcut.error, strip(lambda, 0.0));
  converged = false;
  for (int round = 0; round < options.max_rounds; ++round) {
    const double lambda_before = lambda, c_before = c;
    // Across: the first time over the whole width (the valley may lie off
    // the curve by more than a Brent bracket), then around the last point.
    double lo = c - cell, hi = c + cell;
    if (round == 0) {
      double sampled = kInf;
      const int arg = smallest_sample(strip, lambda, width, samples, sampled);
      if (arg >= 0 && sampled < best) lo = -width + (arg - 1) * cell, hi = -width + (arg + 1) * cell;
    }
    const ScalarSearchResult a = minimize_unimodal([&](double x) { return strip(lambda, x); }, lo, hi, across_search);
    if (a.value < best) best = a.value, c = a.x;
    // Along, across position held.
    const double la = std::max(0.0, lambda - options.along_bracket), lb = std::min(1.0, lambda + options.along_bracket);
    const ScalarSearchResult b = minimize_unimodal([&](double l) { return strip(l, c); }, la, lb, along_search);
    if (b.value < best) best = b.value, lambda = b.x;
    if (std::fabs(c - c_before) <= options.tolerance && std::fabs(lambda - lambda_before) * chord <= options.tolerance) {
      converged = true;
      break;
    }
  }
  StripExtreme out;
  out.error = best;
  out.lambda = lambda;
  out.offset = c;
  out.at = strip.point(lambda, c);
  return out;
}

// The track bottom's crest: the saddle of the error where it is smallest
// across (the valley) and largest along it, found by alternating a Brent
// search across (sampled first over +-width, as for the overcut) with a
// Brent search along, until the point settles (the header). With the valley
// at the edge of the width there is no bottom within the cutter's reach:
// the curve's undercut is kept (`proper` false).
StripExtreme crest(Strip& strip, const FurrowStepResult& on_curve, double width, double chord,
                   const StripStepOptions& options, bool& converged, bool& proper) {
  const int samples = std::max(2, options.across_samples);
  const double cell = 2 * width / samples;
  const ScalarSearchOptions across_search{options.tolerance, options.max_iterations};
  const ScalarSearchOptions along_search{options.tolerance / chord, options.max_iterations};
  double lambda = on_curve.undercut.lambda, c = 0;
  converged = false;
  for (int round = 0; round < options.max_rounds; ++round) {
    const double lambda_before = lambda, c_before = c;
    double lo = std::max(-width, c - cell), hi = std::min(width, c + cell);
    if (round == 0) {
      double sampled = kInf;
      const int arg = smallest_sample(strip, lambda, width, samples, sampled);
      if (arg < 0) break;
      lo = std::max(-width, -width + (arg - 1) * cell), hi = std::min(width, -width + (arg + 1) * cell);
    }
    const ScalarSearchResult a = minimize_unimodal([&](double x) { return strip(lambda, x); }, lo, hi, across_search);
    if (!std::isfinite(a.value)) break;
    c = a.x;
    const double la = std::max(0.0, lambda - options.along_bracket), lb = std::min(1.0, lambda + options.along_bracket);
    const ScalarSearchResult b = minimize_unimodal(
        [&](double l) {
          const double e = strip(l, c);
          return std::isfinite(e) ? -e : kInf;
        },
        la, lb, along_search);
    if (std::isfinite(b.value)) lambda = b.x;
    if (std::fabs(c - c_before) <= options.tolerance && std::fabs(lambda - lambda_before) * chord <= options.tolerance) {
      converged = true;
      break;
    }
  }
  if (!converged) {
    // The alternation can circle a saddle whose valley turns sharply with
    // lambda (a flat end mill's rim): then search it nested, the valley of
    // each section found afresh (sampled over the width, then Brent) and the
    // largest valley by Brent along. Slower, the same answer where both end.
    auto valley = [&](double l, double& at) {
      double sampled = kInf;
      const int arg = smallest_sample(strip, l, width, samples, sampled);
      if (arg < 0) return kInf;
      const double lo = std::max(-width, -width + (arg - 1) * cell), hi = std::min(width, -width + (arg + 1) * cell);
      const ScalarSearchResult r = minimize_unimodal([&](double x) { return strip(l, x); }, lo, hi, across_search);
      at = r.x;
      return r.value;
    };
    const double la = std::max(0.0, on_curve.undercut.lambda - options.along_bracket);
    const double lb = std::min(1.0, on_curve.undercut.lambda + options.along_bracket);
    double at = 0;
    const ScalarSearchResult top = minimize_unimodal(
        [&](double l) {
          const double v = valley(l, at);
          return std::isfinite(v) ? -v : kInf;
        },
        la, lb, along_search);
    converged = top.converged && std::isfinite(top.value);
    lambda = top.x;
    valley(lambda, c);
  }
  const double value = strip(lambda, c);
  proper = std::isfinite(value) && std::fabs(c) < width - 2 * options.tolerance;
  StripExtreme out;
  if (!proper) {
    out = {on_curve.undercut.error, on_curve.undercut.lambda, 0, on_curve.undercut.at};
    return out;
  }
  out.error = std::max(0.0, std::min(value, on_curve.undercut.error));
  out.lambda = lambda;
  out.offset = c;
  out.at = strip.point(lambda, c);
  return out;
}

}  // namespace

StripStepResult strip_step_error(const Part& part, const Cutter& cutter, const SurfaceCurve& curve,
                                 const FurrowStepResult& on_curve, const FurrowStepOptions& step_options,
                                 const StripStepOptions& options) {
  StripStepResult result;
  if (!on_curve.valid) return result;
  result.valid = true;
  result.overcut = {on_curve.overcut.error, on_curve.overcut.lambda, 0, on_curve.overcut.at};
  result.undercut = {on_curve.undercut.error, on_curve.undercut.lambda, 0, on_curve.undercut.at};
  const bool undercut = options.undercut && on_curve.undercut.error > 0;
  if (!(on_curve.overcut.error < 0) && !undercut) return result;
  const Eigen::Vector3d d = on_curve.tip1 - on_curve.tip0;
  const SweptEnvelope envelope(cutter, on_curve.tip0, on_curve.tip1, step_options.envelope);
  const NormalErrorOptions normal = with_height_bounds(
      step_options.normal, std::min(on_curve.tip0.z(), on_curve.tip1.z()), envelope.shadow_box());
  Strip strip(part, curve, envelope, normal, d);
  const SurfacePoint p0 = curve(0.0), p1 = curve(1.0);
  const double chord = std::max((p1.point - p0.point).norm(), 1e-12);
  const double width = options.half_width > 0 ? options.half_width : cutter.radius();
  bool converged = true;
  // Searched also where the curve itself is not overcut: a cutter that
  // does not fit across a concave part cuts in beside the curve only.
  result.overcut = deepest(strip, on_curve, width, chord, options, converged);
  // Where the move cuts in beside the curve, its track has no bottom that
  // leaves material: the undercut stays the curve's (the header).
  if (undercut && !(result.overcut.error < -options.clear)) {
    bool settled = true, proper = true;
    const StripExtreme top = crest(strip, on_curve, width, chord, options, settled, proper);
    // A search that did not settle keeps the curve's figure (an upper
    // bound of the crest) and says so.
    if (settled) result.undercut = top;
    converged = converged && settled;
  }
  result.converged = converged;
  result.evaluations = strip.evaluations;
  return result;
}

}  // namespace furrow
