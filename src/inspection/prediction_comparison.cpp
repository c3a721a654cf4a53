#include "inspection/prediction_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "base/error.hpp"
#include "inspection/surface_fit.hpp"

namespace furrow {

const char* to_string(PredictionVerdict verdict) {
  switch (verdict) {
    case PredictionVerdict::explained: return "explained";
    case PredictionVerdict::not_explained: return "not explained";
    case PredictionVerdict::too_few_points: return "too few points";
  }
  return "unknown";
}

PredictionVerdict parse_prediction_verdict(const std::string& text, const std::string& where) {
  for (PredictionVerdict v : {PredictionVerdict::explained, PredictionVerdict::not_explained,
                              PredictionVerdict::too_few_points})
    if (text == to_string(v)) return v;
  throw InputError(where + ": \"" + text +
                   "\" is not a verdict (explained, not explained, too few points)");
}

namespace {

void check_options(const PredictionComparisonOptions& o) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  // A real probe always scatters, and sigma_total > 0 keeps every z finite.
  if (!positive(o.probe_sigma)) throw InputError("the probing noise sigma must be a positive number of mm");
  if (!positive(o.max_normalised_rms) || !positive(o.within_sigmas))
    throw InputError("the explained-verdict limits must be positive");
  if (!(o.required_share > 0 && o.required_share <= 1))
    throw InputError("the required share of points within the uncertainty must lie in (0, 1]");
  if (o.min_points < 1 || o.max_alignment_iterations < 1)
    throw InputError("the minimum point count and the alignment iterations must be at least 1");
}

double sum(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  return s;
}

// The prediction at every foot point, without the measurement.
PointPrediction predict_at(const Prediction& prediction, const Part& part, const RegisteredPoint& p) {
  PointPrediction out;
  if (p.outlier == OutlierReason::no_foot_point) return out;
  const std::string& face = part.faces[p.foot.face].name();
  if (!prediction.find_face(face)) return out;
  out.face_predicted = true;
  const PredictedError e = prediction.predicted_error_at(face, p.foot.uv.x(), p.foot.uv.y());
  out.status = e.status;
  if (!e.reached()) return out;
  out.predicted = e.value;
  out.band_low = e.max_overcut;
  out.band_high = e.max_undercut;
  return out;
}

// Re-fits the placement to the predicted surface (see the header) and sets
// every reached point's `measured`.
PredictionAlignment align_to_prediction(const RegistrationResult& r, double probe_radius,
                                        const DegreesOfFreedom& dof,
                                        std::vector<PointPrediction>& points,
                                        const PredictionComparisonOptions& o) {
  PredictionAlignment a;
  for (std::size_t i = 0; i < points.size(); ++i) points[i].measured = r.points[i].deviation;
  std::vector<std::size_t> fitted;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].reached() && r.points[i].in_fit) fitted.push_back(i);
  a.points = fitted.size();
  if (!o.align) {
    a.status = "off";
    return a;
  }
  if (fitted.size() < static_cast<std::size_t>(dof.count()) + 1) {
    a.status = "too few points";
    return a;
  }
  std::vector<Eigen::Vector3d> y;
  for (const RegisteredPoint& p : r.points) y.push_back(p.registered);
  SurfaceFit fit(y, probe_radius, dof, RobustLoss::none, 1, o.max_alignment_iterations);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ClosestPoint& f = r.points[i].foot;
    const double e = points[i].reached() ? points[i].predicted : 0.0;
    fit.set_foot(i, f.point + e * f.normal, f.normal, points[i].reached() && r.points[i].in_fit);
  }
  auto rms = [&] {
    double s = 0;
    for (std::size_t i : fitted) s += fit.residual(i) * fit.residual(i);
    return std::sqrt(s / static_cast<double>(fitted.size()));
  };
  a.rms_before = rms();
  std::string message;
  a.iterations = fit.solve(message);
  a.rms_after = rms();
  a.parameters = fit.parameters();
  a.applied = true;
  a.status = message.empty() ? "converged" : message;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].reached()) points[i].measured = fit.residual(i) + points[i].predicted;
  return a;
}

}  // namespace

