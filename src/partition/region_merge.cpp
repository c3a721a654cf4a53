#include "partition/region_merge.hpp"

#include <functional>
#include <numeric>
#include <queue>

#include "partition/region_adjacency.hpp"

namespace furrow {

MergeReport merge_small_regions(RegionLabels& labels, const CurvatureField& field,
                                double min_area) {
  MergeReport report;
  const int n = labels.count();
  report.initial_regions = n;
  const auto index = [](int l) { return static_cast<std::size_t>(l); };

  std::vector<double> area(index(n), 0.0);
  for (std::size_t k = 0; k < labels.label.size(); ++k)
    if (labels.label[k] >= 0) area[index(labels.label[k])] += field.samples[k].area;
  std::vector<std::map<int, double>> borders = shared_borders(labels, field);

  // Smallest first; equal areas by label. Entries go stale when their region
  // grows or disappears and are skipped then.
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int l = 0; l < n; ++l)
    if (area[index(l)] < min_area) queue.push({area[index(l)], l});

  std::vector<int> merged_into(index(n), -1);
  while (!queue.empty()) {
    const auto [queued_area, s] = queue.top();
    queue.pop();
    if (merged_into[index(s)] >= 0 || queued_area != area[index(s)]) continue;
    std::map<int, double>& around = borders[index(s)];
    if (around.empty()) {
      ++report.isolated_small;
      continue;
    }
    int target = -1;
    double longest = -1;
    for (const auto& [neighbour, length] : around) {
      if (length > longest) {  // strict: ties keep the lower label
        longest = length;
        target = neighbour;
      }
    }
    merged_into[index(s)] = target;
    area[index(target)] += area[index(s)];
    labels.components[index(target)] += labels.components[index(s)];
    for (const auto& [neighbour, length] : around) {
      borders[index(neighbour)].erase(s);
      if (neighbour == target) continue;
      borders[index(neighbour)][target] += length;
      borders[index(target)][neighbour] += length;
    }
    around.clear();
    ++report.merges;
    if (area[index(target)] < min_area) queue.push({area[index(target)], target});
  }

  // Resolve chains (a into b, b into c) once per label, then relabel cells.
  std::vector<int> root(index(n));
  std::iota(root.begin(), root.end(), 0);
  for (int l = 0; l < n; ++l) {
    int r = l;
    while (merged_into[index(r)] >= 0) r = merged_into[index(r)];
    root[index(l)] = r;
  }
  for (int& l : labels.label)
    if (l >= 0) l = root[index(l)];
  renumber_in_raster_order(labels);
  return report;
}

}  // namespace furrow
