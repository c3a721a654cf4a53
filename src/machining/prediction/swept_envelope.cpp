#include "machining/prediction/swept_envelope.hpp"

#include <algorithm>

#include "base/scalar_search.hpp"

namespace furrow {

SweptEnvelope::SweptEnvelope(const Cutter& cutter, const Eigen::Vector3d& from_tip,
                             const Eigen::Vector3d& to_tip, const EnvelopeOptions& options)
    : cutter_(&cutter), options_(options), from_(from_tip), to_(to_tip) {
  ball_ = cutter.corner_radius() == cutter.radius();
  const Eigen::Vector3d d = to_tip - from_tip;
  travel_ = std::hypot(d.x(), d.y());
  low_z_ = std::min(from_tip.z(), to_tip.z());
  plunge_ = !(travel_ > options.vertical_tolerance);
  if (!plunge_) {
    ux_ = d.x() / travel_;
    uy_ = d.y() / travel_;
    slope_ = d.z() / travel_;
    dz_over_length_ = d.z() / d.norm();
  }
}

EnvelopePoint SweptEnvelope::evaluate(double x, double y) const {
  EnvelopePoint result;
  const double radius = cutter_->radius();
  const double wx = x - from_.x(), wy = y - from_.y();
  if (plunge_) {
    const double dist = std::hypot(wx, wy);
    if (dist > radius) return result;
    result.z = low_z_ + cutter_->height_at(dist);
    result.s = from_.z() <= to_.z() ? 0.0 : 1.0;
    return result;
  }
  const double t = wx * ux_ + wy * uy_;
  const double delta = wy * ux_ - wx * uy_;
  const double rho2 = radius * radius - delta * delta;
  if (rho2 < 0) return result;
  const double rho = std::sqrt(rho2);
  const double lo = std::max(0.0, t - rho), hi = std::min(travel_, t + rho);
  if (lo > hi) return result;
  if (ball_) {
    result.z = ball_height(x, y);
    double sigma = t - dz_over_length_ * rho;
    sigma = std::clamp(sigma, 0.0, travel_);
    result.s = sigma / travel_;
    return result;
  }
  if (cutter_->corner_radius() == 0) {
    // Flat end mill: height_at is 0 across the whole reachable interval, so
    // the lowest tip position there wins.
    const double sigma = slope_ >= 0 ? lo : hi;
    result.z = from_.z() + sigma * slope_;
    result.s = sigma / travel_;
    return result;
  }
  auto f = [&](double sigma) {
    const double dx = sigma - t;
    const double dist = std::min(std::sqrt(dx * dx + delta * delta), radius);
    return from_.z() + sigma * slope_ + cutter_->height_at(dist);
  };
  const ScalarSearchResult m =
      minimize_unimodal(f, lo, hi, {options_.along_tolerance, options_.max_iterations});
  result.z = m.value;
  result.s = m.x / travel_;
  result.converged = m.converged;
  result.iterations = m.iterations;
  return result;
}

void SweptEnvelope::row(double y, double x0, double dx, int k0, int n, double* out) const {
  if (!ball_ || plunge_) {
    for (int k = k0; k < k0 + n; ++k) out[k - k0] = height_at(x0 + k * dx, y);
    return;
  }
  const double radius = cutter_->radius(), r2 = radius * radius;
  const double wy = y - from_.y(), bx = x0 - from_.x();
  const double ux = ux_, uy = uy_, travel = travel_, k_rho = dz_over_length_;
  const double base = from_.z() + radius, slope = slope_;
  for (int k = k0; k < k0 + n; ++k) {
    const double wx = bx + k * dx;
    const double t = wx * ux + wy * uy;
    const double delta = wy * ux - wx * uy;
    const double rho2 = r2 - delta * delta;
    const double rho = std::sqrt(rho2 > 0 ? rho2 : 0.0);
    double sigma = t - k_rho * rho;
    sigma = sigma < 0 ? 0 : sigma;
    sigma = sigma > travel ? travel : sigma;
    const double xc = sigma - t;
    const double rem = rho2 - xc * xc;
    const double z = base + sigma * slope - std::sqrt(rem > 0 ? rem : 0.0);
    out[k - k0] = (rho2 < 0 || rem < 0) ? kInf : z;
  }
}

namespace {

// Distance from p to the segment [a, b] in the plane.
double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + s * d - p).norm();
}

// Distance between the segments [a, b] and [c, d] in the plane: 0 when they
// cross, else the least end-to-segment distance.
double segment_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                        const Eigen::Vector2d& d) {
  auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
  return std::min(std::min(point_segment_distance(a, c, d), point_segment_distance(b, c, d)),
                  std::min(point_segment_distance(c, a, b), point_segment_distance(d, a, b)));
}

}  // namespace

double SweptEnvelope::lower_bound(const Eigen::AlignedBox2d& area) const {
  if (area.isEmpty()) return kInf;
  const Eigen::Vector2d a = from_.head<2>(), b = to_.head<2>();
  // Zero when the projection enters the rectangle (an end inside, or it
  // crosses a side); otherwise the nearest of the four sides.
  double gap = 0;
  if (!area.contains(a) && !area.contains(b)) {
    using Corner = Eigen::AlignedBox2d;
    const Eigen::Vector2d c[4] = {area.corner(Corner::BottomLeft), area.corner(Corner::BottomRight),
                                  area.corner(Corner::TopRight), area.corner(Corner::TopLeft)};
    gap = kInf;
    for (int i = 0; i < 4; ++i) gap = std::min(gap, segment_distance(c[i], c[(i + 1) % 4], a, b));
  }
  return std::min(from_.z(), to_.z()) + cutter_->height_at(std::min(gap, cutter_->radius()));
}

