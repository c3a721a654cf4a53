#include "machining/prediction/region_errors.hpp"

namespace furrow {

std::vector<RegionErrorRecord> errors_by_region(const Part& part, const ErrorMap& map, std::size_t region_count,
                                                const RegionLookup& lookup) {
  std::vector<RegionErrorRecord> records(region_count);
  for (std::size_t r = 0; r < region_count; ++r) records[r].region = static_cast<int>(r);
  struct Best {
    double value = 0;
    std::size_t face = 0;
    Eigen::Vector2d uv = Eigen::Vector2d::Zero();
    bool found = false;
  };
  std::vector<Best> high(region_count), low(region_count);
  std::vector<double> sums(region_count, 0.0);
  for (const FaceErrorMap& m : map.faces) {
    std::vector<int> region(m.error.size(), -1);
#pragma omp parallel for schedule(dynamic, 8)
    for (int j = 0; j < m.nv; ++j)
      for (int i = 0; i < m.nu; ++i) {
        if (m.status[m.index(i, j)] == ErrorCellStatus::outside) continue;
        const std::optional<int> id = lookup(static_cast<int>(m.face), m.u(i), m.v(j));
        if (id && *id >= 0 && static_cast<std::size_t>(*id) < region_count) region[m.index(i, j)] = *id;
      }
    for (int j = 0; j < m.nv; ++j)
      for (int i = 0; i < m.nu; ++i) {
        const std::size_t k = m.index(i, j);
        if (region[k] < 0) continue;
        const std::size_t r = static_cast<std::size_t>(region[k]);
        RegionErrorRecord& rec = records[r];
        rec.face = part.faces[m.face].name();
        ++rec.samples;
        if (m.status[k] != ErrorCellStatus::reached) continue;
        ++rec.reached;
        const double e = m.error[k];
        sums[r] += e;
        const Eigen::Vector2d uv(m.u(i), m.v(j));
        if (!high[r].found || e > high[r].value) high[r] = {e, m.face, uv, true};
        if (!low[r].found || e < low[r].value) low[r] = {e, m.face, uv, true};
      }
  }
  for (std::size_t r = 0; r < region_count; ++r) {
    RegionErrorRecord& rec = records[r];
    if (rec.reached > 0) rec.mean = sums[r] / rec.reached;
    for (auto [best, target] : {std::pair{&high[r], &rec.max_undercut}, std::pair{&low[r], &rec.max_overcut}}) {
      if (!best->found) continue;
      const SurfacePoint s = surface_point(part, static_cast<int>(best->face), best->uv);
      target->found = true;
      target->error = best->value;
      target->at = {part.faces[best->face].name(), best->uv, s.point};
    }
  }
  return records;
}

}  // namespace furrow
