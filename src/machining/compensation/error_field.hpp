#pragma once
// The systematic error field of a part: per face, a smooth function of
// (u, v) fitted to measured errors (docs/compensation.md "The error field").
//
// Values: the signed error of docs/architecture.md "Conventions" [mm]
// (+ material left, - overcut), with what the prediction explains already
// removed by the caller (inspection/comparison_error_field.hpp builds the
// samples from a comparison).
//
// Parameters to millimetres. A thin-plate spline is isotropic in its
// coordinates, while (u, v) are parameters whose unit differs per face and
// per direction. Each face's (u, v) are therefore scaled to
//   s = (u - u0) * mean|S_u|,  t = (v - v0) * mean|S_v|
// with the means taken over a `scale_grid` x `scale_grid` grid of the
// parameter rectangle: a length in (s, t) is a surface length [mm] where the
// parameterisation is near uniform and orthogonal. Where it is not (|S_u|
// varying a lot over the face, a skewed patch) distances are distorted by
// that ratio: a limit stated in docs/compensation.md.
//
// The fade. The fit is trusted only near the samples. With d the distance
// in (s, t) from a point to its nearest sample and D the fade distance
// (`fade_distance` if given, else `fade_factor` times the median
// nearest-neighbour spacing of the samples), the field applied is
//   weight(d) * f(s, t),  weight = 1 for d <= D/2, 0 for d >= D,
//   and 1 - 3 q^2 + 2 q^3 with q = (2d - D) / D between (C1: its slope is
//   0 at both ends),
// so it never extrapolates further than D from a measured point.
//
// Failure: a face with too few samples (below `min_samples`) or samples
// on one line gets no fit (`fitted` false, `status` says why) and a zero
// field. More than `max_samples` on one face is an InputError naming
// `where` (the spline keeps n x n matrices: 2000 samples take ~100 MB).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "geometry/point_search.hpp"
#include "machining/compensation/thin_plate_spline.hpp"

namespace furrow {

struct ErrorFieldOptions {
  GcvSearchOptions gcv;
  std::optional<double> fade_distance;  // D [mm] (> 0); unset: fade_factor x median spacing
  // h [mm] (> 0): a fixed smoothing instead of GCV's, as a length on the
  // face. With the samples spread over an area A [mm^2] (their box in
  // (s, t)), (1/n) sum of squares ~ (1/A) integral, so the fit damps a
  // wave of angular frequency w by 1 / (1 + lambda_J A w^4), lambda_J the
  // weight of the bending energy J: lambda_J = h^4 / A halves a wave of
  // wavelength 2 pi h. The spline's kernel r^2 log r is 8 pi times J's
  // Green function, so its lambda is 8 pi h^4 / A. Overrides gcv.lambda.
  std::optional<double> smoothing_length;
  // > 0. Full weight reaches D/2 = 3 spacings: scattered samples leave
  // holes wider than their median spacing (250 uniform points: the largest
  // empty circle has a radius ~2.8 median spacings), which must not fade.
  double fade_factor = 6;
  std::size_t min_samples = 6;          // fewer on a face: no field there (>= 4)
  std::size_t max_samples = 2000;       // work cap per face
  int scale_grid = 9;                   // grid for mean |S_u|, |S_v| (>= 2)
};

struct FieldSample {
  double u = 0, v = 0;  // on the face
  double value = 0;     // error [mm]
};

// The field at one point of a face.
struct FieldValue {
  double value = 0;     // weight * fitted: what compensation applies [mm]
  double fitted = 0;    // the spline, unfaded [mm]
  double weight = 0;    // fade weight in [0, 1]
  double distance = 0;  // to the nearest sample in (s, t) [mm]; +inf without samples
  // d value / d(u, v) [mm per unit parameter]: the spline's slope times the
  // weight plus the fade's slope times the spline (the fade is C1, so this
  // is continuous except where the nearest sample changes inside the taper).
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
};

class FaceErrorField {
 public:
  // Fits the samples of face `face` (their (u, v) on it). Throws InputError
  // naming `where` for more than max_samples or a non-finite sample, or a
  // bad option.
  FaceErrorField(const Face& face, std::vector<FieldSample> samples,
                 const ErrorFieldOptions& options, const std::string& where);

  bool fitted() const { return spline_ != nullptr && spline_->fitted(); }
  const std::string& status() const { return status_; }
  std::size_t samples() const { return samples_.size(); }
  const std::vector<FieldSample>& sample_list() const { return samples_; }
  double scale_u() const { return scale_u_; }  // mean |S_u| [mm per unit u]
  double scale_v() const { return scale_v_; }
  double median_spacing() const { return median_spacing_; }  // [mm]; 0 below 2 samples
  double fade_distance() const { return fade_distance_; }    // D [mm]
  // The spline's GCV result; null when not fitted.
  const GcvResult* gcv() const { return fitted() ? &spline_->gcv() : nullptr; }

  // (s, t) [mm] of (u, v).
  Eigen::Vector2d scaled(double u, double v) const;
  FieldValue at(double u, double v) const;
  double value(double u, double v) const { return at(u, v).value; }
  // One standard error of the fitted (unfaded) spline at (u, v) [mm]; 0
  // when not fitted. O(samples^2).
  double standard_error(double u, double v) const;
  // The fade weight at distance d and its slope d weight / d distance
  // [1/mm] (exposed for tests and reports).
  double fade_weight(double distance) const;
  double fade_slope(double distance) const;

 private:
  std::vector<FieldSample> samples_;
  double u0_ = 0, v0_ = 0, scale_u_ = 1, scale_v_ = 1;
  double median_spacing_ = 0, fade_distance_ = 0;
  std::string status_;
  std::unique_ptr<ThinPlateSpline> spline_;
  std::unique_ptr<PointSearch> search_;  // samples in (s, t, 0)
};

// Every face's field, by face index (a face without samples has an empty
// field: status "no samples", value 0 everywhere).
struct ErrorField {
  std::vector<std::unique_ptr<FaceErrorField>> faces;
  double value(std::size_t face, double u, double v) const {
    return face < faces.size() && faces[face] ? faces[face]->value(u, v) : 0.0;
  }
};

// Fits one field per face of `part` from samples grouped by face index
// (`by_face.size()` == part.faces.size()).
ErrorField fit_face_fields(const Part& part, std::vector<std::vector<FieldSample>> by_face,
                           const ErrorFieldOptions& options, const std::string& where);

}  // namespace furrow
