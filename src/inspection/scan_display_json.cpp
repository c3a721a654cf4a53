// The display sample and histogram in comparison.json (contract in
// scan_display_json.hpp).
#include "inspection/scan_display_json.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "base/error.hpp"

namespace furrow {

namespace jf = json_fields;
using nlohmann::json;

namespace {

// The double whose shortest text is the float's shortest text: written by
// the JSON layout as that text, and read back it converts to the same float.
double float_as_written(float f) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, f).ptr;
  *end = '\0';
  return std::strtod(buf, nullptr);
}

}  // namespace

json scan_display_json(const ScanDisplay& d) {
  json points = json::array();
  for (std::size_t k = 0; k < d.points.size(); ++k) {
    const Eigen::Vector3d& p = d.points[k];
    points.push_back({d.index[k], jf::finite(p.x(), "display x"), jf::finite(p.y(), "display y"),
                      jf::finite(p.z(), "display z"), jf::finite(float_as_written(d.deviation[k]), "display deviation")});
  }
  return {{"cap", d.cap},
          {"voxel", jf::finite(d.voxel, "display voxel")},
          {"grid_passes", d.grid_passes},
          {"rule", "one point per occupied voxel, the one with the largest |deviation|; voxel grown until at most "
                   "cap voxels are occupied (0: every evaluated point)"},
          {"columns", {"index", "x", "y", "z", "deviation"}},
          {"points", std::move(points)}};
}

json scan_histogram_json(const ScanHistogram& h) {
  json edges = json::array();
  for (double e : h.edges) edges.push_back(jf::finite(e, "histogram edge"));
  return {{"edges", std::move(edges)}, {"counts", h.counts}};
}

ScanDisplay read_scan_display(const JsonCursor& c) {
  ScanDisplay d;
  d.cap = c.count("cap");
  d.voxel = c.non_negative("voxel");
  d.grid_passes = c.count("grid_passes");
  c.string("rule");
  c.skip("columns");
  const json& points = c.array("points");
  if (points.size() > d.cap)
    throw InputError(c.path("points") + ": " + std::to_string(points.size()) + " points, more than the cap " +
                     std::to_string(d.cap));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::string where = jf::child(c.path("points"), k);
    const std::vector<double> row = jf::numbers(points[k], where);
    if (row.size() != 5) throw InputError(where + ": expected [index, x, y, z, deviation]");
    if (!(row[0] >= 0) || row[0] != std::floor(row[0]) || row[0] > 9.007e15)
      throw InputError(where + ": the index must be a whole number >= 0");
    const std::size_t index = static_cast<std::size_t>(row[0]);
    if (!d.index.empty() && index <= d.index.back())
      throw InputError(where + ": indices must increase (the deviation cloud's order)");
    d.index.push_back(index);
    d.points.emplace_back(row[1], row[2], row[3]);
    d.deviation.push_back(static_cast<float>(row[4]));
  }
  c.finish("docs/formats.md \"comparison.json of a scan\"");
  return d;
}

ScanHistogram read_scan_histogram(const JsonCursor& c) {
  ScanHistogram h;
  h.edges = c.numbers("edges");
  const json& counts = c.array("counts");
  if (h.edges.size() < 2 || counts.size() + 1 != h.edges.size())
    throw InputError(c.path("counts") + ": expected one count per bin (" + std::to_string(h.edges.size()) +
                     " edges, " + std::to_string(counts.size()) + " counts)");
  for (std::size_t k = 1; k < h.edges.size(); ++k)
    if (!(h.edges[k] > h.edges[k - 1])) throw InputError(c.path("edges") + ": must increase");
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const double n = jf::number(counts[k], jf::child(c.path("counts"), k));
    if (!(n >= 0) || n != std::floor(n)) throw InputError(jf::child(c.path("counts"), k) + ": must be a count");
    h.counts.push_back(static_cast<std::size_t>(n));
  }
  c.finish("docs/formats.md \"comparison.json of a scan\"");
  return h;
}

}  // namespace furrow
