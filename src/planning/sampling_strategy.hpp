#pragma once
// Probe points inside one region: the sampling strategies.
//
//   grid        cell centres of an nx x ny lattice, cells square on the surface
//   stratified  one uniform random point per lattice cell (jittered grid)
//   hammersley  Hammersley set ((i + 1/2) / N, radical inverse base 2) — the
//               default: the smallest fit spread of all in
//               tests/planning/test_sampling_accuracy.cpp (docs/cmm.md)
//   halton      Halton sequence (bases 2, 3); nested: a denser plan keeps
//               every point of a sparser one
//   random      independent uniform points
//   curvature   Halton through a density raised where |k|max is high:
//               area * (1 + |k|max / mean |k|max of the part)
//   risk        the local maxima of the predicted |error| first (at least
//               half a point spacing apart), the rest Halton through a
//               density proportional to area * (|error| + 10 % of its mean)
//
// Every strategy builds points in [0, 1)^2 (low_discrepancy.hpp; seeded,
// Cranley-Patterson rotated), maps them onto the region's uv box through an
// area warp (area_warp.hpp: even in the square = even on the surface), and
// keeps the admissible ones (region_domain.hpp: inside the region and the
// trim, border clearance or, in a narrow region, the ball-contact rule). Sequences (halton, random, curvature, risk)
// simply run until `count` points are kept. Sets (grid, stratified,
// hammersley) depend on their size N: N is searched (bracketing, then
// bisection) for exactly `count` admissible points; when no N gives exactly
// `count` (a lattice gains or loses whole rows), the smallest N giving more
// is used and the surplus points nearest the region's edges are dropped.
//
// Failure is reported, not thrown: when the region cannot hold `count`
// admissible points within the candidate budget (a sliver narrower than
// twice the border clearance, a strip where few ball positions pass), the result has fewer points and `short_by`
// says how many are missing.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "planning/region_domain.hpp"

namespace furrow {

enum class SamplingStrategy { grid, stratified, hammersley, halton, random, curvature, risk };
constexpr SamplingStrategy kDefaultSamplingStrategy = SamplingStrategy::hammersley;
const char* to_string(SamplingStrategy strategy);
// Throws InputError naming `where` for an unknown name (lists the valid ones).
SamplingStrategy parse_sampling_strategy(const std::string& text, const std::string& where);
// The strategies that need a risk map.
bool needs_risk(SamplingStrategy strategy);

struct SamplingOptions {
  // Candidates tried before a region is declared too small for the request:
  // max(min_candidates, candidates_per_point * count).
  std::size_t candidates_per_point = 400;
  std::size_t min_candidates = 200000;
  // Set-size search (grid, stratified, hammersley): sizes tried.
  int max_set_sizes = 64;
  // Curvature strategy: weight of |k|max relative to `kappa_ref`.
  double curvature_weight = 1;
  // Risk strategy: floor of the density, as a fraction of the region's mean
  // predicted |error| (keeps some points where nothing is predicted).
  double risk_floor_fraction = 0.1;
};

struct SampledPoint {
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  double edge_distance = 0;  // straight-line distance to the region's edges (capped) [mm]
};

struct RegionSample {
  std::vector<SampledPoint> points;
  std::size_t short_by = 0;        // requested - obtained
  std::size_t candidates_tried = 0;
};

// `count` points of `strategy` in the region. `seed` should already be the
// region's own seed (region_seed). `kappa_ref` is the part's mean |k|max
// (curvature strategy); the risk strategy needs the domain built with a risk
// map.
RegionSample sample_region(const RegionDomain& domain, SamplingStrategy strategy, std::size_t count,
                           std::uint64_t seed, double kappa_ref, const SamplingOptions& options = {});

// `count` points on a gouge site: the point admissible on the site's terms
// (RegionDomain::admissible_on_site) nearest `centre` within `box` first
// (from a grid of candidates), then Halton points in the box. Fewer when the
// site holds fewer admissible points.
RegionSample sample_site(const RegionDomain& domain, const Eigen::AlignedBox2d& box,
                         const Eigen::Vector2d& centre, std::size_t count, std::uint64_t seed,
                         const SamplingOptions& options = {});

// A seed per region from the plan seed (SplitMix64 of both), so regions are
// independent and a region's points do not change when another region's
// count changes.
std::uint64_t region_seed(std::uint64_t seed, int region);

}  // namespace furrow
