// A boundary edge's curve in a periodic surface's parameters (contract in
// cad_projected_curve.hpp).
#include "io/cad/occt/cad_projected_curve.hpp"

#include <Geom_Surface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

#include "base/numbers.hpp"

namespace furrow::cad {

namespace {

constexpr int kSamples = 32;          // reference samples along an edge
constexpr double kPoleLength = 1e-7;  // [mm] a parameter circle shorter than this is a pole
constexpr double kProjection = 1e-9;  // [mm] ShapeAnalysis_Surface's precision
constexpr int kNewtonSteps = 4;       // Gauss-Newton steps after it
constexpr int kPassageSamples = 64;   // samples searched for a pole passage
constexpr int kGoldenSteps = 200;     // golden-section steps refining one
constexpr double kPassageLength = 1e-6;  // [mm] circle length below which the curve passes the pole

// Length of the shortest periodic parameter circle through the surface
// point nearest to p: ~2 pi times its distance from the axis on a surface
// of revolution, 0 at a pole; +inf on a surface without a periodic parameter.
double circle_length(const Handle(ShapeAnalysis_Surface)& surface, const gp_Pnt& p, const Eigen::Vector2d& periods) {
  const gp_Pnt2d q = surface->ValueOfUV(p, kProjection);
  gp_Pnt at;
  gp_Vec du, dv;
  surface->Surface()->D1(q.X(), q.Y(), at, du, dv);
  double length = std::numeric_limits<double>::infinity();
  if (periods.x() > 0) length = std::min(length, du.Magnitude() * periods.x());
  if (periods.y() > 0) length = std::min(length, dv.Magnitude() * periods.y());
  return length;
}

}  // namespace

ProjectedCurve::ProjectedCurve(Handle(Geom_Curve) curve, Handle(ShapeAnalysis_Surface) surface, double from,
                               double to, const Eigen::Vector2d& periods, bool start_pole, bool end_pole)
    : curve_(std::move(curve)), surface_(std::move(surface)), periods_(periods),
      start_pole_(start_pole), end_pole_(end_pole) {
  for (int k = 0; k <= kSamples; ++k) {
    Sample s;
    s.t = from + (to - from) * k / kSamples;
    s.uv = raw(s.t, s.pole);
    samples_.push_back(s);
  }
  samples_.front().pole = samples_.front().pole || start_pole_;
  samples_.back().pole = samples_.back().pole || end_pole_;
  // Unwrap the periodic parameters along the curve; a pole takes its
  // neighbours' value (the nearest sample that is not one).
  const Sample* previous = nullptr;
  for (Sample& s : samples_) {
    if (s.pole) continue;
    if (previous)
      for (int d = 0; d < 2; ++d)
        if (periods_[d] > 0) s.uv[d] += std::round((previous->uv[d] - s.uv[d]) / periods_[d]) * periods_[d];
    previous = &s;
  }
  collapsed_ = previous == nullptr;
  if (collapsed_) return;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    if (!samples_[k].pole) continue;
    std::size_t nearest = 0;
    long best = -1;
    for (std::size_t j = 0; j < samples_.size(); ++j) {
      const long distance = std::labs(static_cast<long>(j) - static_cast<long>(k));
      if (!samples_[j].pole && (best < 0 || distance < best)) nearest = j, best = distance;
    }
    for (int d = 0; d < 2; ++d)
      if (periods_[d] > 0) samples_[k].uv[d] = samples_[nearest].uv[d];
  }
}

Eigen::Vector2d ProjectedCurve::raw(double t, bool& pole) const {
  const gp_Pnt p = curve_->Value(t);
  const gp_Pnt2d q = surface_->ValueOfUV(p, kProjection);
  Eigen::Vector2d uv(q.X(), q.Y());
  gp_Pnt at;
  gp_Vec du, dv;
  surface_->Surface()->D1(uv.x(), uv.y(), at, du, dv);
  pole = (periods_.x() > 0 && du.Magnitude() * periods_.x() < kPoleLength) ||
         (periods_.y() > 0 && dv.Magnitude() * periods_.y() < kPoleLength);
  if (pole) return uv;
  // ShapeAnalysis_Surface stops at its precision on surfaces it solves
  // numerically (a surface of revolution): a few Gauss-Newton steps on the
  // distance take the parameters to rounding, so that a curve along the
  // seam lands on it and the face spans exactly one period.
  for (int k = 0; k < kNewtonSteps; ++k) {
    Eigen::Matrix<double, 3, 2> J;
    J << du.X(), dv.X(), du.Y(), dv.Y(), du.Z(), dv.Z();
    const Eigen::Vector3d r(p.X() - at.X(), p.Y() - at.Y(), p.Z() - at.Z());
    const Eigen::Matrix2d normal = J.transpose() * J;
    if (!(std::abs(normal.determinant()) > 1e-300)) break;
    const Eigen::Vector2d step = normal.ldlt().solve(J.transpose() * r);
    if (!step.allFinite()) break;
    uv += step;
    surface_->Surface()->D1(uv.x(), uv.y(), at, du, dv);
    if (step.norm() < 1e-15) break;
  }
  return uv;
}