ResidualStatistics residual_statistics(const std::vector<double>& predicted,
                                       const std::vector<double>& measured,
                                       const std::vector<double>& sigma,
                                       const PredictionComparisonOptions& o) {
  ResidualStatistics s;
  const std::size_t n = predicted.size();
  s.count = n;
  if (n == 0) return s;
  const double count = static_cast<double>(n);
  std::vector<double> residual(n);
  for (std::size_t i = 0; i < n; ++i) residual[i] = measured[i] - predicted[i];
  s.mean_predicted = sum(predicted) / count;
  s.mean_measured = sum(measured) / count;
  s.mean = sum(residual) / count;
  double squares = 0, centred = 0, z2 = 0, spp = 0, smm = 0, spm = 0;
  std::size_t within = 0;
  for (std::size_t i = 0; i < n; ++i) {
    squares += residual[i] * residual[i];
    centred += (residual[i] - s.mean) * (residual[i] - s.mean);
    s.max_abs = std::max(s.max_abs, std::abs(residual[i]));
    const double z = residual[i] / sigma[i];  // sigma_total >= the probing noise > 0
    z2 += z * z;
    within += std::abs(residual[i]) <= o.within_sigmas * sigma[i];
    const double dp = predicted[i] - s.mean_predicted, dm = measured[i] - s.mean_measured;
    spp += dp * dp;
    smm += dm * dm;
    spm += dp * dm;
  }
  s.rms = std::sqrt(squares / count);
  s.sigma = n > 1 ? std::sqrt(centred / (count - 1)) : 0;
  if (n > 1 && spp > 0 && smm > 0) s.correlation = std::clamp(spm / std::sqrt(spp * smm), -1.0, 1.0);
  s.normalised_rms = std::sqrt(z2 / count);
  s.within_share = static_cast<double>(within) / count;
  if (n < static_cast<std::size_t>(o.min_points))
    s.verdict = PredictionVerdict::too_few_points;
  else
    s.verdict = s.normalised_rms <= o.max_normalised_rms && s.within_share >= o.required_share
                    ? PredictionVerdict::explained
                    : PredictionVerdict::not_explained;
  return s;
}

PredictionComparison compare_with_prediction(const RegistrationResult& r,
                                             const std::vector<std::optional<int>>& region,
                                             const Part& part, double probe_radius,
                                             const DegreesOfFreedom& dof,
                                             const Prediction& prediction,
                                             const PredictionComparisonOptions& o) {
  check_options(o);
  PredictionComparison c;
  c.points.reserve(r.points.size());
  for (const RegisteredPoint& p : r.points) c.points.push_back(predict_at(prediction, part, p));
  c.alignment = align_to_prediction(r, probe_radius, dof, c.points, o);

  struct Series {
    std::vector<double> predicted, measured, sigma;
  };
  Series all;
  std::map<int, Series> by_region;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const RegisteredPoint& p = r.points[i];
    PointPrediction& q = c.points[i];
    if (q.reached()) {
      const double resolution = (q.band_high - q.band_low) / std::sqrt(12.0);
      q.residual = q.measured - q.predicted;
      q.sigma = std::sqrt(p.uncertainty * p.uncertainty + o.probe_sigma * o.probe_sigma +
                          resolution * resolution);
    }
    if (!p.evaluated) continue;
    if (!q.face_predicted) {
      ++c.uncompared.face_not_predicted;
      continue;
    }
    switch (q.status) {
      case ErrorCellStatus::reached: break;
      case ErrorCellStatus::not_reached: ++c.uncompared.not_reached; continue;
      case ErrorCellStatus::outside: ++c.uncompared.outside; continue;
      case ErrorCellStatus::not_machinable: ++c.uncompared.not_machinable; continue;
    }
    q.compared = true;
    for (Series* s : {&all, i < region.size() && region[i] ? &by_region[*region[i]] : nullptr}) {
      if (!s) continue;
      s->predicted.push_back(q.predicted);
      s->measured.push_back(q.measured);
      s->sigma.push_back(q.sigma);
    }
  }
  c.overall = residual_statistics(all.predicted, all.measured, all.sigma, o);
  for (const auto& [id, s] : by_region)
    c.regions.push_back({id, residual_statistics(s.predicted, s.measured, s.sigma, o)});
  return c;
}

std::size_t admit_predicted_deviations(RegistrationResult& r, const PredictionComparison& c,
                                       const PredictionComparisonOptions& o) {
  std::size_t admitted = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    RegisteredPoint& p = r.points[i];
    const PointPrediction& q = c.points[i];
    if (p.outlier != OutlierReason::blunder || !q.reached() ||
        !(std::abs(q.residual) <= o.within_sigmas * q.sigma))
      continue;
    p.outlier = OutlierReason::large_deviation;
    p.evaluated = true;
    char note[160];
    std::snprintf(note, sizeof note, "; explained by the prediction (predicted %.4f mm, residual %.4f mm)",
                  q.predicted, q.residual);
    p.outlier_detail += note;
    ++admitted;
  }
  return admitted;
}

}  // namespace furrow
