#include "inspection/coarse_alignment.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "geometry/point_search.hpp"
#include "inspection/point_subsets.hpp"
#include "inspection/surface_sampling.hpp"
#include "base/numbers.hpp"

namespace furrow {

const char* to_string(CoarseMethod method) {
  switch (method) {
    case CoarseMethod::identity:
      return "identity";
    case CoarseMethod::plan_ids:
      return "plan ids";
    case CoarseMethod::dmis_nominals:
      return "dmis nominals";
    case CoarseMethod::global_search:
      return "global search";
    case CoarseMethod::frame:
      return "alignment frame";
    case CoarseMethod::features:
      return "features";
  }
  return "?";
}

namespace {

// Every ceil(n / max)-th index: a deterministic, evenly spread subset.
std::vector<std::size_t> stride_subset(std::size_t n, std::size_t max) {
  const std::size_t step = std::max<std::size_t>(1, (n + max - 1) / std::max<std::size_t>(max, 1));
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < n; k += step) out.push_back(k);
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Rigid Umeyama fit from -> to with one pass that drops pairs off by more
// than three times the median residual. False when the pairs cannot fix a
// rotation (fewer than min_matches, or all on one line).
bool fit_pairs(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to,
               int min_matches, Eigen::Isometry3d& out) {
  std::vector<std::size_t> keep(from.size());
  for (std::size_t k = 0; k < keep.size(); ++k) keep[k] = k;
  for (int pass = 0; pass < 2; ++pass) {
    if (static_cast<int>(keep.size()) < std::max(3, min_matches)) return false;
    Eigen::Matrix3Xd a(3, keep.size()), b(3, keep.size());
    for (std::size_t k = 0; k < keep.size(); ++k) {
      a.col(k) = from[keep[k]];
      b.col(k) = to[keep[k]];
    }
    // Collinear (or coincident) targets leave a rotation free: the second
    // principal variance must not vanish against the first.
    const Eigen::Matrix3Xd centred = b.colwise() - b.rowwise().mean();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(centred * centred.transpose());
    if (!(es.eigenvalues()(1) > 1e-12 * es.eigenvalues()(2))) return false;
    out = Eigen::Isometry3d(Eigen::Matrix4d(Eigen::umeyama(a, b, false)));
    std::vector<double> residual(keep.size());
    for (std::size_t k = 0; k < keep.size(); ++k) residual[k] = (out * a.col(k) - b.col(k)).norm();
    const double limit = std::max(3 * median(residual), 1e-9);
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < keep.size(); ++k)
      if (residual[k] <= limit) kept.push_back(keep[k]);
    if (kept.size() == keep.size()) break;
    keep = std::move(kept);
  }
  return true;
}

// Centroid and principal axes (columns, by decreasing variance).
void principal_axes(const std::vector<Eigen::Vector3d>& pts, Eigen::Vector3d& centroid,
                    Eigen::Matrix3d& axes) {
  centroid.setZero();
  for (const auto& p : pts) centroid += p;
  centroid /= static_cast<double>(std::max<std::size_t>(pts.size(), 1));
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) cov += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  axes = es.eigenvectors().rowwise().reverse();
}

// The 24 proper signed permutation matrices (rotations of a cube).
std::vector<Eigen::Matrix3d> cube_rotations() {
  std::vector<Eigen::Matrix3d> out;
  std::array<int, 3> perm = {0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d p = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i) p(i, perm[i]) = (signs >> i & 1) ? -1.0 : 1.0;
      if (p.determinant() > 0) out.push_back(p);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

double rotation_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

struct Candidate {
  Eigen::Isometry3d transform;
  double score;
};

}  // namespace

