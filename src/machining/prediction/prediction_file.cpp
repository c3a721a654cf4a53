#include "machining/prediction/prediction_file.hpp"

#include <cmath>

#include "base/error.hpp"
#include "base/atomic_file.hpp"
#include "base/json_fields.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

constexpr double kLengthQuantum = 1e-7;      // mm
constexpr double kParameterQuantum = 1e-12;  // unit-free

json length(double x, const char* what) {
  return jf::finite(std::round(x / kLengthQuantum) * kLengthQuantum + 0.0, what);
}
json parameter(double x, const char* what) {
  return jf::finite(std::round(x / kParameterQuantum) * kParameterQuantum + 0.0, what);
}
json xyz(const Eigen::Vector3d& p) {
  return json::array({length(p.x(), "x"), length(p.y(), "y"), length(p.z(), "z")});
}
json uv(const Eigen::Vector2d& p) { return json::array({parameter(p.x(), "u"), parameter(p.y(), "v")}); }

json location(const SurfaceLocation& s) {
  json j = json::object();
  j["face"] = s.face;
  j["uv"] = uv(s.uv);
  j["xyz"] = xyz(s.xyz);
  return j;
}

json error_at(const ErrorAt& e) {
  if (!e.found) return nullptr;
  json j = location(e.at);
  j["error"] = length(e.error, "error");
  return j;
}

json tool_json(const ToolSpec& t) {
  json j = json::object();
  j["name"] = t.name;
  j["type"] = to_string(t.type);
  j["diameter"] = jf::finite(t.diameter, "diameter");
  j["corner_radius"] = jf::finite(t.corner_radius, "corner_radius");
  return j;
}

json summary_json(const PredictionSummary& s) {
  json j = json::object();
  j["max_undercut"] = error_at(s.max_undercut);
  j["max_overcut"] = error_at(s.max_overcut);
  j["steps"] = s.steps;
  j["steps_evaluated"] = s.steps_evaluated;
  j["steps_over_tolerance"] = s.steps_over_tolerance;
  if (s.steps_not_converged) j["steps_not_converged"] = *s.steps_not_converged;
  j["max_step_error"] = length(s.max_step_error, "max_step_error");
  j["max_scallop"] = length(s.max_scallop, "max_scallop");
  j["max_cusp"] = length(s.max_cusp, "max_cusp");
  j["gouge_sites"] = s.gouge_sites;
  j["local_gouge_points"] = s.local_gouge_points;
  j["path_points"] = s.path_points;
  j["points_without_contact"] = s.points_without_contact;
  j["points_in_air"] = s.points_in_air;
  j["points_below_surface"] = s.points_below_surface;
  j["lowest_gap"] = length(s.lowest_gap, "lowest_gap");
  j["samples"] = {{"reached", s.samples_reached},
                  {"not_reached", s.samples_not_reached},
                  {"not_machinable", s.samples_not_machinable},
                  {"boundary", s.samples_boundary}};
  return j;
}

json face_json(const FaceGridRecord& f) {
  json j = json::object();
  j["name"] = f.name;
  j["domain"] = {{"u", json::array({f.domain.u0, f.domain.u1})}, {"v", json::array({f.domain.v0, f.domain.v1})}};
  j["cells"] = json::array({f.cells_u, f.cells_v});
  json rows = json::array();
  for (int cj = 0; cj < f.cells_v; ++cj) {
    std::string row(static_cast<std::size_t>(f.cells_u), 'O');
    for (int ci = 0; ci < f.cells_u; ++ci) row[ci] = status_letter(f.status[static_cast<std::size_t>(cj) * f.cells_u + ci]);
    rows.push_back(row);
  }
  j["status"] = rows;
  const std::pair<const char*, const std::vector<double>*> columns[] = {
      {"mean", &f.mean}, {"max_undercut", &f.max_undercut}, {"max_overcut", &f.max_overcut}};
  for (const auto& [key, values] : columns) {
    json a = json::array();
    for (std::size_t k = 0; k < f.status.size(); ++k)
      a.push_back(f.status[k] == ErrorCellStatus::reached ? length((*values)[k], key) : json(nullptr));
    j[key] = a;
  }
  json boundary = json::array();
  for (std::size_t k = 0; k < f.status.size(); ++k) boundary.push_back(k < f.boundary.size() ? f.boundary[k] : 0);
  j["boundary"] = boundary;
  if (f.has_samples)
    j["samples"] = {{"reached", f.samples_reached},
                    {"not_reached", f.samples_not_reached},
                    {"not_machinable", f.samples_not_machinable},
                    {"outside", f.samples_outside}};
  return j;
}

}  // namespace

char status_letter(ErrorCellStatus status) {
  switch (status) {
    case ErrorCellStatus::reached: return 'R';
    case ErrorCellStatus::not_reached: return 'N';
    case ErrorCellStatus::outside: return 'O';
    case ErrorCellStatus::not_machinable: return 'M';
  }
  return '?';
}

