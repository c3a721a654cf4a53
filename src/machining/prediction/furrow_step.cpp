#include "machining/prediction/furrow_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <cstdint>
#include <cstring>
#include <vector>

#include "base/scalar_search.hpp"

namespace furrow {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

int interval_count(double chord, const FurrowStepOptions& o) {
  const double n = std::ceil(chord / std::max(o.max_sample_spacing, 1e-9));
  return static_cast<int>(std::clamp(n, double(std::max(1, o.min_intervals)), double(std::max(1, o.max_intervals))));
}

// The extremum of sign * f over [0, 1]: the best of the samples `values`
// (sign * values[i] is compared; -inf marks a sample to skip), refined on the
// bracket of its neighbouring samples. f returns NaN where it is undefined
// (never chosen by the refinement).
struct Sampled {
  double value = -kInf;  // sign * f at the extremum
  double lambda = 0;
  bool converged = true;
};

template <class F>
Sampled extremum(F&& f, int n, double sign, double chord, const FurrowStepOptions& o,
                 const std::vector<double>& values) {
  Sampled best;
  int arg = -1;
  for (int i = 0; i <= n; ++i)
    if (sign * values[i] > best.value) best.value = sign * values[i], arg = i;
  if (arg < 0) return best;
  best.lambda = double(arg) / n;
  const double a = double(std::max(arg - 1, 0)) / n, b = double(std::min(arg + 1, n)) / n;
  auto neg = [&](double lambda) {
    const double v = f(lambda);
    return std::isfinite(v) ? -sign * v : kInf;
  };
  const ScalarSearchResult r =
      minimize_unimodal(neg, a, b, {o.refine_tolerance / std::max(chord, 1e-12), o.refine_iterations});
  best.converged = r.converged;
  if (-r.value > best.value) best.value = -r.value, best.lambda = r.x;
  return best;
}

// The points of a curve evaluated so far, by lambda (exact match): the
// sampling grid's ends are the contact points evaluated first, and the
// extremes are evaluated again for their surface points. A small
// open-addressing table on lambda's bits: a node-based map's allocations
// cost as much as they saved.
class Remembered {
 public:
  explicit Remembered(const SurfaceCurve& curve) : curve_(&curve), slots_(128, -1) { points_.reserve(64); }
  SurfacePoint operator()(double lambda) {
    const double key = lambda + 0.0;  // -0 and +0 alike
    std::uint64_t bits = 0;
    std::memcpy(&bits, &key, sizeof bits);
    const std::size_t mask = slots_.size() - 1;
    std::size_t at = (bits * 0x9E3779B97F4A7C15ull) >> 40 & mask;
    for (; slots_[at] >= 0; at = (at + 1) & mask)
      if (lambdas_[slots_[at]] == key) return points_[slots_[at]];
    const SurfacePoint p = (*curve_)(lambda);
    slots_[at] = static_cast<int>(points_.size());
    lambdas_.push_back(key);
    points_.push_back(p);
    if (2 * points_.size() > slots_.size()) rehash();
    return p;
  }

 private:
  void rehash() {
    slots_.assign(2 * slots_.size(), -1);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t k = 0; k < lambdas_.size(); ++k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &lambdas_[k], sizeof bits);
      std::size_t at = (bits * 0x9E3779B97F4A7C15ull) >> 40 & mask;
      while (slots_[at] >= 0) at = (at + 1) & mask;
      slots_[at] = static_cast<int>(k);
    }
  }

  const SurfaceCurve* curve_;  // outlives this
  std::vector<int> slots_;     // index into lambdas_ / points_, -1: empty; size a power of two
  std::vector<double> lambdas_;
  std::vector<SurfacePoint> points_;
};