double median_surface_distance(const ClosestPointFinder& finder, const MeasurementSet& set,
                               const Eigen::Isometry3d& transform, std::size_t max_points) {
  // Scored on the points that can lie on the part in this placement: a
  // blunder far away would only cost a projection and cannot move a median.
  const Eigen::AlignedBox3d box = finder.part().control_box();
  const double reach = 1.5 * box.diagonal().norm();
  std::vector<Eigen::Vector3d> all(set.points.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = transform * set.points[k].xyz;
  std::vector<std::size_t> near;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (all[k].allFinite() && box.exteriorDistance(all[k]) <= reach) near.push_back(k);
  const std::vector<std::size_t> subset = spread_subset(all, near, max_points);
  if (subset.empty()) return std::numeric_limits<double>::infinity();
  std::vector<double> d(subset.size());
#pragma omp parallel for schedule(static) if (subset.size() >= kParallelProjections)
  for (std::size_t k = 0; k < subset.size(); ++k) {
    const ClosestPoint c = finder.project(all[subset[k]]);
    d[k] = std::abs(c.signed_distance - set.probe_radius);
  }
  return median(d);
}

namespace {

// What the measured points are matched against: probe-centre positions
// over a sampling of the part's surface, with a k-d tree over them.
struct SearchTarget {
  std::vector<Eigen::Vector3d> points;
  double diagonal = 0;  // of their box [mm]
  PointSearch tree;
};

SearchTarget search_target(const Part& part, double probe_radius, std::size_t samples) {
  const std::vector<SurfaceSample> surface = sample_part_surface(part, samples);
  std::vector<Eigen::Vector3d> points(surface.size());
  for (std::size_t k = 0; k < surface.size(); ++k) points[k] = surface[k].point + probe_radius * surface[k].normal;
  Eigen::AlignedBox3d box;
  for (const auto& p : points) box.extend(p);
  const double diagonal = box.diagonal().norm();
  PointSearch tree(points);
  return {std::move(points), diagonal, std::move(tree)};
}

// Points that cannot lie on the part in any placement (blunders metres
// away, at any finite magnitude) take no part in the search; the fine fit
// later flags them. Without a bulk (fewer than 3 points near the median)
// every finite point is used.
std::vector<std::size_t> usable_points(const std::vector<Eigen::Vector3d>& all, double diagonal) {
  std::vector<std::size_t> usable = points_near_the_bulk(all, 1.5 * diagonal);
  if (usable.size() < 3) usable = points_near_the_bulk(all, std::numeric_limits<double>::max());
  return usable;
}

// Starting placements: the measured principal axes turned onto the
// surface's in each of the cube's 24 rotations, and the 24 rotations alone,
// each moving the measured centroid onto the surface's.
std::vector<Eigen::Isometry3d> starting_placements(const std::vector<Eigen::Vector3d>& target,
                                                   const std::vector<Eigen::Vector3d>& measured) {
  Eigen::Vector3d c_surface, c_measured;
  Eigen::Matrix3d e_surface, e_measured;
  principal_axes(target, c_surface, e_surface);
  principal_axes(measured, c_measured, e_measured);
  std::vector<Eigen::Isometry3d> starts;
  for (const Eigen::Matrix3d& p : cube_rotations()) {
    for (const Eigen::Matrix3d& r : {Eigen::Matrix3d(e_surface * p * e_measured.transpose()), p}) {
      if (r.determinant() < 0) continue;
      Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
      t.linear() = r;
      t.translation() = c_surface - r * c_measured;
      starts.push_back(t);
    }
  }
  return starts;
}

// Trimmed point-to-point ICP against the sampling (k-d tree, Umeyama in
// double): pairs farther than max_distance or than three times the median
// pair distance are dropped, so blunders do not pull. Stops after
// `iterations`, when the transform moves less than `tolerance`, or when
// fewer than 3 pairs are left.
Eigen::Isometry3d trimmed_icp(const SearchTarget& target, const std::vector<Eigen::Vector3d>& source,
                              Eigen::Isometry3d t, int iterations, double max_distance, double tolerance) {
  for (int it = 0; it < iterations; ++it) {
    std::vector<std::pair<std::size_t, int>> pairs;
    std::vector<double> dist;
    for (std::size_t k = 0; k < source.size(); ++k) {
      const PointNeighbour near = target.tree.nearest(t * source[k]);
      if (near.index < target.points.size() && near.distance <= max_distance) {
        pairs.emplace_back(k, static_cast<int>(near.index));
        dist.push_back(near.distance);
      }
    }
    const double limit = 3 * median(dist) + 1e-9;
    std::vector<Eigen::Vector3d> from, to;
    for (std::size_t m = 0; m < pairs.size(); ++m)
      if (dist[m] <= limit) {
        from.push_back(source[pairs[m].first]);
        to.push_back(target.points[pairs[m].second]);
      }
    if (from.size() < 3) break;
    Eigen::Matrix3Xd a(3, from.size()), b(3, from.size());
    for (std::size_t m = 0; m < from.size(); ++m) {
      a.col(m) = from[m];
      b.col(m) = to[m];
    }
    const Eigen::Isometry3d next(Eigen::Matrix4d(Eigen::umeyama(a, b, false)));
    const double change = (next.matrix() - t.matrix()).norm();
    t = next;
    if (change < tolerance) break;
  }
  return t;
}

// A short ICP of every start on the screening points, scored by the median
// distance to the nearest target sample; best first. Candidates are
// independent (read-only tree): screened in parallel, each into its own
// slot, so the outcome does not depend on scheduling.
std::vector<Candidate> screen_placements(const SearchTarget& target, const std::vector<Eigen::Isometry3d>& starts,
                                         const std::vector<Eigen::Vector3d>& screen, const CoarseOptions& options) {
  std::vector<Candidate> screened(starts.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const Eigen::Isometry3d t =
        trimmed_icp(target, screen, starts[k], options.screen_iterations, target.diagonal / 4, options.icp_tolerance);
    std::vector<double> d;
    for (const Eigen::Vector3d& p : screen) d.push_back(target.tree.nearest(t * p).distance);
    screened[k] = {t, median(d)};
  }
  std::stable_sort(screened.begin(), screened.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  return screened;
}

// The best screened candidates refined by two tighter ICP rounds and scored
// by the median distance to the true surface; best first.
std::vector<Candidate> refine_placements(const ClosestPointFinder& finder, const MeasurementSet& set,
                                         const SearchTarget& target, const std::vector<Candidate>& screened,
                                         const std::vector<Eigen::Vector3d>& refine, const CoarseOptions& options) {
  std::vector<Candidate> refined;
  const int wanted = refine.size() < options.few_points ? options.refine_candidates_few : options.refine_candidates;
  const std::size_t n = std::min<std::size_t>(screened.size(), static_cast<std::size_t>(std::max(1, wanted)));
  for (std::size_t k = 0; k < n; ++k) {
    Eigen::Isometry3d t = trimmed_icp(target, refine, screened[k].transform, options.refine_iterations,
                                      target.diagonal / 10, options.icp_tolerance);
    t = trimmed_icp(target, refine, t, options.refine_iterations, target.diagonal / 50, options.icp_tolerance);
    refined.push_back({t, median_surface_distance(finder, set, t, options.refine_points)});
  }
  std::stable_sort(refined.begin(), refined.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  return refined;
}

// The best refined placement, and whether a placement turned by more than
// the ambiguity angle scores nearly as well (a symmetric part).
CoarseResult best_placement(const std::vector<Candidate>& refined, int candidates, const CoarseOptions& options) {
  CoarseResult out;
  out.method = CoarseMethod::global_search;
  out.transform = refined[0].transform;
  out.median_distance = refined[0].score;
  out.candidates = candidates;
  for (std::size_t k = 1; k < refined.size(); ++k) out.alternatives.push_back(refined[k].transform);
  const double angle_limit = options.ambiguity_angle_deg * kPi / 180;
  for (std::size_t k = 1; k < refined.size(); ++k) {
    if (rotation_angle(refined[k].transform.linear(), out.transform.linear()) < angle_limit) continue;
    out.runner_up_median = refined[k].score;
    out.ambiguous = refined[k].score <= options.ambiguity_ratio * out.median_distance + 1e-3;
    break;
  }
  return out;
}

}  // namespace

CoarseResult coarse_global_search(const ClosestPointFinder& finder, const MeasurementSet& set,
                                  const CoarseOptions& options) {
  const SearchTarget target = search_target(finder.part(), set.probe_radius, options.surface_samples);
  std::vector<Eigen::Vector3d> all(set.points.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = set.points[k].xyz;
  const std::vector<std::size_t> usable = usable_points(all, target.diagonal);
  std::vector<Eigen::Vector3d> measured;
  for (std::size_t k : usable) measured.push_back(all[k]);
  const std::vector<Eigen::Isometry3d> starts = starting_placements(target.points, measured);
  // Spread over the part, not by file order (point_subsets.hpp says why).
  auto subset = [&](std::size_t max) {
    std::vector<Eigen::Vector3d> pts;
    for (std::size_t k : spread_subset(all, usable, max)) pts.push_back(all[k]);
    return pts;
  };
  const std::vector<Candidate> screened = screen_placements(target, starts, subset(options.screen_points), options);
  const std::vector<Candidate> refined =
      refine_placements(finder, set, target, screened, subset(options.refine_points), options);
  return best_placement(refined, static_cast<int>(starts.size()), options);
}

CoarseResult coarse_alignment(const ClosestPointFinder& finder, const MeasurementSet& set,
                              const InspectionPlan* plan, const CoarseOptions& options) {
  std::vector<Eigen::Vector3d> from, to;
  CoarseMethod method = CoarseMethod::identity;
  // A closed-form start needs no more than a few thousand pairs: match the
  // ids of an evenly spread subset (a small index, one pass over the plan).
  const std::vector<std::size_t> subset = stride_subset(set.points.size(), options.max_id_pairs);
  if (set.ids_from_file && plan) {
    std::unordered_map<std::string, std::size_t> wanted;
    wanted.reserve(subset.size());
    for (std::size_t k : subset) wanted.emplace(set.points[k].id, k);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // measured, planned
    for (std::size_t j = 0; j < plan->points.size(); ++j)
      if (const auto it = wanted.find(plan->points[j].id); it != wanted.end())
        pairs.emplace_back(it->second, j);
    std::sort(pairs.begin(), pairs.end());
    for (const auto& [k, j] : pairs) {
      const PlannedPoint& n = plan->points[j];
      from.push_back(set.points[k].xyz);
      to.push_back(set.kind == ProbePointKind::probe_centre ? n.centre(set.probe_radius) : n.xyz);
    }
    method = CoarseMethod::plan_ids;
  }
  if (from.size() < 3) {
    from.clear();
    to.clear();
    for (std::size_t k : subset) {
      const MeasuredPoint& p = set.points[k];
      if (!p.nominal) continue;
      from.push_back(p.xyz);
      const Eigen::Vector3d n = p.nominal_ijk.value_or(Eigen::Vector3d::Zero());
      to.push_back(*p.nominal +
                   (set.kind == ProbePointKind::probe_centre ? set.probe_radius : 0.0) * n);
    }
    method = CoarseMethod::dmis_nominals;
  }
  CoarseResult by_ids;
  bool have_ids = fit_pairs(from, to, options.min_matches, by_ids.transform);
  if (have_ids) {
    by_ids.method = method;
    by_ids.matched = from.size();
    by_ids.median_distance =
        median_surface_distance(finder, set, by_ids.transform, options.refine_points);
    if (by_ids.median_distance <= options.fallback_median) return by_ids;
  }
  CoarseResult global = coarse_global_search(finder, set, options);
  if (have_ids && by_ids.median_distance <= global.median_distance) return by_ids;
  return global;
}

}  // namespace furrow
