#include "machining/gouge/tool_selection_report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "machining/gouge/site_json.hpp"

namespace furrow {

namespace {

namespace sj = site_json;
using sj::json;

// Radius of curvature for a curvature; null when the surface is not concave
// there (no radius limit).
json radius(double curvature) {
  return curvature > 0 ? sj::rounded(1 / curvature, sj::kLengthQuantum, "radius") : json(nullptr);
}

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

// The machinable site without a tool where the smallest tool's excess is
// largest (or, failing that, where it interferes deepest); -1 if none.
long worst_site(const ToolSelection& sel) {
  long worst = -1;
  for (std::size_t k = 0; k < sel.sites.size(); ++k) {
    const SiteSelection& s = sel.sites[k];
    if (!s.machinable || s.tool >= 0) continue;
    if (worst < 0) {
      worst = static_cast<long>(k);
      continue;
    }
    const SiteSelection& w = sel.sites[static_cast<std::size_t>(worst)];
    const bool better = s.smallest_gouges_locally != w.smallest_gouges_locally
                            ? s.smallest_gouges_locally
                            : (s.smallest_gouges_locally ? s.needed.excess > w.needed.excess
                                                         : s.interference > w.interference);
    if (better) worst = static_cast<long>(k);
  }
  return worst;
}

}  // namespace

std::string tool_selection_json(const Part& part, const std::string& part_path,
                                const std::string& library_path, const ToolSelection& sel,
                                const SiteSource& source, const ToolSelectionOptions& options) {
  json doc;
  doc["part"] = part_path;
  doc["library"] = library_path;
  doc["sites"] = sj::sites_source(source.grid, source.points_file, sel.sites.size());
  doc["curvature_tolerance"] = json_fields::finite(options.scan.gouge.curvature_tolerance, "tolerance");
  doc["interference_check"] = options.check_interference;
  // Only when on, so the default document is unchanged.
  if (options.check_interference && options.share_interference) doc["interference_shared"] = true;
  json tools = json::array();
  for (std::size_t t = 0; t < sel.library.size(); ++t) {
    const ToolSpec spec = sel.library[t].spec();
    tools.push_back({{"name", spec.name},
                     {"type", to_string(spec.type)},
                     {"diameter", json_fields::finite(spec.diameter, "diameter")},
                     {"corner_radius", json_fields::finite(spec.corner_radius, "corner_radius")},
                     {"gouging_points", sel.gouging_sites[t]},
                     {"interfering_points", sel.interfering_sites[t]}});
  }
  doc["tools"] = std::move(tools);
  doc["whole_surface"] =
      sel.whole_surface >= 0 ? json(sel.library[sel.whole_surface].name()) : json(nullptr);
  doc["summary"] = {{"points", sel.sites.size()},
                    {"unmachinable", sel.unmachinable},
                    {"without_tool", sel.without_tool},
                    {"border_unresolved", sel.border_unresolved}};
  json points = json::array();
  for (const SiteSelection& s : sel.sites) {
    json j = sj::site(part, s.site, s.point, s.normal, s.k1, s.k2);
    if (!s.machinable) {
      j["status"] = to_string(s.smallest_status);
      j["tool"] = nullptr;
      points.push_back(std::move(j));
      continue;
    }
    j["tool"] = s.tool >= 0 ? json(sel.library[s.tool].name()) : json(nullptr);
    if (s.tool < 0 && s.smallest_gouges_locally) {
      const NeededCurvature& n = s.needed;
      j["needed"] = {
          {"direction", sj::rounded(n.direction, sj::kUnitQuantum, "direction")},
          {"design_curvature", sj::rounded(n.design_curvature, sj::kCurvatureQuantum, "curvature")},
          {"allowed_curvature", sj::rounded(n.allowed_curvature, sj::kCurvatureQuantum, "curvature")},
          {"design_radius", radius(n.design_curvature)},
          {"required_radius", radius(n.allowed_curvature)}};
    } else if (s.tool < 0) {
      j["interference_depth"] = sj::rounded(s.interference, sj::kLengthQuantum, "depth");
    }
    points.push_back(std::move(j));
  }
  doc["points"] = std::move(points);
  return json_fields::to_text(doc);
}

std::string tool_selection_text(const Part& part, const std::string& part_path,
                                const ToolSelection& sel) {
  std::ostringstream out;
  const std::size_t machinable = sel.sites.size() - sel.unmachinable;
  out << "select-tool: " << part_path << ", " << sel.library.size() << " tools, "
      << sel.sites.size() << " contact points";
  if (sel.unmachinable) out << " (" << sel.unmachinable << " not machinable from above)";
  out << "\n";
  if (sel.border_unresolved)
    out << "  " << sel.border_unresolved
        << " border points: the search for the neighbouring face did not converge (checked as free edges)\n";
  if (sel.whole_surface >= 0) {
    const Cutter& c = sel.library[sel.whole_surface];
    out << "  largest tool gouge-free everywhere: " << c.name() << " (" << to_string(c.type())
        << fmt(", diameter %g", c.diameter());
    if (c.type() == ToolType::bull) out << fmt(", corner radius %g", c.corner_radius());
    out << ")\n";
  } else {
    out << "  no tool of the library is gouge-free everywhere\n";
  }
  // How often each tool is the per-point pick, largest first.
  std::vector<std::size_t> picks(sel.library.size(), 0);
  for (const SiteSelection& s : sel.sites)
    if (s.machinable && s.tool >= 0) ++picks[s.tool];
  out << "  per point:";
  int listed = 0;
  for (std::size_t t = 0; t < picks.size() && listed < 6; ++t) {
    if (!picks[t]) continue;
    out << (listed ? ", " : " ") << sel.library[t].name()
        << fmt(" %.1f%%", machinable ? 100.0 * picks[t] / machinable : 0.0);
    ++listed;
  }
  if (!listed) out << " none";
  out << "\n";
  const long w = worst_site(sel);
  if (w >= 0) {
    const SiteSelection& s = sel.sites[static_cast<std::size_t>(w)];
    out << "  every tool gouges at " << sel.without_tool << " points; worst on face "
        << part.faces[s.site.face].name()
        << fmt(" at (%.3f, %.3f, %.3f): ", s.point.x(), s.point.y(), s.point.z());
    if (s.smallest_gouges_locally) {
      out << fmt("design curvature %.4g /mm", s.needed.design_curvature) << ", "
          << sel.library.back().name() << fmt(" allows %.4g /mm", s.needed.allowed_curvature);
      if (s.needed.allowed_curvature > 0)
        out << fmt(" (radius >= %.4g mm)", 1 / s.needed.allowed_curvature);
    } else {
      out << sel.library.back().name() << fmt(" cuts in %.4g mm elsewhere", s.interference);
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace furrow
