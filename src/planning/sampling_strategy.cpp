#include "planning/sampling_strategy.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <random>

#include "base/error.hpp"
#include "planning/low_discrepancy.hpp"

namespace furrow {

namespace {

struct StrategyName {
  SamplingStrategy strategy;
  const char* name;
};
constexpr StrategyName kNames[] = {
    {SamplingStrategy::grid, "grid"},           {SamplingStrategy::stratified, "stratified"},
    {SamplingStrategy::hammersley, "hammersley"}, {SamplingStrategy::halton, "halton"},
    {SamplingStrategy::random, "random"},       {SamplingStrategy::curvature, "curvature"},
    {SamplingStrategy::risk, "risk"},
};

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::size_t budget_for(std::size_t count, const SamplingOptions& o) {
  return std::max(o.min_candidates, o.candidates_per_point * count);
}

// Tries one unit-square point; appends it when admissible.
bool try_point(const RegionDomain& domain, const AreaWarp& warp, const Eigen::Vector2d& st,
               std::vector<SampledPoint>& out) {
  SampledPoint p;
  p.uv = warp.map(st);
  const std::optional<double> d = domain.admissible(p.uv, &p.xyz);
  if (!d) return false;
  p.edge_distance = *d;
  out.push_back(p);
  return true;
}

// Sequences: run until `count` are kept or the budget is spent.
RegionSample run_sequence(const RegionDomain& domain, const AreaWarp& warp, std::size_t count,
                          const std::function<Eigen::Vector2d(std::size_t)>& point, std::size_t budget,
                          RegionSample sample = {}) {
  for (std::size_t i = 0; sample.points.size() < count && sample.candidates_tried < budget; ++i) {
    ++sample.candidates_tried;
    try_point(domain, warp, point(i), sample.points);
  }
  sample.short_by = count - std::min(count, sample.points.size());
  return sample;
}

// Admissible fraction of the warped box, from unrotated Halton points.
double admissible_fraction(const RegionDomain& domain, const AreaWarp& warp, std::size_t& tried) {
  constexpr std::size_t kProbe = 1024;
  std::vector<SampledPoint> kept;
  for (std::size_t i = 0; i < kProbe; ++i) try_point(domain, warp, halton_point(i), kept);
  tried += kProbe;
  return std::max(static_cast<double>(kept.size()), 0.25) / kProbe;
}

// Keeps `count` of `points`, dropping those nearest the region's edges
// (ties: later points first); the survivors keep their order.
std::vector<SampledPoint> drop_nearest_edges(std::vector<SampledPoint> points, std::size_t count) {
  std::vector<std::size_t> order(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].edge_distance != points[b].edge_distance)
      return points[a].edge_distance < points[b].edge_distance;
    return a > b;
  });
  std::vector<bool> drop(points.size(), false);
  for (std::size_t k = 0; k + count < points.size(); ++k) drop[order[k]] = true;
  std::vector<SampledPoint> kept;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!drop[k]) kept.push_back(points[k]);
  return kept;
}

