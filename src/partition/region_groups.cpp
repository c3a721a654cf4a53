#include "partition/region_groups.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/closest_point.hpp"

namespace furrow {

namespace {

void check(const RegionGroupOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v)) throw InputError(std::string("region groups: ") + name + " must be positive");
  };
  positive(o.gap, "gap");
  positive(o.max_angle, "max_angle");
  if (!(o.min_tangent_fraction > 0 && o.min_tangent_fraction <= 1))
    throw InputError("region groups: min_tangent_fraction must be in (0, 1]");
}

// The region of the labelled cell nearest to (u,v) within two cells, or -1.
int region_near(const PartitionResult& result, std::size_t face, const Eigen::Vector2d& uv) {
  const RegionFace& info = result.map.faces[face];
  const FaceCells& cells = result.cells[face];
  const ParameterDomain& d = info.domain;
  const int nu = cells.labels.nu, nv = cells.labels.nv;
  const double du = d.width_u() / nu, dv = d.width_v() / nv;
  const int ci = std::clamp(static_cast<int>((uv.x() - d.u0) / du), 0, nu - 1);
  const int cj = std::clamp(static_cast<int>((uv.y() - d.v0) / dv), 0, nv - 1);
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i = std::max(0, ci - 2); i <= std::min(nu - 1, ci + 2); ++i)
    for (int j = std::max(0, cj - 2); j <= std::min(nv - 1, cj + 2); ++j) {
      const int label = cells.labels.at(i, j);
      if (label < 0) continue;
      // Distance in cells, so a long thin cell does not favour one direction.
      const double di = (d.u0 + (i + 0.5) * du - uv.x()) / du, dj = (d.v0 + (j + 0.5) * dv - uv.y()) / dv;
      const double distance = di * di + dj * dj;
      if (distance < best_distance) {
        best_distance = distance;
        best = cells.first_id + label;
      }
    }
  return best;
}

struct BoundarySample {
  Eigen::Vector2d uv;
  double length = 0;  // of the boundary it stands for [mm]
};

// A closed (u,v) polyline resampled at about `spacing` mm on the surface.
void sample_loop(const Face& face, const std::vector<Eigen::Vector2d>& loop, double spacing,
                 std::vector<BoundarySample>& out) {
  // A coarse copy (trim polygons from CAD can have thousands of vertices)
  // measured on the surface, then samples at equal arc length along it.
  const std::size_t stride = std::max<std::size_t>(1, loop.size() / 2048);
  std::vector<Eigen::Vector2d> coarse;
  for (std::size_t k = 0; k < loop.size(); k += stride) coarse.push_back(loop[k]);
  coarse.push_back(coarse.front());
  std::vector<double> at{0};
  for (std::size_t k = 1; k < coarse.size(); ++k)
    at.push_back(at.back() + (face.surface().point(coarse[k].x(), coarse[k].y()) -
                              face.surface().point(coarse[k - 1].x(), coarse[k - 1].y()))
                                 .norm());
  const double total = at.back();
  if (!(total > 0)) return;
  const int n = static_cast<int>(std::clamp(std::ceil(total / spacing), 8.0, 4096.0));
  std::size_t seg = 0;
  for (int k = 0; k < n; ++k) {
    const double s = total * (k + 0.5) / n;
    while (seg + 2 < at.size() && at[seg + 1] < s) ++seg;
    const double piece = at[seg + 1] - at[seg];
    const double t = piece > 0 ? (s - at[seg]) / piece : 0;
    out.push_back({coarse[seg] + t * (coarse[seg + 1] - coarse[seg]), total / n});
  }
}

std::vector<BoundarySample> boundary_samples(const Face& face, double spacing) {
  std::vector<BoundarySample> out;
  if (!face.trim().empty()) {
    for (const UvLoop& loop : face.trim().loops()) sample_loop(face, loop, spacing, out);
    return out;
  }
  const ParameterDomain& d = face.domain();
  sample_loop(face, {{d.u0, d.v0}, {d.u1, d.v0}, {d.u1, d.v1}, {d.u0, d.v1}}, spacing, out);
  return out;
}

int find(std::vector<int>& parent, int k) {
  while (parent[static_cast<std::size_t>(k)] != k) k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
  return k;
}

}  // namespace

void group_regions_across_faces(const Part& part, PartitionResult& result, const RegionGroupOptions& options) {
  check(options);
  RegionMap& map = result.map;
  std::vector<int> parent(map.regions.size());
  std::iota(parent.begin(), parent.end(), 0);
  if (part.faces.size() > 1) {
    const ClosestPointFinder finder(part);
    const double cos_max = std::cos(radians(options.max_angle));
    // Per ordered pair of regions (a on this face, b on another): the
    // length of edge they share and the tangent part of it.
    std::map<std::pair<int, int>, std::pair<double, double>> edges;
    std::map<std::pair<int, int>, int> tangent_samples;
    for (std::size_t f = 0; f < part.faces.size(); ++f) {
      const Face& face = part.faces[f];
      const RegionFace& info = map.faces[f];
      // About every four cells along the surface.
      const double cell = std::sqrt(info.area / std::max(1, info.valid_cells));
      if (!(cell > 0)) continue;
      for (const BoundarySample& s : boundary_samples(face, 4 * cell)) {
        const int a = region_near(result, f, s.uv);
        if (a < 0) continue;
        const DifferentialGeometry here = face.geometry(s.uv.x(), s.uv.y());
        if (here.degenerate) continue;
        const std::optional<ClosestPoint> foot = finder.project_to_other_faces(here.point, f);
        if (!foot || !(foot->distance <= options.gap)) continue;
        const int b = region_near(result, foot->face, foot->uv);
        if (b < 0) continue;
        auto& edge = edges[{a, b}];
        edge.first += s.length;
        if (here.normal.dot(foot->normal) >= cos_max) {
          edge.second += s.length;
          ++tangent_samples[{a, b}];
        }
      }
    }
    for (const auto& [pair, edge] : edges) {
      const auto [a, b] = pair;
      if (map.regions[static_cast<std::size_t>(a)].curvature_class !=
          map.regions[static_cast<std::size_t>(b)].curvature_class)
        continue;
      const auto seen = tangent_samples.find(pair);
      if (seen == tangent_samples.end() || seen->second < 2) continue;
      if (edge.second < options.min_tangent_fraction * edge.first) continue;
      const int ra = find(parent, a), rb = find(parent, b);
      if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
  }
  // Groups numbered by their smallest region id (the root: unions keep the smaller).
  std::vector<int> group_of_root(map.regions.size(), -1);
  int groups = 0;
  for (std::size_t r = 0; r < map.regions.size(); ++r) {
    const int root = find(parent, static_cast<int>(r));
    if (group_of_root[static_cast<std::size_t>(root)] < 0) group_of_root[static_cast<std::size_t>(root)] = groups++;
    map.regions[r].group = group_of_root[static_cast<std::size_t>(root)];
  }
  map.collect_groups();
}

}  // namespace furrow
