#include "machining/compensation/error_field.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

void check_options(const ErrorFieldOptions& o, const std::string& where) {
  if (o.fade_distance && !(std::isfinite(*o.fade_distance) && *o.fade_distance > 0))
    throw InputError(where + ": fade distance must be positive");
  if (!(std::isfinite(o.fade_factor) && o.fade_factor > 0))
    throw InputError(where + ": fade factor must be positive");
  if (o.min_samples < 4) throw InputError(where + ": at least 4 samples per face are needed for a field");
  if (o.scale_grid < 2) throw InputError(where + ": the scale grid needs at least 2 points a side");
  if (o.smoothing_length && !(std::isfinite(*o.smoothing_length) && *o.smoothing_length > 0))
    throw InputError(where + ": the smoothing length must be a positive number of mm");
  if (o.gcv.lambda && !(std::isfinite(*o.gcv.lambda) && *o.gcv.lambda > 0))
    throw InputError(where + ": smoothing lambda must be positive");
  if (o.gcv.grid_points < 3 || o.gcv.max_iterations < 0 || !(o.gcv.tolerance > 0))
    throw InputError(where + ": bad GCV search settings");
}

}  // namespace

FaceErrorField::FaceErrorField(const Face& face, std::vector<FieldSample> samples,
                               const ErrorFieldOptions& options, const std::string& where)
    : samples_(std::move(samples)) {
  check_options(options, where);
  if (samples_.size() > options.max_samples)
    throw InputError(where + ": " + std::to_string(samples_.size()) + " samples on face '" +
                     face.name() + "', more than the " + std::to_string(options.max_samples) +
                     " one error field may hold");
  for (const FieldSample& s : samples_)
    if (!std::isfinite(s.u) || !std::isfinite(s.v) || !std::isfinite(s.value))
      throw InputError(where + ": a non-finite sample on face '" + face.name() + "'");

  // Mean |S_u| and |S_v| over a grid of the parameter rectangle.
  const ParameterDomain& dom = face.domain();
  u0_ = dom.u0, v0_ = dom.v0;
  double su = 0, sv = 0;
  const int g = options.scale_grid;
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      const double u = dom.u0 + dom.width_u() * i / (g - 1);
      const double v = dom.v0 + dom.width_v() * j / (g - 1);
      const SurfaceDerivatives d = face.surface().evaluate(u, v, 1);
      su += d.Su.norm(), sv += d.Sv.norm();
    }
  scale_u_ = su / (g * g), scale_v_ = sv / (g * g);
  if (!(scale_u_ > 0) || !(scale_v_ > 0)) scale_u_ = scale_v_ = 1;  // a collapsed face: parameters as they are

  std::vector<Eigen::Vector2d> points;
  std::vector<double> values;
  std::vector<Eigen::Vector3d> points3;
  for (const FieldSample& s : samples_) {
    points.push_back(scaled(s.u, s.v));
    points3.emplace_back(points.back().x(), points.back().y(), 0.0);
    values.push_back(s.value);
  }
  search_ = std::make_unique<PointSearch>(points3);
  if (samples_.size() >= 2) {
    std::vector<double> spacing;
    for (const Eigen::Vector3d& p : points3) spacing.push_back(search_->nearest(p, 2).back().distance);
    std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
    median_spacing_ = spacing[spacing.size() / 2];
  }
  fade_distance_ = options.fade_distance ? *options.fade_distance : options.fade_factor * median_spacing_;

  if (samples_.empty()) {
    status_ = "no samples";
  } else if (samples_.size() < options.min_samples) {
    status_ = std::to_string(samples_.size()) + " samples, fewer than " + std::to_string(options.min_samples);
  } else if (!(fade_distance_ > 0)) {
    status_ = "samples all at one point";
  } else {
    GcvSearchOptions gcv = options.gcv;
    if (options.smoothing_length) {
      Eigen::AlignedBox2d box;
      for (const Eigen::Vector2d& p : points) box.extend(p);
      const double area = std::max(box.sizes().prod(), median_spacing_ * median_spacing_);
      // The spline's kernel is r^2 log r, 8 pi times the bending energy's
      // Green function, so its lambda is 8 pi times the lambda of J.
      gcv.lambda = 8 * kPi * std::pow(*options.smoothing_length, 4) / area;
    }
    spline_ = std::make_unique<ThinPlateSpline>(std::move(points), values, gcv);
    status_ = spline_->status();
  }
}

Eigen::Vector2d FaceErrorField::scaled(double u, double v) const {
  return {(u - u0_) * scale_u_, (v - v0_) * scale_v_};
}

double FaceErrorField::fade_weight(double distance) const {
  const double D = fade_distance_;
  if (distance <= 0.5 * D) return 1;
  if (distance >= D) return 0;
  const double q = (2 * distance - D) / D;
  return 1 - q * q * (3 - 2 * q);
}

double FaceErrorField::fade_slope(double distance) const {
  const double D = fade_distance_;
  if (distance <= 0.5 * D || distance >= D) return 0;
  const double q = (2 * distance - D) / D;
  return 6 * q * (q - 1) * 2 / D;
}

FieldValue FaceErrorField::at(double u, double v) const {
  FieldValue out;
  out.distance = std::numeric_limits<double>::infinity();
  if (!fitted()) return out;
  const Eigen::Vector2d x = scaled(u, v);
  const PointNeighbour nearest = search_->nearest(Eigen::Vector3d(x.x(), x.y(), 0.0));
  out.distance = nearest.distance;
  out.weight = fade_weight(out.distance);
  Eigen::Vector2d g;
  out.fitted = spline_->value(x, g);
  out.value = out.weight * out.fitted;
  // In (s, t), then by the chain rule ds/du = scale_u, dt/dv = scale_v.
  g *= out.weight;
  const double slope = fade_slope(out.distance);
  if (slope != 0) {
    const Eigen::Vector3d& p = search_->point(nearest.index);
    g += out.fitted * slope * (x - Eigen::Vector2d(p.x(), p.y())) / out.distance;
  }
  out.gradient = {g.x() * scale_u_, g.y() * scale_v_};
  return out;
}

double FaceErrorField::standard_error(double u, double v) const {
  return fitted() ? spline_->standard_error(scaled(u, v)) : 0.0;
}

ErrorField fit_face_fields(const Part& part, std::vector<std::vector<FieldSample>> by_face,
                           const ErrorFieldOptions& options, const std::string& where) {
  ErrorField field;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    std::vector<FieldSample> samples = f < by_face.size() ? std::move(by_face[f]) : std::vector<FieldSample>{};
    field.faces.push_back(std::make_unique<FaceErrorField>(part.faces[f], std::move(samples), options, where));
  }
  return field;
}

}  // namespace furrow
