#include "machining/prediction/cross_section_scallop.hpp"

#include <cmath>
#include <limits>

#include "machining/prediction/normal_error.hpp"
#include "base/scalar_search.hpp"

namespace furrow {

namespace {

constexpr double kFlatCurvature = 1e-9;

// The cross-section: arc-length parameter sigma, x across, z up.
struct Section {
  double k, tilt;
  void at(double sigma, Eigen::Vector2d& p, Eigen::Vector2d& n) const {
    if (std::fabs(k) < kFlatCurvature) {
      n = {std::sin(tilt), std::cos(tilt)};
      p = sigma * Eigen::Vector2d(std::cos(tilt), -std::sin(tilt));
      return;
    }
    const double rho = 1 / std::fabs(k);
    const Eigen::Vector2d n0(std::sin(tilt), std::cos(tilt));
    if (k < 0) {  // convex: normal away from the centre
      const double phi = tilt + sigma / rho;
      n = {std::sin(phi), std::cos(phi)};
      p = -rho * n0 + rho * n;
    } else {  // concave: normal toward the centre
      const double phi = tilt - sigma / rho;
      n = {std::sin(phi), std::cos(phi)};
      p = rho * n0 - rho * n;
    }
  }
};

// Tip of the cutter touching at p with normal n (cutter_location.hpp in the
// plane); at a horizontal contact the axis goes to +x, the same side for
// both passes, as cutter_location's fixed horizontal side does.
Eigen::Vector2d tip_at(const Cutter& c, const Eigen::Vector2d& p, const Eigen::Vector2d& n) {
  const double side = std::fabs(n.x()) > 1e-12 ? (n.x() > 0 ? 1.0 : -1.0) : 1.0;
  return p + c.corner_radius() * n + Eigen::Vector2d(c.flat_radius() * side, -c.corner_radius());
}

}  // namespace

std::optional<double> cutter_scallop_height(const Cutter& cutter, double k, double tilt, double w,
                                            const CrossSectionOptions& options, double first) {
  if (cutter.corner_radius() == cutter.radius()) return ball_scallop_height(cutter.radius(), k, w);
  if (!(w > 0)) return 0.0;
  const Section s{k, tilt};
  Eigen::Vector2d pa, na, pb, nb;
  const double sa = first * w, sb = (first + 1) * w;
  s.at(sa, pa, na);
  s.at(sb, pb, nb);
  if (!(na.y() > 0) || !(nb.y() > 0)) return std::nullopt;
  const Eigen::Vector2d ta = tip_at(cutter, pa, na), tb = tip_at(cutter, pb, nb);
  const double R = cutter.radius();
  auto envelope = [&](double x, double) {
    const double da = std::fabs(x - ta.x()), db = std::fabs(x - tb.x());
    double z = std::numeric_limits<double>::infinity();
    if (da <= R) z = ta.y() + cutter.height_at(da);
    if (db <= R) z = std::min(z, tb.y() + cutter.height_at(db));
    return z;
  };
  NormalErrorOptions normal;
  normal.max_distance = 4 * R;
  bool ridge = true;
  auto error = [&](double sigma) {
    Eigen::Vector2d p, n;
    s.at(sigma, p, n);
    const NormalError e = normal_error(envelope, Eigen::Vector3d(p.x(), 0, p.y()), Eigen::Vector3d(n.x(), 0, n.y()), normal);
    if (!e.reached) ridge = false;
    return e.reached ? e.error : 0.0;
  };
  const int n = std::max(4, options.samples);
  int best_k = 0;
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    const double e = error(sa + w * i / n);
    if (e > best) best = e, best_k = i;
  }
  if (!ridge) return std::nullopt;  // the two cutters leave a gap between them
  double centre = sa + w * best_k / n;
  // The ridge is where the two envelopes cross; it can be narrower than the
  // samples (a bull-nose's flat bottoms leave only a sliver): find it
  // directly and refine around it if it beats the samples.
  if (ta.x() < tb.x()) {
    auto diff = [&](double x) {
      const double za = ta.y() + cutter.height_at(std::min(std::fabs(x - ta.x()), R));
      const double zb = tb.y() + cutter.height_at(std::min(std::fabs(x - tb.x()), R));
      return za - zb;
    };
    double lo = ta.x(), hi = tb.x();
    if (diff(lo) <= 0 && diff(hi) >= 0) {
      for (int it = 0; it < 200 && hi - lo > 1e-12 * R; ++it) {
        const double mid = 0.5 * (lo + hi);
        (diff(mid) <= 0 ? lo : hi) = mid;
      }
      double a = sa, b = sb;  // the arc point under the ridge (x grows along the arc)
      for (int it = 0; it < 200 && b - a > 1e-12 * w; ++it) {
        const double mid = 0.5 * (a + b);
        Eigen::Vector2d p, nn;
        s.at(mid, p, nn);
        (p.x() < lo ? a : b) = mid;
      }
      const double e = error(0.5 * (a + b));
      if (e > best) best = e, centre = 0.5 * (a + b);
    }
  }
  const double h = w / n;
  const double lo = std::max(sa, centre - h), hi = std::min(sb, centre + h);
  const ScalarSearchResult r = minimize_unimodal([&](double sigma) { return -error(sigma); }, lo, hi,
                                                 {options.ridge_tolerance, 100});
  return std::max(best, -r.value);
}

SideStepResult cutter_side_step_for_scallop(const Cutter& cutter, double k, double tilt, double height,
                                            const CrossSectionOptions& options, double first) {
  if (cutter.corner_radius() == cutter.radius())
    return ball_side_step_for_scallop(cutter.radius(), k, height, {options.side_step_tolerance / cutter.radius(),
                                                                   options.max_iterations});
  SideStepResult result;
  if (!(height > 0)) return result;
  auto below = [&](double w) {
    const auto h = cutter_scallop_height(cutter, k, tilt, w, options, first);
    return h && *h <= height;
  };
  // Cutters of diameter 2R overlap only while w < 2R (flat case); curved
  // sections move that bound by at most a factor of a few.
  double lo = 0, hi = 2 * cutter.radius();
  while (below(hi) && hi < 64 * cutter.radius()) lo = hi, hi *= 2;
  result.feasible = true;
  const ScalarSearchResult s =
      largest_satisfying(below, lo, hi, {options.side_step_tolerance, options.max_iterations});
  result.side_step = s.x;
  result.converged = s.converged;
  result.iterations = s.iterations;
  return result;
}

}  // namespace furrow
