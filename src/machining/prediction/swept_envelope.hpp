#pragma once
// The machined surface left by one straight cutting move: the lower envelope
// of the cutter swept from one tool tip to the next (docs/architecture.md "Machining
// error between contact points").
//
// With the tip moving on T(s) = T0 + s (T1 - T0), s in [0, 1], and the
// cutter's lower envelope height_at(rho) (cutter.hpp), the swept envelope is
//   z_env(x, y) = min over s of  T(s).z + height_at(|(x, y) - T_xy(s)|),
// +infinity where no position of the cutter is above (x, y) (outside the
// move's "shadow", the stadium of radius R around the projected segment).
// The swept solid is the Minkowski sum of a convex cutter and a segment, so
// z_env is a convex function of (x, y), and for a fixed (x, y) the function
// of s is convex on the interval where the cutter reaches (x, y):
// height_at is convex and nondecreasing, the distance is convex in s, T.z is
// linear. Hence:
//   - ball (r = R): closed form. The swept ball is a capsule; in the frame
//     of the projected move (along-track t, cross-track delta) the stationary
//     point of s -> C.z(s) - sqrt(R^2 - d(s)^2) is
//        sigma* = t - D.z * sqrt(R^2 - delta^2) / |D|,
//     (sigma = distance travelled horizontally, D = T1 - T0), clamped to the
//     move; convexity makes the clamped point the minimum.
//   - flat end mill (r = 0): the envelope is the tip height wherever the
//     bottom disc reaches, so the minimum is at the end of the reachable
//     interval on the descending side: exact.
//   - bull-nose: Brent's bracketed minimisation on the reachable interval
//     (scalar_search.hpp), tolerance and cap in EnvelopeOptions.
// Moves with almost no horizontal travel (under `vertical_tolerance`) are
// plunges: the envelope is the lower tip's cutter.
//
// The Cutter is referenced, not copied: it must outlive the envelope. Units
// are millimetres in the part frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "machining/cutter/cutter.hpp"

namespace furrow {

struct EnvelopeOptions {
  // Bull-nose minimisation: tolerance on the horizontal position along the
  // move [mm] and iteration cap. The height error is about the tolerance
  // times the move's slope (the function is convex, the minimum may sit at
  // an end of the interval), so 1e-9 mm keeps it far below a nanometre.
  double along_tolerance = 1e-9;
  int max_iterations = 200;
  // Horizontal travel below this is a plunge (pure z move) [mm].
  double vertical_tolerance = 1e-9;
};

struct EnvelopePoint {
  double z = std::numeric_limits<double>::infinity();  // +inf: not under the cutter
  double s = 0;            // move parameter of the lowest cutter position, [0, 1]
  bool converged = true;   // false only if a bull-nose search hit its cap
  int iterations = 0;
};

class SweptEnvelope {
 public:
  SweptEnvelope(const Cutter& cutter, const Eigen::Vector3d& from_tip, const Eigen::Vector3d& to_tip,
                const EnvelopeOptions& options = {});

  // z_env(x, y) [mm]; +infinity outside the shadow.
  double height_at(double x, double y) const {
    return ball_ ? ball_height(x, y) : evaluate(x, y).z;
  }
  // With the parameter of the lowest position and the search's status.
  EnvelopePoint evaluate(double x, double y) const;

  // z_env at the n points (x0 + k dx, y), k = 0..n-1, into out[k]: the z-map's
  // inner loop (the ball's closed form runs branch-free, so it vectorises).
  void row(double y, double x0, double dx, int n, double* out) const { row(y, x0, dx, 0, n, out); }
  // The same for k = k0..k0+n-1 into out[k - k0]; each value is bit for bit
  // what the whole row from x0 gives at k (the z-map evaluates a row in
  // pieces and must not depend on where a piece starts).
  void row(double y, double x0, double dx, int k0, int n, double* out) const;
  // A lower bound of z_env over the points x0 + k dx, k = ka..kb, of the row
  // y, all inside the shadow; -infinity when there is none. For the ball:
  // the envelope is convex along the row (the header), so it lies above its
  // tangents at the two ends, and the lowest point of the larger tangent
  // bounds it from below (-infinity near the shadow's rim, where the slope
  // is unbounded). Other cutters and plunges: the lower tip plus the
  // profile at the distance between the piece and the move's projection
  // (tight for short moves). The z-map skips a piece of a row where the
  // bound is above every node's height so far: cheaper than the row.
  double row_lower_bound(double y, double x0, double dx, int ka, int kb) const;

  // A lower bound of z_env anywhere on the rows from y_lo to y_hi (any
  // cutter): the lower tip plus the profile at the distance between that
  // strip and the move's projection. One square root for the whole strip:
  // the z-map skips a band of rows, or a row, where it is above every
  // node's height so far before bounding it piece by piece (on a raster,
  // the neighbouring passes' rows: most of them).
  double strip_floor(double y_lo, double y_hi) const {
    const double lo = std::min(from_.y(), to_.y()), hi = std::max(from_.y(), to_.y());
    const double gap = hi < y_lo ? y_lo - hi : lo > y_hi ? lo - y_hi : 0.0;
    return low_z_ + cutter_->height_at(std::min(gap, cutter_->radius()));
  }

  // A lower bound of z_env over the rectangle `area` (any cutter): the lower
  // tip plus the profile at the distance between the rectangle and the
  // move's projection, as row_lower_bound for non-ball cutters. Lets a
  // caller skip a patch of surface whose top is not above it.
  double lower_bound(const Eigen::AlignedBox2d& area) const;

  // The x interval of the shadow on the row y: false when the row misses it.
  bool row_span(double y, double& x_lo, double& x_hi) const;
  // Bounding box of the shadow (the two end discs).
  Eigen::AlignedBox2d shadow_box() const;

  const Eigen::Vector3d& from() const { return from_; }
  const Eigen::Vector3d& to() const { return to_; }
  bool is_ball() const { return ball_; }

 private:
  double ball_height(double x, double y) const {
    const double wx = x - from_.x(), wy = y - from_.y();
    const double radius = cutter_->radius();
    if (plunge_) {
      const double q = radius * radius - (wx * wx + wy * wy);
      return q < 0 ? kInf : low_z_ + radius - std::sqrt(q);
    }
    const double t = wx * ux_ + wy * uy_;     // along track
    const double delta = wy * ux_ - wx * uy_;  // across track
    const double rho2 = radius * radius - delta * delta;
    if (rho2 < 0) return kInf;
    double sigma = t - dz_over_length_ * std::sqrt(rho2);
    sigma = sigma < 0 ? 0 : (sigma > travel_ ? travel_ : sigma);
    const double xc = sigma - t;
    const double rem = rho2 - xc * xc;
    if (rem < 0) return kInf;
    return from_.z() + sigma * slope_ + radius - std::sqrt(rem);
  }

  static constexpr double kInf = std::numeric_limits<double>::infinity();
  const Cutter* cutter_;
  EnvelopeOptions options_;
  Eigen::Vector3d from_, to_;
  bool ball_ = false;
  bool plunge_ = false;
  double ux_ = 1, uy_ = 0;         // unit horizontal direction of travel
  double travel_ = 0;              // horizontal length e [mm]
  double slope_ = 0;               // dz per mm of horizontal travel
  double dz_over_length_ = 0;      // D.z / |D|
  double low_z_ = 0;               // lower end's tip height (plunges)
};

}  // namespace furrow
