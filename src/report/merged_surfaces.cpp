#include "report/merged_surfaces.hpp"

namespace furrow {

std::vector<MergedSurface> merged_surfaces(const ComparisonDocument& doc, const RegionMap* map) {
  std::vector<MergedSurface> out;
  if (!map) return out;
  std::vector<int> slot(map->groups.size(), -1);
  for (const RegionGroup& g : map->groups)
    if (g.regions.size() > 1) {
      slot[static_cast<std::size_t>(g.id)] = static_cast<int>(out.size());
      out.push_back({&g, {}, 0});
    }
  std::vector<std::vector<double>> values(out.size());
  for (const ComparisonDocument::Point& p : doc.points) {
    if (!p.evaluated || !p.region || *p.region < 0 || static_cast<std::size_t>(*p.region) >= map->regions.size())
      continue;
    const int group = map->regions[static_cast<std::size_t>(*p.region)].group;
    if (group < 0 || static_cast<std::size_t>(group) >= slot.size() || slot[static_cast<std::size_t>(group)] < 0)
      continue;
    const auto k = static_cast<std::size_t>(slot[static_cast<std::size_t>(group)]);
    values[k].push_back(p.deviation);
    out[k].out_of_tolerance += p.in_tolerance == false;
  }
  for (std::size_t k = 0; k < out.size(); ++k) out[k].deviations = deviation_statistics(values[k]);
  return out;
}

}  // namespace furrow