Eigen::Vector2d ProjectedCurve::reference(double t) const {
  const double from = samples_.front().t, to = samples_.back().t;
  const double x = to == from ? 0.0 : std::clamp((t - from) / (to - from), 0.0, 1.0) * kSamples;
  const int i = std::min(static_cast<int>(x), kSamples - 1);
  const double a = x - i;
  return (1 - a) * samples_[static_cast<std::size_t>(i)].uv + a * samples_[static_cast<std::size_t>(i + 1)].uv;
}

Eigen::Vector2d ProjectedCurve::uv(double t) const {
  bool pole = false;
  Eigen::Vector2d q = raw(t, pole);
  // A declared pole end takes its piece's parameter even where rounding
  // puts the curve's point a hair off the axis.
  pole = pole || (start_pole_ && t == samples_.front().t) || (end_pole_ && t == samples_.back().t);
  const Eigen::Vector2d ref = reference(t);
  for (int d = 0; d < 2; ++d) {
    if (!(periods_[d] > 0)) continue;
    q[d] = pole ? ref[d] : q[d] + std::round((ref[d] - q[d]) / periods_[d]) * periods_[d];
  }
  return q;
}

Eigen::Vector4d ProjectedCurve::box() const {
  // A periodic parameter is ill-conditioned near a pole (a 3-D error of e mm
  // moves it by e over the circle's radius): each point widens the box only
  // as far as it lies kBoxTolerance mm beyond it on the surface, so that a
  // curve along the seam that strays from it by rounding near a pole does
  // not make the face wider than a period.
  constexpr int kDense = 512;
  constexpr double kBoxTolerance = 1e-8;  // [mm]
  const double from = samples_.front().t, to = samples_.back().t;
  Eigen::Vector4d b(1e300, 1e300, -1e300, -1e300);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int k = 0; k <= kDense; ++k) {
    const Eigen::Vector2d q = uv(from + (to - from) * k / kDense);
    mean += q / (kDense + 1);
    gp_Pnt at;
    gp_Vec du, dv;
    surface_->Surface()->D1(q.x(), q.y(), at, du, dv);
    const Eigen::Vector2d speed(du.Magnitude(), dv.Magnitude());
    for (int d = 0; d < 2; ++d) {
      const double slack = periods_[d] > 0 ? (speed[d] > 0 ? kBoxTolerance / speed[d] : 1e300) : 0.0;
      b[d] = std::min(b[d], q[d] + slack);
      b[d + 2] = std::max(b[d + 2], q[d] - slack);
    }
  }
  for (int d = 0; d < 2; ++d)
    if (b[d] > b[d + 2]) b[d] = b[d + 2] = std::clamp(mean[d], b[d + 2], b[d]);
  return b;
}

std::vector<double> pole_passages(const Handle(Geom_Curve)& curve, const Handle(ShapeAnalysis_Surface)& surface,
                                  double from, double to, const Eigen::Vector2d& periods) {
  std::vector<double> passages;
  if (!(periods.x() > 0 || periods.y() > 0) || from == to) return passages;
  auto length_at = [&](double t) { return circle_length(surface, curve->Value(t), periods); };
  std::vector<double> t(kPassageSamples + 1), length(kPassageSamples + 1);
  for (int k = 0; k <= kPassageSamples; ++k) {
    t[static_cast<std::size_t>(k)] = from + (to - from) * k / kPassageSamples;
    length[static_cast<std::size_t>(k)] = length_at(t[static_cast<std::size_t>(k)]);
  }
  const gp_Pnt start = curve->Value(from), end = curve->Value(to);
  for (std::size_t k = 1; k < t.size() - 1; ++k) {
    if (!(length[k] <= length[k - 1] && length[k] < length[k + 1])) continue;  // not a local minimum
    // A curve through a pole passes it within its samples' spacing: farther
    // off, the minimum is a circle the curve only runs along (or rounding).
    const double spacing = curve->Value(t[k - 1]).Distance(curve->Value(t[k + 1]));
    if (!(length[k] <= 2 * kPi * spacing)) continue;
    // Golden-section search for the shortest circle between the neighbours.
    const double ratio = 0.5 * (std::sqrt(5.0) - 1);
    double a = t[k - 1], b = t[k + 1];
    double c = b - ratio * (b - a), d = a + ratio * (b - a);
    double lc = length_at(c), ld = length_at(d);
    for (int step = 0; step < kGoldenSteps && std::abs(b - a) > 1e-15 * (std::abs(a) + std::abs(b) + 1); ++step) {
      if (lc <= ld) {
        b = d, d = c, ld = lc;
        c = b - ratio * (b - a), lc = length_at(c);
      } else {
        a = c, c = d, lc = ld;
        d = a + ratio * (b - a), ld = length_at(d);
      }
    }
    const double best = lc <= ld ? c : d;
    if (!(std::min(lc, ld) < kPassageLength)) continue;
    const gp_Pnt p = curve->Value(best);
    if (p.Distance(start) < kPassageLength || p.Distance(end) < kPassageLength) continue;  // an end, not a passage
    if (!passages.empty() && std::abs(best - passages.back()) <= 1e-12 * std::abs(to - from)) continue;
    passages.push_back(best);
  }
  return passages;
}

}  // namespace furrow::cad
