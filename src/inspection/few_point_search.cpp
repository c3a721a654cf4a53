#include "inspection/few_point_search.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "inspection/coarse_alignment.hpp"
#include "inspection/orientation_check.hpp"
#include "inspection/registration_run.hpp"

namespace furrow {

namespace {

// Normal score of the chi-square quantile that bounds an alternative's
// scatter (99.9 %, one-sided).
constexpr double kScatterScore = 3.09;

// Up to this many points without ids the global search is also run
// without each point in turn (search_few_points).
constexpr std::size_t kLeaveOutSearchPoints = 16;

// A converged fit, as the search compares them.
struct Candidate {
  double cost = 0;                  // sum of min(d^2, T^2) over all points
  std::vector<std::size_t> flagged; // left out by the outlier rule (not for want of a foot)
  double squares = 0;               // sum of d^2 over the points in the fit
  double nu = 0;                    // points in the fit less motions fitted
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  OtherOrientation orientation;     // the fit as another orientation of the kept one
};

Candidate describe(const RegistrationResult& r, const RegistrationOptions& o) {
  Candidate c;
  c.cost = fit_cost(r, o);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const RegisteredPoint& p = r.points[i];
    const bool footless = p.outlier == OutlierReason::no_foot_point || !std::isfinite(p.deviation);
    if (p.in_fit) {
      c.squares += p.deviation * p.deviation;
      c.nu += 1;
    } else if (!footless) {
      c.flagged.push_back(i);
    }
  }
  c.nu -= r.fitted_dof;
  c.transform = r.transform;
  c.orientation = orientation_of(r);
  return c;
}

// The points flagged by one fit and kept by the other (both sorted).
std::vector<std::size_t> exchanged(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  std::vector<std::size_t> out;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

double chi_square_quantile(double nu, double z) {
  const double h = 2 / (9 * nu);
  return nu * std::pow(std::max(0.0, 1 - h + z * std::sqrt(h)), 3);
}

RegistrationResult search_few_points(RegistrationResult first, const ClosestPointFinder& finder,
                                     const MeasurementSet& set, const InspectionPlan* plan,
                                     const RegistrationOptions& options) {
  const CoarseResult coarse = first.coarse;
  std::vector<Candidate> tried;
  RegistrationResult best = std::move(first);
  double lowest = std::numeric_limits<double>::infinity();
  if (best.converged) {
    tried.push_back(describe(best, options));
    lowest = tried.back().cost;
  }
  const auto consider = [&](RegistrationResult r, const Eigen::Isometry3d& start, bool search_start) {
    if (!r.converged) return;
    tried.push_back(describe(r, options));
    const double cost = tried.back().cost;
    if (!(cost < lowest * (1 - 1e-9))) return;  // ties to the earlier
    lowest = cost;
    const double median = r.coarse.median_distance;  // of this start
    r.coarse = coarse;
    if (search_start) {
      r.coarse.transform = start;
      r.coarse.median_distance = median;
    }
    best = std::move(r);
  };
  RegistrationOptions o = options;
  o.progress = nullptr;
  if (!options.start && coarse.method == CoarseMethod::global_search)
    for (const Eigen::Isometry3d& start : coarse.alternatives) {
      o.start = start;
      consider(run_registration(finder, set, plan, o), start, true);
    }
  // Very few points: one blunder can move the whole coarse search, so it
  // runs again without each point in turn, and the fit from its placement
  // leaves that point out of its first pass.
  if (!options.start && coarse.method == CoarseMethod::global_search &&
      set.points.size() <= kLeaveOutSearchPoints) {
    for (std::size_t i = 0; i < set.points.size(); ++i) {
      MeasurementSet without = set;
      without.points.erase(without.points.begin() + static_cast<std::ptrdiff_t>(i));
      const CoarseResult placed = coarse_global_search(finder, without, options.coarse);
      o.start = placed.transform;
      consider(run_registration(finder, set, plan, o, i), placed.transform, true);
    }
  }
  if (!best.converged) return best;
  if (!describe(best, options).flagged.empty()) {
    o.start = best.transform;
    const Eigen::Isometry3d from = best.transform;
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < best.points.size(); ++i)
      if (best.points[i].in_fit) kept.push_back(i);
    for (const std::size_t i : kept) consider(run_registration(finder, set, plan, o, i), from, false);
  }

  const Candidate final = describe(best, options);
  // Another orientation that explains the points about as well, decided on
  // the fits (orientation_check.hpp), not on the coarse scores: a search
  // without one point can find the other side of a flat part without
  // calling it ambiguous, and the search's own call can be wrong.
  if (coarse.method == CoarseMethod::global_search && !options.start) {
    // The other orientation reported is the cheapest that passes.
    const Candidate* other = nullptr;
    for (const Candidate& c : tried)
      if (another_orientation(final.transform, final.cost, c.transform, c.cost, options.coarse) &&
          (!other || c.cost < other->cost))
        other = &c;
    best.coarse.ambiguous = other != nullptr;
    best.other_orientation.reset();
    if (other) best.other_orientation = other->orientation;
  }
  if (final.flagged.empty() || !(final.nu >= 1)) return best;
  const double variance = final.squares / final.nu;
  std::vector<std::size_t> ambiguous;
  for (const Candidate& c : tried) {
    if (c.flagged.size() != final.flagged.size() || c.flagged == final.flagged || !(c.nu >= 1)) continue;
    if (!(c.squares <= variance * chi_square_quantile(c.nu, kScatterScore))) continue;
    const std::vector<std::size_t> more = exchanged(c.flagged, final.flagged);
    ambiguous.insert(ambiguous.end(), more.begin(), more.end());
  }
  std::sort(ambiguous.begin(), ambiguous.end());
  ambiguous.erase(std::unique(ambiguous.begin(), ambiguous.end()), ambiguous.end());
  best.ambiguous_outliers = std::move(ambiguous);
  return best;
}

}  // namespace furrow
