#include "machining/toolpath/forward_step.hpp"
#include "base/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace furrow {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double chord_between(const PassCurve& pass, double a, double b) {
  const SurfacePoint pa = pass.at(a), pb = pass.at(b);
  if (!pa.valid || !pb.valid) return kInf;
  return (pb.point - pa.point).norm();
}

// The parameter after t whose chord from t is `length` (bisection; chords
// grow along a pass), or t1 when the pass ends first.
double param_at_chord(const PassCurve& pass, double t, double length) {
  if (!std::isfinite(length) || chord_between(pass, t, pass.t1) <= length) return pass.t1;
  double lo = t, hi = pass.t1;
  for (int k = 0; k < 60 && hi - lo > 1e-12 * (pass.t1 - pass.t0); ++k) {
    const double mid = 0.5 * (lo + hi);
    (chord_between(pass, t, mid) <= length ? lo : hi) = mid;
  }
  return lo > t ? lo : hi;
}

}  // namespace

const char* to_string(StepRule rule) {
  switch (rule) {
    case StepRule::exact: return "exact";
    case StepRule::chord: return "chord";
    case StepRule::circular_arc: return "circular_arc";
  }
  return "unknown";
}

double step_error(const Cutter& cutter, const SurfaceCurve& curve, StepRule rule, const FurrowStepOptions& predictor) {
  if (rule == StepRule::chord) {
    const ChordDeviation c = chord_deviation(curve, predictor);
    return c.valid ? c.deviation : kInf;
  }
  const FurrowStepResult r = furrow_step_error(cutter, curve, predictor);
  return r.valid && r.unreached == 0 ? r.magnitude() : kInf;
}

double circular_arc_step(const Part& part, const Cutter& cutter, const SurfacePoint& at,
                         const Eigen::Vector3d& direction, double tolerance) {
  const DifferentialGeometry g = part.faces[at.face].geometry(at.uv.x(), at.uv.y());
  if (g.degenerate) return kInf;
  const double k = g.normal_curvature(direction);
  const double r = cutter.corner_radius();
  if (std::fabs(k) < 1e-9) return kInf;
  const double rho = 1 / std::fabs(k);
  const double a = k < 0 ? rho + r : rho - r;  // radius of the tool-reference path
  if (!(a > 0)) return kInf;
  const double c = 1 - tolerance / a;
  if (c <= -1) return kPi * rho;
  return 2 * rho * std::acos(c);
}

ForwardSteps place_contact_points(const Part& part, const PassCurve& pass, const Cutter& cutter,
                                  const ForwardStepOptions& options) {
  ForwardSteps result;
  result.params.push_back(pass.t0);
  double t = pass.t0;
  auto error = [&](double a, double b) {
    ++result.evaluations;
    const double e = step_error(cutter, pass.between(a, b), options.rule, options.predictor);
    if (!std::isfinite(e)) ++result.invalid;
    return e;
  };
  const double span = pass.t1 - pass.t0;
  while (t < pass.t1) {
    // A count from the input's ratio of length to tolerance: bounded.
    if (static_cast<long>(result.params.size()) > options.max_points) {
      result.truncated = true;
      break;
    }
    // Upper end: the pass end, or the parameter at max_step.
    const double end = options.max_step > 0 ? param_at_chord(pass, t, options.max_step) : pass.t1;
    // Estimate: the circular-arc step at t.
    const SurfacePoint here = pass.at(t);
    double estimate = end;
    if (here.valid) {
      const SurfacePoint ahead = pass.at(std::min(t + 1e-3 * span, pass.t1));
      const Eigen::Vector3d dir = (ahead.point - here.point).normalized();
      const double ds = circular_arc_step(part, cutter, here, dir, options.tolerance);
      estimate = std::min(end, param_at_chord(pass, t, ds));
    }
    if (options.rule == StepRule::circular_arc) {
      t = estimate > t ? estimate : end;
      result.params.push_back(t);
      continue;
    }
    const double e = options.tolerance;
    if (error(t, end) <= e) {
      t = end;
      result.params.push_back(t);
      continue;
    }
    // Bracket [lo, hi]: error(lo) <= e < error(hi).
    double lo = t, hi = end;
    double trial = std::clamp(estimate, t + 1e-9 * span, end);
    int it = 0;
    for (; it < options.max_iterations; ++it) {
      if (trial >= hi || trial <= lo) break;
      if (error(t, trial) <= e) {
        lo = trial;
        trial = t + 2 * (trial - t);
      } else {
        hi = trial;
        if (lo > t) break;
        trial = t + 0.5 * (trial - t);
      }
      if (lo > t && hi < end) break;
    }
    for (; it < options.max_iterations && hi - lo > options.precision * std::max(lo - t, 1e-12 * span); ++it) {
      const double mid = 0.5 * (lo + hi);
      (error(t, mid) <= e ? lo : hi) = mid;
    }
    if (it >= options.max_iterations) ++result.capped;
    if (!(lo > t)) lo = std::min(hi, t + 1e-9 * span);  // cannot stall: a minimal step
    t = lo;
    result.params.push_back(t);
  }
  return result;
}

}  // namespace furrow
