#pragma once
// Predicted versus measured: at every evaluated measured point, the
// machining error the prediction (prediction.json) expects at the point's
// foot (face, u, v) next to the measured deviation, their residual
// (measured - predicted), statistics overall and per region, and a verdict:
// does the prediction explain the measurement within the measurement
// uncertainty? The rules are defended in docs/verification.md.
//
// Alignment. The measured deviations come from a best fit to the NOMINAL
// surface, which absorbs any rigid component of the real error field (a
// part whose scallops leave +5 um everywhere is shifted down by 5 um). The
// prediction is absolute, so comparing it with best-fit deviations would
// charge the prediction with what the fit moved. With `align` the placement
// is therefore re-fitted to the PREDICTED surface (nominal + e n): with the
// feet held, Ceres finds the small rigid correction (free DOF of the
// registration) minimising sum (d_i + J_i delta - e_i)^2 over the points in
// the registration's fit where the prediction reached; `measured` is the
// deviation after that correction, `residual` = measured - predicted. The
// tolerance evaluation keeps the nominal best fit (the QA reference).
//
// Uncertainty of a residual (1 sigma):
//   sigma_total^2 = u_reg^2 + sigma_probe^2 + sigma_pred^2
// with u_reg the point's deviation uncertainty from the registration
// covariance (0 when there is none), sigma_probe the CMM's probing noise
// (an option: a property of the machine that one measurement of an unknown
// surface cannot reveal) and sigma_pred = (band_high - band_low) / sqrt(12),
// the prediction's resolution: the prediction stores per cell (~1 mm) a mean
// and the band [max_overcut, max_undercut] of its samples; where in the band
// the probed spot lies is unknown, uniform over it.
//
// Verdict over the compared points (evaluated, prediction reached) with
// z_i = residual_i / sigma_total_i:
//   explained      when RMS(z) <= max_normalised_rms and the share of
//                  |z_i| <= within_sigmas is at least required_share;
//   not explained  otherwise;
//   too few points below min_points compared points.
// Everything is summed in point order: deterministic.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/degrees_of_freedom.hpp"
#include "inspection/registration.hpp"
#include "machining/prediction/prediction.hpp"

namespace furrow {

struct PredictionComparisonOptions {
  double probe_sigma = 0.002;       // [mm] 1-sigma probing noise along the normal, > 0
  bool align = true;                // re-fit the placement to the predicted surface
  int max_alignment_iterations = 10;  // Ceres iterations (the problem is linear: 1-2 suffice)
  double max_normalised_rms = 1.5;  // RMS of residual / sigma_total for "explained"
  double within_sigmas = 3;         // |residual| <= this * sigma_total counts as within
  double required_share = 0.95;     // share of compared points that must be within
  int min_points = 5;               // fewer compared points: no verdict
};

enum class PredictionVerdict { explained, not_explained, too_few_points };
const char* to_string(PredictionVerdict verdict);
PredictionVerdict parse_prediction_verdict(const std::string& text, const std::string& where);

// The prediction at one measured point.
struct PointPrediction {
  bool face_predicted = false;  // the prediction covers the foot's face
  ErrorCellStatus status = ErrorCellStatus::outside;  // of the cell holding the foot
  bool compared = false;        // evaluated and reached: in the statistics
  // The numbers below are set where the prediction reached the foot.
  double predicted = 0;                // e [mm]
  double band_low = 0, band_high = 0;  // the cell's [max_overcut, max_undercut] [mm]
  double measured = 0;                 // deviation after the prediction alignment [mm]
  double residual = 0;                 // measured - predicted [mm]
  double sigma = 0;                    // sigma_total [mm]
  bool reached() const { return face_predicted && status == ErrorCellStatus::reached; }
};

struct ResidualStatistics {
  std::size_t count = 0;                      // compared points
  double mean_predicted = 0, mean_measured = 0;  // [mm]
  double mean = 0, sigma = 0, rms = 0, max_abs = 0;  // of the residuals [mm] (sigma: sample)
  std::optional<double> correlation;  // Pearson r of predicted vs measured; unset when
                                      // fewer than 2 points or either is constant
  double normalised_rms = 0;  // RMS of residual / sigma_total
  double within_share = 0;    // share with |residual| <= within_sigmas sigma_total
  PredictionVerdict verdict = PredictionVerdict::too_few_points;
  bool explained() const { return verdict == PredictionVerdict::explained; }
};

struct RegionResidualStatistics {
  int region = 0;
  ResidualStatistics statistics;
};

struct PredictionAlignment {
  bool applied = false;   // false: measured = deviation
  std::string status;     // "converged", "off", "too few points", or Ceres' message
  Eigen::Matrix<double, 6, 1> parameters = Eigen::Matrix<double, 6, 1>::Zero();  // rx ry rz [rad], tx ty tz [mm]
  std::size_t points = 0;  // in the fit
  int iterations = 0;
  double rms_before = 0, rms_after = 0;  // residual RMS over the fitted points [mm]
};

// Evaluated points the prediction did not reach, by reason.
struct UncomparedCounts {
  std::size_t face_not_predicted = 0, not_reached = 0, outside = 0, not_machinable = 0;
};

struct PredictionComparison {
  PredictionAlignment alignment;
  std::vector<PointPrediction> points;  // one per measured point
  ResidualStatistics overall;
  std::vector<RegionResidualStatistics> regions;  // by increasing region id
  UncomparedCounts uncompared;
};

// Statistics and verdict of compared points (equal-length vectors).
ResidualStatistics residual_statistics(const std::vector<double>& predicted,
                                       const std::vector<double>& measured,
                                       const std::vector<double>& sigma,
                                       const PredictionComparisonOptions& options);

// `region` holds each point's region id (may be empty); `dof` and
// `probe_radius` are the registration's. The prediction must belong to the
// part (check_prediction_against_part). Throws InputError for a negative or
// non-finite option.
PredictionComparison compare_with_prediction(const RegistrationResult& registration,
                                             const std::vector<std::optional<int>>& region,
                                             const Part& part, double probe_radius,
                                             const DegreesOfFreedom& dof,
                                             const Prediction& prediction,
                                             const PredictionComparisonOptions& options);

// Blunders the prediction explains. The registration calls a large
// deviation a blunder (not evaluated) when its neighbours do not deviate
// alike - true of a single probe point on a small predicted gouge, where the
// planner puts one on purpose. A blunder is an isolated deviation nothing
// explains; one whose residual against the prediction at that very spot is
// within within_sigmas sigma_total is a real deviation: it becomes a
// large_deviation (evaluated, still out of the fit) with a note in its
// outlier detail. Returns how many; compare again afterwards.
std::size_t admit_predicted_deviations(RegistrationResult& registration,
                                       const PredictionComparison& compared,
                                       const PredictionComparisonOptions& options);

}  // namespace furrow