double SweptEnvelope::row_lower_bound(double y, double x0, double dx, int ka, int kb) const {
  if (kb < ka) return -kInf;
  if (!ball_ || plunge_) {
    // Any cutter: no position is lower than the lower tip, and none is
    // nearer the piece than the move's projection is, where the profile
    // (nondecreasing) is lowest.
    const double gap = segment_distance(Eigen::Vector2d(x0 + ka * dx, y), Eigen::Vector2d(x0 + kb * dx, y),
                                        from_.head<2>(), to_.head<2>());
    const double radius = cutter_->radius();
    return std::min(from_.z(), to_.z()) + cutter_->height_at(std::min(gap, radius));
  }
  const double radius = cutter_->radius(), r2 = radius * radius;
  const double wy = y - from_.y(), bx = x0 - from_.x();
  // Height and slope along x at node k, as row() computes the height. The
  // slope is the sphere's at the lowest position (the minimum over the move
  // has the partial derivative at its minimiser as derivative); false near
  // the shadow's rim, where the slope is unbounded.
  auto tangent = [&](int k, double& z, double& g) {
    const double wx = bx + k * dx;
    const double t = wx * ux_ + wy * uy_;
    const double delta = wy * ux_ - wx * uy_;
    const double rho2 = r2 - delta * delta;
    if (!(rho2 > 0)) return false;
    double sigma = t - dz_over_length_ * std::sqrt(rho2);
    sigma = sigma < 0 ? 0 : (sigma > travel_ ? travel_ : sigma);
    const double xc = sigma - t;
    const double rem = rho2 - xc * xc;
    if (!(rem > 1e-6 * r2)) return false;
    const double root = std::sqrt(rem);
    z = from_.z() + radius + sigma * slope_ - root;
    g = (wx - sigma * ux_) / root;
    return true;
  };
  double za = 0, ga = 0, zb = 0, gb = 0;
  if (!tangent(ka, za, ga) || !tangent(kb, zb, gb)) return -kInf;
  // max(La, Lb) over [a, b] (a = 0, b = span): lowest at an end or where
  // the two lines cross.
  const double span = (kb - ka) * dx;
  double bound = std::min(std::max(za, zb - gb * span), std::max(za + ga * span, zb));
  if (ga < gb) {
    const double cross = (zb - gb * span - za) / (ga - gb);
    if (cross > 0 && cross < span) bound = std::min(bound, std::max(za + ga * cross, zb + gb * (cross - span)));
  }
  return std::isfinite(bound) ? bound : -kInf;
}

namespace {

// Intersects [lo, hi] with {x : a x + b in [c0, c1]}; false when empty.
bool clip_linear(double a, double b, double c0, double c1, double& lo, double& hi) {
  if (std::fabs(a) < 1e-15) return b >= c0 && b <= c1;
  double x0 = (c0 - b) / a, x1 = (c1 - b) / a;
  if (x0 > x1) std::swap(x0, x1);
  lo = std::max(lo, x0);
  hi = std::min(hi, x1);
  return lo <= hi;
}

}  // namespace

bool SweptEnvelope::row_span(double y, double& x_lo, double& x_hi) const {
  const double radius = cutter_->radius();
  bool any = false;
  x_lo = kInf;
  x_hi = -kInf;
  // The shadow is the union of the end discs and the band between them; its
  // slice by a row is one interval (the shadow is convex), the hull of the
  // pieces' slices.
  for (const Eigen::Vector3d* end : {&from_, &to_}) {
    const double dy = y - end->y();
    const double q = radius * radius - dy * dy;
    if (q < 0) continue;
    const double half = std::sqrt(q);
    x_lo = std::min(x_lo, end->x() - half);
    x_hi = std::max(x_hi, end->x() + half);
    any = true;
  }
  if (!plunge_) {
    double lo = -kInf, hi = kInf;
    const double dy = y - from_.y();
    // along = (x - x0) ux + dy uy in [0, e]; across = dy ux - (x - x0) uy in [-R, R].
    if (clip_linear(ux_, -from_.x() * ux_ + dy * uy_, 0.0, travel_, lo, hi) &&
        clip_linear(-uy_, from_.x() * uy_ + dy * ux_, -radius, radius, lo, hi) && lo <= hi &&
        std::isfinite(lo) && std::isfinite(hi)) {
      x_lo = std::min(x_lo, lo);
      x_hi = std::max(x_hi, hi);
      any = true;
    }
  }
  return any;
}

Eigen::AlignedBox2d SweptEnvelope::shadow_box() const {
  const double radius = cutter_->radius();
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector3d* end : {&from_, &to_}) {
    box.extend(Eigen::Vector2d(end->x() - radius, end->y() - radius));
    box.extend(Eigen::Vector2d(end->x() + radius, end->y() + radius));
  }
  return box;
}

}  // namespace furrow
