#include "machining/gouge/gouge_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "machining/gouge/site_json.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

namespace sj = site_json;
using sj::json;

constexpr double kRadToDeg = 180 / kPi;

json cutter_json(const LocalGouge& g) {
  const CutterCurvature& c = g.cutter;
  json j;
  j["k_max"] = c.sharp ? json(nullptr) : sj::rounded(c.k_max, sj::kCurvatureQuantum, "k_max");
  j["k_min"] = sj::rounded(c.k_min, sj::kCurvatureQuantum, "k_min");
  j["dir_max"] = sj::rounded(c.dir_max, sj::kUnitQuantum, "dir_max");
  j["dir_min"] = sj::rounded(c.dir_min, sj::kUnitQuantum, "dir_min");
  j["contact_angle_deg"] = sj::rounded(c.contact_angle() * kRadToDeg, sj::kAngleQuantum, "angle");
  j["sharp"] = c.sharp;
  j["flat_bottom"] = c.flat_bottom;
  j["side"] = c.side;
  return j;
}

json point_json(const Part& part, const GougePoint& p) {
  json j = sj::site(part, p.site, p.point, p.normal, p.k1, p.k2);
  const LocalGouge& g = p.gouge;
  j["status"] = to_string(g.status);
  if (p.sides != 0) {
    json b;
    if (p.has_neighbour) {
      b["neighbour"] = part.faces[p.neighbour_face].name();
      b["neighbour_uv"] = json::array({sj::rounded(p.neighbour_uv.x(), 1e-12, "u"),
                                       sj::rounded(p.neighbour_uv.y(), 1e-12, "v")});
      b["crease_deg"] = sj::rounded(p.crease_angle * kRadToDeg, sj::kAngleQuantum, "crease");
    } else {
      b["neighbour"] = nullptr;
    }
    b["search_converged"] = p.border_search_converged;
    j["border"] = std::move(b);
  }
  if (!g.cutter.reachable) return j;
  j["contact_normal"] = sj::rounded(g.cutter.normal, sj::kUnitQuantum, "normal");
  j["tip"] = sj::rounded(p.tip, sj::kLengthQuantum, "tip");
  j["cutter"] = cutter_json(g);
  if (g.quick) {
    j["max_excess_bound"] = sj::rounded(g.max_excess, sj::kCurvatureQuantum, "excess");
  } else {
    j["max_excess"] = sj::rounded(g.max_excess, sj::kCurvatureQuantum, "excess");
    j["max_excess_angle_deg"] = sj::rounded(g.max_excess_angle * kRadToDeg, sj::kAngleQuantum, "angle");
  }
  json ranges = json::array();
  for (const AngularRange& r : g.ranges)
    ranges.push_back(json::array({sj::rounded(r.start_deg(), sj::kAngleQuantum, "range"),
                                  sj::rounded(r.end_deg(), sj::kAngleQuantum, "range")}));
  j["gouge_ranges_deg"] = std::move(ranges);
  if (g.gouges())
    j["max_excess_direction"] = sj::rounded(g.direction(g.max_excess_angle), sj::kUnitQuantum, "dir");
  return j;
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

}  // namespace

GougeSummary summarize_gouges(const Part& part, const std::vector<GougePoint>& points) {
  GougeSummary s;
  s.points = points.size();
  s.face_points.assign(part.faces.size(), 0);
  s.face_gouges.assign(part.faces.size(), 0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const GougePoint& p = points[k];
    ++s.face_points[p.site.face];
    s.border += p.sides != 0;
    s.border_unresolved += p.sides != 0 && !p.border_search_converged;
    switch (p.gouge.status) {
      case GougeStatus::clear: ++s.clear; break;
      case GougeStatus::gouge:
        ++s.gouge;
        ++s.face_gouges[p.site.face];
        if (s.worst < 0 || p.gouge.max_excess > s.max_excess) {
          s.max_excess = p.gouge.max_excess;
          s.worst = static_cast<long>(k);
        }
        break;
      case GougeStatus::unreachable: ++s.unreachable; break;
      case GougeStatus::degenerate: ++s.degenerate; break;
      case GougeStatus::concave_crease:
        ++s.concave_crease;
        ++s.face_gouges[p.site.face];
        break;
    }
  }
  return s;
}