// Sets: search the set size N for exactly `count` admissible points.
RegionSample run_set(const RegionDomain& domain, const AreaWarp& warp, std::size_t count,
                     const std::function<std::vector<Eigen::Vector2d>(std::size_t)>& make_set,
                     const SamplingOptions& options) {
  RegionSample sample;
  if (count == 0) return sample;
  const std::size_t budget = budget_for(count, options);
  double fraction = admissible_fraction(domain, warp, sample.candidates_tried);
  std::size_t n = static_cast<std::size_t>(std::ceil(count / fraction));
  std::size_t lo = 0, hi = 0;  // largest size with too few, smallest with too many (0: none)
  std::vector<SampledPoint> over, under;
  for (int iter = 0; iter < options.max_set_sizes && sample.candidates_tried < budget; ++iter) {
    std::vector<SampledPoint> kept;
    const std::vector<Eigen::Vector2d> set = make_set(n);
    for (const Eigen::Vector2d& st : set) try_point(domain, warp, st, kept);
    sample.candidates_tried += set.size();
    if (kept.size() == count) {
      sample.points = std::move(kept);
      return sample;
    }
    if (!kept.empty()) fraction = static_cast<double>(kept.size()) / static_cast<double>(set.size());
    if (kept.size() < count) {
      lo = std::max(lo, n);
      if (kept.size() >= under.size()) under = std::move(kept);
    } else if (hi == 0 || n < hi) {
      hi = n;
      over = std::move(kept);
    }
    std::size_t next;
    if (hi != 0 && lo != 0) {
      if (hi - lo <= 1) break;
      next = lo + (hi - lo) / 2;
    } else if (hi == 0) {
      const double missing = static_cast<double>(count - std::min(count, under.size()));
      next = n + std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(missing / fraction)));
    } else {
      const double surplus = static_cast<double>(over.size() - count);
      const std::size_t step = std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(surplus / fraction)));
      next = n > step ? std::max(n - step, lo + 1) : lo + 1;
      if (next >= hi) break;
    }
    n = next;
  }
  if (!over.empty()) {
    sample.points = drop_nearest_edges(std::move(over), count);
  } else {
    sample.points = std::move(under);
    sample.short_by = count - sample.points.size();
  }
  return sample;
}

std::vector<SampledPoint> risk_maxima(const RegionDomain& domain, std::size_t limit, double spacing) {
  const int n = domain.grid_cells();
  const std::vector<DomainCell>& cells = domain.cells();
  auto at = [&](int i, int j) -> const DomainCell& { return cells[static_cast<std::size_t>(i) * n + j]; };
  std::vector<std::size_t> peaks;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const DomainCell& c = at(i, j);
      if (!c.inside || !(c.risk > 0)) continue;
      bool peak = true;
      for (int di = -1; di <= 1 && peak; ++di)
        for (int dj = -1; dj <= 1 && peak; ++dj) {
          const int a = i + di, b = j + dj;
          if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= n || b >= n) continue;
          const DomainCell& o = at(a, b);
          // Plateaus: the first cell in raster order wins.
          const bool earlier = a * n + b < i * n + j;
          if (o.risk > c.risk || (earlier && o.risk == c.risk)) peak = false;
        }
      if (peak) peaks.push_back(static_cast<std::size_t>(i) * n + j);
    }
  std::stable_sort(peaks.begin(), peaks.end(),
                   [&](std::size_t a, std::size_t b) { return cells[a].risk > cells[b].risk; });
  std::vector<SampledPoint> out;
  for (std::size_t k : peaks) {
    if (out.size() >= limit) break;
    SampledPoint p;
    p.uv = cells[k].uv;
    const std::optional<double> d = domain.admissible(p.uv, &p.xyz);
    if (!d) continue;
    p.edge_distance = *d;
    const bool crowded = std::any_of(out.begin(), out.end(), [&](const SampledPoint& q) {
      return (q.xyz - p.xyz).norm() < spacing;
    });
    if (!crowded) out.push_back(p);
  }
  return out;
}

}  // namespace

const char* to_string(SamplingStrategy strategy) {
  for (const StrategyName& s : kNames)
    if (s.strategy == strategy) return s.name;
  return "?";
}

SamplingStrategy parse_sampling_strategy(const std::string& text, const std::string& where) {
  std::string valid;
  for (const StrategyName& s : kNames) {
    if (text == s.name) return s.strategy;
    valid += (valid.empty() ? "" : ", ") + std::string(s.name);
  }
  throw InputError(where + ": unknown strategy \"" + text + "\" (valid: " + valid + ")");
}

bool needs_risk(SamplingStrategy strategy) { return strategy == SamplingStrategy::risk; }

std::uint64_t region_seed(std::uint64_t seed, int region) {
  return splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(region) + 1));
}

