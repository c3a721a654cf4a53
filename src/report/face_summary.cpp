#include "report/face_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "report/html.hpp"
#include "report/point_table.hpp"

#include "base/number_text.hpp"

namespace furrow {

namespace {

std::string um(double mm) { return signed_fixed(mm * 1000, 1); }

}  // namespace

std::vector<FaceDeviationSummary> face_summaries(const ComparisonDocument& doc) {
  std::map<int, FaceDeviationSummary> by_face;
  std::map<int, double> sums;
  const ToleranceZone& zone = doc.options.tolerance;
  for (const ComparisonDocument::Point& p : doc.points) {
    FaceDeviationSummary& f = by_face[p.face_index];
    f.face_index = p.face_index;
    f.face = p.face;
    ++f.points;
    if (!p.evaluated) continue;
    ++f.evaluated;
    if (!p.in_tolerance.value_or(zone.contains(p.deviation))) ++f.out_of_tolerance;
    f.min_deviation = std::min(f.min_deviation.value_or(p.deviation), p.deviation);
    f.max_deviation = std::max(f.max_deviation.value_or(p.deviation), p.deviation);
    sums[p.face_index] += p.deviation;
    if (f.worst_point.empty() || std::abs(p.deviation) > f.max_abs_deviation) {
      f.max_abs_deviation = std::abs(p.deviation);
      f.worst_point = p.id;
    }
    f.worst_excess = std::max(f.worst_excess, out_of_tolerance_amount(p.deviation, zone));
  }
  std::vector<FaceDeviationSummary> out;
  for (auto& [index, f] : by_face) {
    if (f.evaluated > 0) f.mean_deviation = sums[index] / static_cast<double>(f.evaluated);
    out.push_back(std::move(f));
  }
  std::sort(out.begin(), out.end(), [](const FaceDeviationSummary& a, const FaceDeviationSummary& b) {
    if ((a.evaluated > 0) != (b.evaluated > 0)) return a.evaluated > 0;
    if (a.worst_excess != b.worst_excess) return a.worst_excess > b.worst_excess;
    if (a.max_abs_deviation != b.max_abs_deviation) return a.max_abs_deviation > b.max_abs_deviation;
    return a.face_index < b.face_index;
  });
  return out;
}

std::string face_summary_html(const ComparisonDocument& doc,
                              const std::vector<std::optional<AnalyticSurface>>& surfaces) {
  const std::vector<FaceDeviationSummary> faces = face_summaries(doc);
  std::size_t bad = 0;
  for (const FaceDeviationSummary& f : faces) bad += f.out_of_tolerance > 0;
  std::string out = "<section id=\"faces\"><h2>Faces</h2>\n<p>" + std::to_string(faces.size()) +
                    (faces.size() == 1 ? " face carries" : " faces carry") + " measured points; " +
                    std::to_string(bad) +
                    " with points out of tolerance. Worst first: by the largest amount beyond the zone, then by "
                    "the largest |deviation|.</p>\n";
  std::vector<html::TableRow> rows;
  const std::string dash = "&ndash;";
  for (const FaceDeviationSummary& f : faces) {
    html::TableRow row;
    row.cells = {html::escape(f.face),
                 std::to_string(f.face_index),
                 std::to_string(f.points),
                 std::to_string(f.evaluated),
                 std::to_string(f.out_of_tolerance),
                 f.min_deviation ? um(*f.min_deviation) : dash,
                 f.max_deviation ? um(*f.max_deviation) : dash,
                 f.mean_deviation ? um(*f.mean_deviation) : dash,
                 f.evaluated ? um(f.worst_excess).substr(f.worst_excess > 0 ? 1 : 0) : dash,
                 f.worst_point.empty() ? dash : html::escape(f.worst_point)};
    const bool known = f.face_index >= 0 && static_cast<std::size_t>(f.face_index) < surfaces.size();
    const std::optional<AnalyticSurface>* surface = known ? &surfaces[static_cast<std::size_t>(f.face_index)] : nullptr;
    row.cells.push_back(!surface ? dash : *surface ? html::escape(describe(**surface)) : "free-form");
    if (f.out_of_tolerance > 0) row.css_class = "out";
    rows.push_back(std::move(row));
  }
  out += html::table({"Face", "Index", "Points", "Evaluated", "Out", "Min [um]", "Max [um]", "Mean [um]",
                      "Beyond zone [um]", "Worst point", "Surface"},
                     rows, "faces");
  return out + "</section>\n";
}

}  // namespace furrow