std::string gouge_report_json(const Part& part, const std::string& part_path,
                              const Cutter& cutter, const std::vector<GougePoint>& points,
                              const SiteSource& source, const GougeScanOptions& options) {
  const GougeSummary s = summarize_gouges(part, points);
  json doc;
  doc["part"] = part_path;
  const ToolSpec spec = cutter.spec();
  doc["tool"] = {{"name", spec.name},
                 {"type", to_string(spec.type)},
                 {"diameter", json_fields::finite(spec.diameter, "diameter")},
                 {"corner_radius", json_fields::finite(spec.corner_radius, "corner_radius")}};
  doc["sites"] = sj::sites_source(source.grid, source.points_file, points.size());
  doc["curvature_tolerance"] = json_fields::finite(options.gouge.curvature_tolerance, "tolerance");
  json summary;
  summary["points"] = s.points;
  summary["clear"] = s.clear;
  summary["gouge"] = s.gouge;
  summary["unreachable"] = s.unreachable;
  summary["degenerate"] = s.degenerate;
  summary["concave_crease"] = s.concave_crease;
  summary["border_points"] = s.border;
  summary["border_unresolved"] = s.border_unresolved;
  summary["max_excess"] = s.worst >= 0 ? sj::rounded(s.max_excess, sj::kCurvatureQuantum, "excess") : json(nullptr);
  summary["worst_point"] = s.worst >= 0 ? json(s.worst) : json(nullptr);
  doc["summary"] = std::move(summary);
  json faces = json::array();
  for (std::size_t f = 0; f < part.faces.size(); ++f)
    faces.push_back({{"name", part.faces[f].name()},
                     {"points", s.face_points[f]},
                     {"gouge", s.face_gouges[f]}});
  doc["faces"] = std::move(faces);
  json jp = json::array();
  for (const GougePoint& p : points) jp.push_back(point_json(part, p));
  doc["points"] = std::move(jp);
  return json_fields::to_text(doc);
}

std::string gouge_summary_text(const Part& part, const std::string& part_path,
                               const Cutter& cutter, const std::vector<GougePoint>& points) {
  const GougeSummary s = summarize_gouges(part, points);
  std::ostringstream out;
  out << "gouge: tool " << cutter.name() << " (" << to_string(cutter.type()) << ", diameter "
      << fmt("%g", cutter.diameter());
  if (cutter.type() == ToolType::bull) out << ", corner radius " << fmt("%g", cutter.corner_radius());
  out << ") on " << part_path << ", " << s.points << " contact points\n";
  const double share = s.points ? 100.0 * s.gouge / s.points : 0.0;
  out << "  gouge at " << s.gouge << " points" << fmt(" (%.1f%%)", share);
  if (s.worst >= 0) {
    const GougePoint& w = points[static_cast<std::size_t>(s.worst)];
    out << ", largest excess " << fmt("%.4g /mm", s.max_excess) << " on face "
        << part.faces[w.site.face].name() << fmt(" at (%.3f, %.3f, %.3f)", w.point.x(), w.point.y(), w.point.z());
  }
  out << "\n";
  if (s.unreachable || s.degenerate || s.concave_crease)
    out << "  unreachable from above " << s.unreachable << ", degenerate " << s.degenerate
        << ", concave crease " << s.concave_crease << "\n";
  if (s.border_unresolved)
    out << "  " << s.border_unresolved
        << " border points: the search for the neighbouring face did not converge (checked as free edges)\n";
  return out.str();
}

}  // namespace furrow