RegionSample sample_region(const RegionDomain& domain, SamplingStrategy strategy, std::size_t count,
                           std::uint64_t seed, double kappa_ref, const SamplingOptions& options) {
  RegionSample empty;
  if (count == 0) return empty;
  const Eigen::Vector2d shift = rotation_from_seed(seed);
  const double aspect = domain.length_v() > 0 ? domain.length_u() / domain.length_v() : 1.0;
  const std::size_t budget = budget_for(count, options);
  std::mt19937_64 rng(seed);
  switch (strategy) {
    case SamplingStrategy::halton:
      return run_sequence(domain, domain.area_warp(), count,
                          [&](std::size_t i) { return rotate(halton_point(i), shift); }, budget);
    case SamplingStrategy::random:
      return run_sequence(domain, domain.area_warp(), count, [&](std::size_t) { return random_point(rng); },
                          budget);
    case SamplingStrategy::curvature:
      return run_sequence(domain, domain.warp(options.curvature_weight, kappa_ref, 0, 1), count,
                          [&](std::size_t i) { return rotate(halton_point(i), shift); }, budget);
    case SamplingStrategy::risk: {
      const double mean = domain.statistics().mean_risk;
      const double spacing = 0.5 * std::sqrt(domain.statistics().area / static_cast<double>(count));
      RegionSample sample;
      sample.points = risk_maxima(domain, (count + 1) / 2, spacing);
      const AreaWarp warp = mean > 0 ? domain.warp(0, 1, 1, options.risk_floor_fraction * mean) : domain.area_warp();
      return run_sequence(domain, warp, count, [&](std::size_t i) { return rotate(halton_point(i), shift); },
                          budget, std::move(sample));
    }
    case SamplingStrategy::hammersley:
      return run_set(domain, domain.area_warp(), count,
                     [&](std::size_t n) {
                       std::vector<Eigen::Vector2d> set = hammersley_set(n);
                       for (Eigen::Vector2d& p : set) p = rotate(p, shift);
                       return set;
                     },
                     options);
    case SamplingStrategy::stratified:
      return run_set(domain, domain.area_warp(), count,
                     [&](std::size_t n) {
                       std::mt19937_64 local(seed ^ static_cast<std::uint64_t>(n));
                       return stratified_set(strata_for(n, aspect), local);
                     },
                     options);
    case SamplingStrategy::grid:
      return run_set(domain, domain.area_warp(), count,
                     [&](std::size_t n) { return grid_set(strata_for(n, aspect)); }, options);
  }
  return empty;
}

RegionSample sample_site(const RegionDomain& domain, const Eigen::AlignedBox2d& box,
                         const Eigen::Vector2d& centre, std::size_t count, std::uint64_t seed,
                         const SamplingOptions& options) {
  RegionSample sample;
  if (count == 0) return sample;
  // The admissible candidate nearest the centre (on the surface, straight line).
  const Eigen::Vector3d target = domain.face().surface().point(centre.x(), centre.y());
  std::optional<SampledPoint> best;
  auto consider = [&](const Eigen::Vector2d& uv) {
    ++sample.candidates_tried;
    SampledPoint p;
    p.uv = uv;
    const std::optional<double> d = domain.admissible_on_site(uv, &p.xyz);
    if (!d) return;
    p.edge_distance = *d;
    if (!best || (p.xyz - target).norm() < (best->xyz - target).norm()) best = p;
  };
  consider(centre);
  if (!best) {
    constexpr int kGrid = 17;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j)
        consider(box.min() + box.sizes().cwiseProduct(Eigen::Vector2d((i + 0.5) / kGrid, (j + 0.5) / kGrid)));
  }
  if (!best) {
    sample.short_by = count;
    return sample;
  }
  sample.points.push_back(*best);
  // The rest: Halton points in the site's box (a plain affine map: sites are small).
  const Eigen::Vector2d shift = rotation_from_seed(seed);
  const std::size_t budget = budget_for(count, options);
  for (std::size_t i = 0; sample.points.size() < count && sample.candidates_tried < budget; ++i) {
    ++sample.candidates_tried;
    SampledPoint p;
    p.uv = box.min() + box.sizes().cwiseProduct(rotate(halton_point(i + 1), shift));
    const std::optional<double> d = domain.admissible_on_site(p.uv, &p.xyz);
    if (!d) continue;
    p.edge_distance = *d;
    sample.points.push_back(p);
  }
  sample.short_by = count - sample.points.size();
  return sample;
}

}  // namespace furrow
