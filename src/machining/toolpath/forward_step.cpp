#include "machining/toolpath/forward_step.hpp"
#include "base/error.hpp"
#include "base/numbers.hpp"
#include "base/text_fields.hpp"
#include "machining/gouge/local_gouge.hpp"
#include "machining/prediction/strip_step.hpp"

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

StepRule parse_step_rule(const std::string& text, const std::string& where) {
  for (StepRule r : {StepRule::exact, StepRule::chord, StepRule::circular_arc})
    if (text == to_string(r)) return r;
  if (text == "circular-arc") return StepRule::circular_arc;
  throw InputError(where + ": unknown rule " + quote_field(text) + " (valid: exact, chord, circular_arc)");
}

double step_error(const Part& part, const Cutter& cutter, const SurfaceCurve& curve, StepRule rule,
                  const FurrowStepOptions& predictor, bool beside) {
  if (rule == StepRule::chord) {
    const ChordDeviation c = chord_deviation(curve, predictor);
    return c.valid ? c.deviation : kInf;
  }
  if (!beside) {
    const FurrowStepResult r = furrow_step_error(cutter, curve, predictor);
    return r.valid && r.unreached == 0 ? r.magnitude() : kInf;
  }
  // One remembering curve: the strip search starts on the curve's points.
  const SurfaceCurve remembered = remembering_curve(curve);
  FurrowStepResult r = furrow_step_error(cutter, remembered, predictor);
  if (!r.valid || r.unreached != 0) return kInf;
  // The undercut stays the curve's: never below the track's crest
  // (strip_step.hpp), so a step planned by it keeps the tolerance there too.
  // A step whose curve is not overcut is taken at the curve's figure: the
  // planner looks beside the curve only where the cutter fits the part (the
  // caller), and the search beside starts from the curve's overcut.
  if (!(r.overcut.error < 0)) return r.magnitude();
  StripStepOptions beside_options;
  beside_options.undercut = false;
  const StripStepResult strip = strip_step_error(part, cutter, remembered, r, predictor, beside_options);
  if (strip.valid) r.overcut.error = strip.overcut.error;
  return r.magnitude();
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
  // Whether the cutter fits the part at a pass point (no local gouge in any
  // direction): only then is a step's overcut beside its curve the step's
  // doing (strip_step.hpp), not a gouge no step length removes. Asked at the
  // step's start only, so that one search sees one error function.
  auto fits = [&](double at) {
    const SurfacePoint p = pass.at(at);
    if (!p.valid) return false;
    const DifferentialGeometry g = part.faces[p.face].geometry(p.uv.x(), p.uv.y());
    return !g.degenerate && check_local_gouge(cutter, g).status == GougeStatus::clear;
  };
  bool beside = false;  // the current step's error includes the strip beside the curve
  auto error = [&](double a, double b) {
    ++result.evaluations;
    const double e = step_error(part, cutter, pass.between(a, b), options.rule, options.predictor, beside);
    if (!std::isfinite(e)) ++result.invalid;
    return e;
  };
  const double span = pass.t1 - pass.t0;
  // One step from t: the longest whose error is within the tolerance (the
  // header), with whether it jumped or hit the iteration cap.
  struct Next {
    double t = 0;
    bool jump = false, capped = false, minimal = false;
  };
  auto search = [&](double end, double estimate) {
    Next next;
    const double e = options.tolerance;
    const double e_end = error(t, end);
    if (e_end <= e) {
      next.t = end;
      return next;
    }
    // Bracket [lo, hi]: error(lo) <= e < error(hi).
    double lo = t, hi = end, e_lo = 0, e_hi = e_end;  // errors at the ends
    double trial = std::clamp(estimate, t + 1e-9 * span, end);
    int it = 0;
    for (; it < options.max_iterations; ++it) {
      if (trial >= hi || trial <= lo) break;
      const double et = error(t, trial);
      if (et <= e) {
        lo = trial;
        e_lo = et;
        trial = t + 2 * (trial - t);
      } else {
        hi = trial;
        e_hi = et;
        if (lo > t) break;
        trial = t + 0.5 * (trial - t);
      }
      if (lo > t && hi < end) break;
    }
    // Refine to the error, not to the parameter: false position on
    // error - e (Illinois: the end that stays is halved in weight so the
    // bracket shrinks from both sides); bisection when an end is unknown.
    // Stops when the accepted step's error is within the precision below
    // the tolerance, or the bracket cannot shrink (the error jumps over the
    // tolerance there: a new face or a change of contact).
    const double close_enough = std::max(options.relative_precision * e, options.absolute_precision);
    double g_lo = e - e_lo, g_hi = e_hi - e;  // distances of the ends' errors from the tolerance
    int replaced = 0;                         // end replaced last: -1 lo, +1 hi
    bool resolved = false;
    for (; it < options.max_iterations; ++it) {
      if (lo > t && e - e_lo <= close_enough) {
        resolved = true;
        break;
      }
      if (hi - lo <= 1e-12 * span) break;
      double mid = 0.5 * (lo + hi);
      if (lo > t && std::isfinite(g_hi)) {
        // Inside the bracket, away from its ends.
        const double f = lo + (hi - lo) * g_lo / (g_lo + g_hi);
        mid = std::clamp(f, lo + 1e-3 * (hi - lo), hi - 1e-3 * (hi - lo));
      }
      const double em = error(t, mid);
      if (em <= e) {
        lo = mid;
        e_lo = em;
        g_lo = e - em;
        if (replaced == -1) g_hi *= 0.5;
        replaced = -1;
      } else {
        hi = mid;
        g_hi = em - e;
        if (replaced == +1) g_lo *= 0.5;
        replaced = +1;
      }
    }
    next.jump = !resolved && it < options.max_iterations && lo > t;
    next.capped = it >= options.max_iterations;
    next.minimal = !(lo > t);
    if (next.minimal) lo = std::min(hi, t + 1e-9 * span);  // cannot stall: a minimal step
    next.t = lo;
    return next;
  };
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
    beside = options.rule == StepRule::exact && fits(t);
    Next next = search(end, estimate);
    // An overcut beside the curve that even the shortest step keeps, or
    // that jumps over the tolerance, is not the step's growing furrow (a
    // feature beside the pass within the cutter's reach, a part edge): the
    // curve's error decides this step, as it does where the cutter does not
    // fit.
    if ((next.minimal || next.jump) && beside) {
      beside = false;
      next = search(end, estimate);
    }
    result.jumps += next.jump;
    result.capped += next.capped;
    t = next.t;
    result.params.push_back(t);
  }
  return result;
}

}  // namespace furrow
