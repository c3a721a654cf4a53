#include "inspection/measurement_merge.hpp"

#include <stdexcept>
#include <unordered_map>

#include "base/error.hpp"

namespace furrow {

MergedMeasurements merge_measurements(const std::vector<MeasurementSet>& sets) {
  if (sets.empty()) throw std::logic_error("merge_measurements: no measurement set");
  MergedMeasurements m;
  const MeasurementSet& first = sets.front();
  m.set.kind = first.kind;
  m.set.probe_radius = first.probe_radius;
  m.set.ids_from_file = first.ids_from_file;
  std::unordered_map<std::string, std::size_t> index;
  for (std::size_t f = 0; f < sets.size(); ++f) {
    const MeasurementSet& s = sets[f];
    if (sets.size() > 1 && !s.ids_from_file)
      throw InputError(s.source + ": its point ids are generated (an XYZ file or a CSV without an id column), "
                       "and several measurement files are merged by id: give each file its ids");
    if (s.kind != first.kind)
      throw InputError(s.source + ": holds " + to_string(s.kind) + " points but " + first.source + " holds " +
                       to_string(first.kind) + " points: give --points for both");
    if (s.probe_radius != first.probe_radius)
      throw InputError(s.source + ": probe diameter " + std::to_string(2 * s.probe_radius) + " mm but " +
                       first.source + " has " + std::to_string(2 * first.probe_radius) + " mm");
    m.files.push_back(s.source);
    m.file_points.push_back(s.points.size());
    m.set.source += (f == 0 ? "" : " + ") + s.source;
    for (const MeasuredPoint& p : s.points) {
      const auto [it, inserted] = index.emplace(p.id, m.set.points.size());
      if (inserted) {
        m.set.points.push_back(p);
        m.origin.push_back(f);
        continue;
      }
      // Within one file ids are unique (the reader's rule), so this is an
      // earlier file's point measured again.
      m.replaced.push_back({p.id, m.origin[it->second], f, m.set.points[it->second].xyz});
      m.set.points[it->second] = p;
      m.origin[it->second] = f;
    }
  }
  return m;
}

}  // namespace furrow