std::string prediction_to_json_text(const Prediction& p) {
  json j = json::object();
  j["format"] = "furrow-prediction";
  j["version"] = kPredictionFormatVersion;
  j["units"] = "mm";
  j["part"] = p.part;
  j["toolpath"] = p.toolpath;
  j["tool"] = tool_json(p.tool);
  // Only for a program that changes tools: a one-tool prediction keeps its bytes.
  if (!p.tools.empty()) {
    json tools = json::array();
    for (const ToolUseRecord& t : p.tools) tools.push_back({{"number", t.number}, {"tool", tool_json(t.tool)}});
    j["tools"] = tools;
    j["pass_tools"] = p.pass_tools;
  }
  j["tolerance"] = jf::finite(p.tolerance, "tolerance");
  j["gouge_threshold"] = jf::finite(p.gouge_threshold, "gouge_threshold");
  j["zmap"] = {{"resolution", jf::finite(p.zmap.resolution, "resolution")},
               {"origin", json::array({length(p.zmap.origin.x(), "x"), length(p.zmap.origin.y(), "y")})},
               {"nodes", json::array({p.zmap.nx, p.zmap.ny})},
               {"moves", p.zmap.moves},
               {"cut_nodes", p.zmap.cut_nodes}};
  j["summary"] = summary_json(p.summary);
  json steps = json::array();
  for (const StepRecord& s : p.steps) {
    json o = json::object();
    o["pass"] = s.pass;
    o["step"] = s.step;
    o["status"] = s.status;
    if (s.status == "evaluated") {
      o["length"] = length(s.length, "length");
      o["max_undercut"] = error_at(s.undercut);
      o["max_overcut"] = error_at(s.overcut);
      o["chord_deviation"] = length(s.chord_deviation, "chord_deviation");
      if (s.converged) o["converged"] = *s.converged;
    }
    steps.push_back(o);
  }
  j["steps"] = steps;
  json scallops = json::array();
  for (const ScallopRecord& s : p.scallops) {
    json o = location(s.at);
    o["passes"] = json::array({s.pass_a, s.pass_b});
    o["height"] = length(s.height, "height");
    if (s.has_cusp) {
      json c = location(s.cusp_at);
      c["height"] = length(s.cusp, "cusp.height");
      o["cusp"] = c;
    }
    scallops.push_back(o);
  }
  j["scallops"] = scallops;
  json sites = json::array();
  for (const GougeSiteRecord& s : p.gouge_sites) {
    json o = json::object();
    o["id"] = s.id;
    o["face"] = s.face;
    o["depth"] = length(s.depth, "depth");
    o["deepest"] = location(s.deepest);
    o["area_mm2"] = length(s.area, "area");
    o["samples"] = s.samples;
    o["centroid"] = location(s.centroid);
    o["xyz_box"] = {{"min", xyz(s.box.min())}, {"max", xyz(s.box.max())}};
    o["uv_box"] = {{"min", uv(s.uv_box.min())}, {"max", uv(s.uv_box.max())}};
    sites.push_back(o);
  }
  j["gouge_sites"] = sites;
  json local = json::array();
  for (const LocalGougeRecord& g : p.local_gouges) {
    json o = location(g.at);
    o["pass"] = g.pass;
    o["point"] = g.point;
    o["line"] = g.line;
    o["status"] = g.status;
    o["max_excess"] = jf::finite(g.max_excess, "max_excess");
    json arcs = json::array();
    for (const Eigen::Vector2d& a : g.directions_deg)
      arcs.push_back(json::array({parameter(a.x(), "start"), parameter(a.y(), "width")}));
    o["directions_deg"] = arcs;
    local.push_back(o);
  }
  j["local_gouges"] = local;
  if (p.rapids.written) {
    json gouges = json::array();
    for (const RapidGougeRecord& g : p.rapids.gouges) {
      json o = json::object();
      o["line"] = g.line;
      o["kind"] = g.kind;
      o["depth"] = length(g.depth, "depth");
      o["xyz"] = xyz(g.at.xyz);
      if (g.kind == "part") {
        o["face"] = g.at.face;
        o["uv"] = uv(g.at.uv);
      }
      gouges.push_back(o);
    }
    json stock = nullptr;
    if (p.rapids.has_stock) stock = {{"min", xyz(p.rapids.stock.min())}, {"max", xyz(p.rapids.stock.max())}};
    j["rapids"] = {{"checked", p.rapids.checked}, {"unchecked", p.rapids.unchecked}, {"stock", stock},
                   {"gouges", gouges}};
  }
  if (p.has_regions) {
    json regions = json::array();
    for (const RegionErrorRecord& r : p.regions) {
      json o = json::object();
      o["region"] = r.region;
      o["face"] = r.face;
      o["class"] = r.curvature_class;
      o["samples"] = r.samples;
      o["reached"] = r.reached;
      o["mean"] = r.reached > 0 ? length(r.mean, "mean") : json(nullptr);
      o["max_undercut"] = error_at(r.max_undercut);
      o["max_overcut"] = error_at(r.max_overcut);
      regions.push_back(o);
    }
    j["regions"] = {{"file", p.regions_file}, {"by_region", regions}};
  }
  json faces = json::array();
  for (const FaceGridRecord& f : p.faces) faces.push_back(face_json(f));
  j["faces"] = faces;
  return jf::to_text(j);
}

void write_prediction(const Prediction& prediction, const std::string& path) {
  write_file_atomically(path, prediction_to_json_text(prediction));
}

}  // namespace furrow