FurrowStepResult step_error(const Cutter& cutter, const Eigen::Vector3d& tip0, const Eigen::Vector3d& tip1,
                            Remembered& curve, const FurrowStepOptions& options) {
  FurrowStepResult result;
  const SurfacePoint p0 = curve(0.0), p1 = curve(1.0);
  if (!p0.valid || !p1.valid || !(p0.normal.z() >= 0) || !(p1.normal.z() >= 0)) return result;
  result.valid = true;
  result.tip0 = tip0;
  result.tip1 = tip1;
  const SweptEnvelope envelope(cutter, tip0, tip1, options.envelope);
  auto height = [&](double x, double y) { return envelope.height_at(x, y); };
  const NormalErrorOptions normal =
      with_height_bounds(options.normal, std::min(tip0.z(), tip1.z()), envelope.shadow_box());
  bool all_converged = true;
  // Error at a curve point; `reached` says whether it is defined.
  auto error_at = [&](double lambda, bool& reached) {
    const SurfacePoint p = curve(lambda);
    reached = false;
    if (!p.valid || !(p.normal.z() >= 0)) return 0.0;
    const NormalError e = normal_error(height, p.point, p.normal, normal);
    reached = e.reached;
    if (e.reached && !e.converged) all_converged = false;
    return e.error;
  };
  const double chord = (p1.point - p0.point).norm();
  const int n = interval_count(chord, options);
  std::vector<double> values(n + 1), maxima(n + 1), minima(n + 1);
  for (int i = 0; i <= n; ++i) {
    bool reached = false;
    values[i] = error_at(double(i) / n, reached);
    maxima[i] = reached ? values[i] : -kInf;
    minima[i] = reached ? values[i] : kInf;  // sign -1: -(+inf) is skipped
    result.unreached += !reached;
  }
  result.samples = n + 1;
  auto f = [&](double lambda) {
    bool reached = false;
    const double e = error_at(lambda, reached);
    return reached ? e : std::numeric_limits<double>::quiet_NaN();
  };
  const Sampled hi = extremum(f, n, +1.0, chord, options, maxima);
  const Sampled lo = extremum(f, n, -1.0, chord, options, minima);
  result.converged = all_converged && hi.converged && lo.converged;
  if (std::isfinite(hi.value) && hi.value > 0) {
    result.undercut.error = hi.value;
    result.undercut.lambda = hi.lambda;
  }
  if (std::isfinite(lo.value) && lo.value > 0) {
    result.overcut.error = -lo.value;
    result.overcut.lambda = lo.lambda;
  }
  result.undercut.at = curve(result.undercut.lambda);
  result.overcut.at = curve(result.overcut.lambda);
  return result;
}

}  // namespace

FurrowStepResult furrow_step_error(const Cutter& cutter, const Eigen::Vector3d& tip0,
                                   const Eigen::Vector3d& tip1, const SurfaceCurve& curve,
                                   const FurrowStepOptions& options) {
  Remembered remembered(curve);
  return step_error(cutter, tip0, tip1, remembered, options);
}

FurrowStepResult furrow_step_error(const Cutter& cutter, const SurfaceCurve& curve,
                                   const FurrowStepOptions& options) {
  Remembered remembered(curve);
  const SurfacePoint p0 = remembered(0.0), p1 = remembered(1.0);
  if (!p0.valid || !p1.valid) return {};
  const CutterLocation a = cutter_location(cutter, p0.point, p0.normal, options.location);
  const CutterLocation b = cutter_location(cutter, p1.point, p1.normal, options.location);
  if (!a.reachable || !b.reachable) return {};
  return step_error(cutter, a.tip, b.tip, remembered, options);
}

SurfaceCurve remembering_curve(SurfaceCurve curve) {
  struct Owned {
    explicit Owned(SurfaceCurve c) : curve(std::move(c)) {}
    SurfaceCurve curve;
    Remembered remembered{curve};
  };
  auto owned = std::make_shared<Owned>(std::move(curve));
  return [owned](double lambda) { return owned->remembered(lambda); };
}

ChordDeviation chord_deviation(const SurfaceCurve& plain, const FurrowStepOptions& options) {
  Remembered curve(plain);
  ChordDeviation result;
  const SurfacePoint p0 = curve(0.0), p1 = curve(1.0);
  if (!p0.valid || !p1.valid) return result;
  result.valid = true;
  const Eigen::Vector3d a = p0.point, d = p1.point - p0.point;
  const double len2 = d.squaredNorm();
  auto distance = [&](double lambda) {
    const SurfacePoint p = curve(lambda);
    if (!p.valid) return std::numeric_limits<double>::quiet_NaN();
    const double s = len2 > 0 ? std::clamp((p.point - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p.point - (a + s * d)).norm();
  };
  const double chord = std::sqrt(len2);
  const int n = interval_count(chord, options);
  std::vector<double> values(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double v = distance(double(i) / n);
    values[i] = std::isfinite(v) ? v : -kInf;
  }
  const Sampled hi = extremum(distance, n, +1.0, chord, options, values);
  result.deviation = std::max(0.0, hi.value);
  result.lambda = hi.lambda;
  result.at = curve(hi.lambda);
  return result;
}

}  // namespace furrow
