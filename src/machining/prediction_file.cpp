#include "machining/prediction_file.hpp"

#include <cmath>

#include "geometry/error.hpp"
#include "io/atomic_file.hpp"
#include "io/json_fields.hpp"

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
  j["max_step_error"] = length(s.max_step_error, "max_step_error");
  j["max_scallop"] = length(s.max_scallop, "max_scallop");
  j["gouge_sites"] = s.gouge_sites;
  j["local_gouge_points"] = s.local_gouge_points;
  j["path_points"] = s.path_points;
  j["points_without_contact"] = s.points_without_contact;
  j["points_in_air"] = s.points_in_air;
  j["points_below_surface"] = s.points_below_surface;
  j["lowest_gap"] = length(s.lowest_gap, "lowest_gap");
  j["samples"] = {{"reached", s.samples_reached},
                  {"not_reached", s.samples_not_reached},
                  {"not_machinable", s.samples_not_machinable}};
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
      a.push_back(f.status[k] == SampleStatus::reached ? length((*values)[k], key) : json(nullptr));
    j[key] = a;
  }
  return j;
}

}  // namespace

char status_letter(SampleStatus status) {
  switch (status) {
    case SampleStatus::reached: return 'R';
    case SampleStatus::not_reached: return 'N';
    case SampleStatus::outside: return 'O';
    case SampleStatus::not_machinable: return 'M';
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
    }
    steps.push_back(o);
  }
  j["steps"] = steps;
  json scallops = json::array();
  for (const ScallopRecord& s : p.scallops) {
    json o = location(s.at);
    o["passes"] = json::array({s.pass_a, s.pass_b});
    o["height"] = length(s.height, "height");
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
  json faces = json::array();
  for (const FaceGridRecord& f : p.faces) faces.push_back(face_json(f));
  j["faces"] = faces;
  return jf::to_text(j);
}

void write_prediction(const Prediction& prediction, const std::string& path) {
  write_file_atomically(path, prediction_to_json_text(prediction));
}

}  // namespace furrow

// ---------------------------------------------------------------- reader

namespace furrow {

namespace {

std::size_t count(const json& v, const std::string& where) {
  const int n = jf::integer(v, where);
  if (n < 0) throw InputError(where + ": must not be negative, got " + std::to_string(n));
  return static_cast<std::size_t>(n);
}

SurfaceLocation read_location(const json& o, const std::string& where) {
  jf::object(o, where);
  SurfaceLocation s;
  s.face = jf::string(jf::member(o, "face", where), jf::child(where, "face"));
  s.uv = jf::vector2(jf::member(o, "uv", where), jf::child(where, "uv"));
  s.xyz = jf::vector3(jf::member(o, "xyz", where), jf::child(where, "xyz"));
  return s;
}

ErrorAt read_error_at(const json& o, const std::string& where) {
  ErrorAt e;
  if (o.is_null()) return e;
  e.found = true;
  e.at = read_location(o, where);
  e.error = jf::number(jf::member(o, "error", where), jf::child(where, "error"));
  return e;
}

SampleStatus status_from_letter(char c, const std::string& where) {
  switch (c) {
    case 'R': return SampleStatus::reached;
    case 'N': return SampleStatus::not_reached;
    case 'O': return SampleStatus::outside;
    case 'M': return SampleStatus::not_machinable;
  }
  throw InputError(where + ": unknown cell status '" + std::string(1, c) + "' (expected R, N, O or M)");
}

FaceGridRecord read_face(const json& o, const std::string& where) {
  jf::object(o, where);
  FaceGridRecord f;
  f.name = jf::string(jf::member(o, "name", where), jf::child(where, "name"));
  const std::string wd = jf::child(where, "domain");
  const json& d = jf::member(o, "domain", where);
  const Eigen::Vector2d du = jf::vector2(jf::member(d, "u", wd), jf::child(wd, "u"));
  const Eigen::Vector2d dv = jf::vector2(jf::member(d, "v", wd), jf::child(wd, "v"));
  if (!(du.y() > du.x()) || !(dv.y() > dv.x())) throw InputError(wd + ": each range must be increasing");
  f.domain = {du.x(), du.y(), dv.x(), dv.y()};
  const std::string wc = jf::child(where, "cells");
  const json& cells = jf::array(jf::member(o, "cells", where), wc);
  if (cells.size() != 2) throw InputError(wc + ": expected [cells_u, cells_v]");
  f.cells_u = jf::integer(cells[0], jf::child(wc, 0));
  f.cells_v = jf::integer(cells[1], jf::child(wc, 1));
  if (f.cells_u < 1 || f.cells_v < 1 || double(f.cells_u) * f.cells_v > 1e8)
    throw InputError(wc + ": cell counts must be between 1 and a sane size");
  const std::size_t n = static_cast<std::size_t>(f.cells_u) * f.cells_v;
  const std::string ws = jf::child(where, "status");
  const json& rows = jf::array(jf::member(o, "status", where), ws);
  if (rows.size() != static_cast<std::size_t>(f.cells_v))
    throw InputError(ws + ": expected " + std::to_string(f.cells_v) + " rows, got " + std::to_string(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::string row = jf::string(rows[r], jf::child(ws, r));
    if (row.size() != static_cast<std::size_t>(f.cells_u))
      throw InputError(jf::child(ws, r) + ": expected " + std::to_string(f.cells_u) + " cells, got " +
                       std::to_string(row.size()));
    for (char c : row) f.status.push_back(status_from_letter(c, jf::child(ws, r)));
  }
  const std::pair<const char*, std::vector<double>*> columns[] = {
      {"mean", &f.mean}, {"max_undercut", &f.max_undercut}, {"max_overcut", &f.max_overcut}};
  for (const auto& [key, values] : columns) {
    const std::string wk = jf::child(where, key);
    const json& a = jf::array(jf::member(o, key, where), wk);
    if (a.size() != n)
      throw InputError(wk + ": expected " + std::to_string(n) + " values, got " + std::to_string(a.size()));
    values->assign(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const bool reached = f.status[k] == SampleStatus::reached;
      if (reached != !a[k].is_null())
        throw InputError(jf::child(wk, k) + (reached ? ": expected a number for a reached cell, got null"
                                                     : ": expected null for a cell that was not reached"));
      if (reached) (*values)[k] = jf::number(a[k], jf::child(wk, k));
    }
  }
  for (std::size_t k = 0; k < n; ++k)
    if (f.status[k] == SampleStatus::reached && !(f.max_overcut[k] <= f.mean[k] && f.mean[k] <= f.max_undercut[k]))
      throw InputError(jf::child(where, "mean") + "[" + std::to_string(k) +
                       "]: the mean lies outside [max_overcut, max_undercut]");
  return f;
}

}  // namespace

Prediction parse_prediction_json(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  jf::object(doc, root);
  Prediction p;
  if (jf::string(jf::member(doc, "format", root), jf::child(root, "format")) != "furrow-prediction")
    throw InputError(jf::child(root, "format") + ": not a furrow prediction");
  const int version = jf::integer(jf::member(doc, "version", root), jf::child(root, "version"));
  if (version != kPredictionFormatVersion)
    throw InputError(jf::child(root, "version") + ": version " + std::to_string(version) +
                     " is not supported (this furrow reads version " + std::to_string(kPredictionFormatVersion) + ")");
  if (jf::string(jf::member(doc, "units", root), jf::child(root, "units")) != "mm")
    throw InputError(jf::child(root, "units") + ": predictions are written in mm");
  p.part = jf::string(jf::member(doc, "part", root), jf::child(root, "part"));
  p.toolpath = jf::string(jf::member(doc, "toolpath", root), jf::child(root, "toolpath"));
  p.tool = parse_tool_json(jf::member(doc, "tool", root).dump(), jf::child(root, "tool"));
  p.tolerance = jf::positive_number(jf::member(doc, "tolerance", root), jf::child(root, "tolerance"));
  p.gouge_threshold = jf::non_negative_number(jf::member(doc, "gouge_threshold", root), jf::child(root, "gouge_threshold"));

  const std::string wz = jf::child(root, "zmap");
  const json& z = jf::object(jf::member(doc, "zmap", root), wz);
  p.zmap.resolution = jf::positive_number(jf::member(z, "resolution", wz), jf::child(wz, "resolution"));
  p.zmap.origin = jf::vector2(jf::member(z, "origin", wz), jf::child(wz, "origin"));
  const Eigen::Vector2d nodes = jf::vector2(jf::member(z, "nodes", wz), jf::child(wz, "nodes"));
  p.zmap.nx = static_cast<int>(nodes.x());
  p.zmap.ny = static_cast<int>(nodes.y());
  p.zmap.moves = count(jf::member(z, "moves", wz), jf::child(wz, "moves"));
  p.zmap.cut_nodes = count(jf::member(z, "cut_nodes", wz), jf::child(wz, "cut_nodes"));

  const std::string wsum = jf::child(root, "summary");
  const json& s = jf::object(jf::member(doc, "summary", root), wsum);
  auto field = [&](const char* key) -> const json& { return jf::member(s, key, wsum); };
  auto at = [&](const char* key) { return jf::child(wsum, key); };
  PredictionSummary& sum = p.summary;
  sum.max_undercut = read_error_at(field("max_undercut"), at("max_undercut"));
  sum.max_overcut = read_error_at(field("max_overcut"), at("max_overcut"));
  sum.steps = count(field("steps"), at("steps"));
  sum.steps_evaluated = count(field("steps_evaluated"), at("steps_evaluated"));
  sum.steps_over_tolerance = count(field("steps_over_tolerance"), at("steps_over_tolerance"));
  sum.max_step_error = jf::number(field("max_step_error"), at("max_step_error"));
  sum.max_scallop = jf::number(field("max_scallop"), at("max_scallop"));
  sum.gouge_sites = count(field("gouge_sites"), at("gouge_sites"));
  sum.local_gouge_points = count(field("local_gouge_points"), at("local_gouge_points"));
  sum.path_points = count(field("path_points"), at("path_points"));
  sum.points_without_contact = count(field("points_without_contact"), at("points_without_contact"));
  sum.points_in_air = count(field("points_in_air"), at("points_in_air"));
  sum.points_below_surface = count(field("points_below_surface"), at("points_below_surface"));
  sum.lowest_gap = jf::number(field("lowest_gap"), at("lowest_gap"));
  const std::string wsam = at("samples");
  const json& samples = jf::object(field("samples"), wsam);
  sum.samples_reached = count(jf::member(samples, "reached", wsam), jf::child(wsam, "reached"));
  sum.samples_not_reached = count(jf::member(samples, "not_reached", wsam), jf::child(wsam, "not_reached"));
  sum.samples_not_machinable = count(jf::member(samples, "not_machinable", wsam), jf::child(wsam, "not_machinable"));

  const std::string wst = jf::child(root, "steps");
  const json& steps = jf::array(jf::member(doc, "steps", root), wst);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const std::string w = jf::child(wst, k);
    const json& o = jf::object(steps[k], w);
    StepRecord r;
    r.pass = jf::integer(jf::member(o, "pass", w), jf::child(w, "pass"));
    r.step = jf::integer(jf::member(o, "step", w), jf::child(w, "step"));
    r.status = jf::string(jf::member(o, "status", w), jf::child(w, "status"));
    if (r.status == "evaluated") {
      r.length = jf::non_negative_number(jf::member(o, "length", w), jf::child(w, "length"));
      r.undercut = read_error_at(jf::member(o, "max_undercut", w), jf::child(w, "max_undercut"));
      r.overcut = read_error_at(jf::member(o, "max_overcut", w), jf::child(w, "max_overcut"));
      r.chord_deviation = jf::non_negative_number(jf::member(o, "chord_deviation", w), jf::child(w, "chord_deviation"));
    }
    p.steps.push_back(r);
  }
  const std::string wsc = jf::child(root, "scallops");
  const json& scallops = jf::array(jf::member(doc, "scallops", root), wsc);
  for (std::size_t k = 0; k < scallops.size(); ++k) {
    const std::string w = jf::child(wsc, k);
    ScallopRecord r;
    r.at = read_location(scallops[k], w);
    const Eigen::Vector2d passes = jf::vector2(jf::member(scallops[k], "passes", w), jf::child(w, "passes"));
    r.pass_a = static_cast<int>(passes.x());
    r.pass_b = static_cast<int>(passes.y());
    r.height = jf::number(jf::member(scallops[k], "height", w), jf::child(w, "height"));
    p.scallops.push_back(r);
  }
  const std::string wg = jf::child(root, "gouge_sites");
  const json& sites = jf::array(jf::member(doc, "gouge_sites", root), wg);
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const std::string w = jf::child(wg, k);
    const json& o = jf::object(sites[k], w);
    GougeSiteRecord r;
    r.id = jf::integer(jf::member(o, "id", w), jf::child(w, "id"));
    r.face = jf::string(jf::member(o, "face", w), jf::child(w, "face"));
    r.depth = jf::non_negative_number(jf::member(o, "depth", w), jf::child(w, "depth"));
    r.deepest = read_location(jf::member(o, "deepest", w), jf::child(w, "deepest"));
    r.area = jf::non_negative_number(jf::member(o, "area_mm2", w), jf::child(w, "area_mm2"));
    r.samples = jf::integer(jf::member(o, "samples", w), jf::child(w, "samples"));
    r.centroid = read_location(jf::member(o, "centroid", w), jf::child(w, "centroid"));
    const std::string wb = jf::child(w, "xyz_box"), wu = jf::child(w, "uv_box");
    const json& b = jf::object(jf::member(o, "xyz_box", w), wb);
    const json& u = jf::object(jf::member(o, "uv_box", w), wu);
    r.box = Eigen::AlignedBox3d(jf::vector3(jf::member(b, "min", wb), jf::child(wb, "min")),
                                jf::vector3(jf::member(b, "max", wb), jf::child(wb, "max")));
    r.uv_box = Eigen::AlignedBox2d(jf::vector2(jf::member(u, "min", wu), jf::child(wu, "min")),
                                   jf::vector2(jf::member(u, "max", wu), jf::child(wu, "max")));
    p.gouge_sites.push_back(r);
  }
  const std::string wl = jf::child(root, "local_gouges");
  const json& local = jf::array(jf::member(doc, "local_gouges", root), wl);
  for (std::size_t k = 0; k < local.size(); ++k) {
    const std::string w = jf::child(wl, k);
    LocalGougeRecord r;
    r.at = read_location(local[k], w);
    r.pass = jf::integer(jf::member(local[k], "pass", w), jf::child(w, "pass"));
    r.point = jf::integer(jf::member(local[k], "point", w), jf::child(w, "point"));
    r.line = jf::integer(jf::member(local[k], "line", w), jf::child(w, "line"));
    r.status = jf::string(jf::member(local[k], "status", w), jf::child(w, "status"));
    r.max_excess = jf::number(jf::member(local[k], "max_excess", w), jf::child(w, "max_excess"));
    const std::string wa = jf::child(w, "directions_deg");
    const json& arcs = jf::array(jf::member(local[k], "directions_deg", w), wa);
    for (std::size_t a = 0; a < arcs.size(); ++a) r.directions_deg.push_back(jf::vector2(arcs[a], jf::child(wa, a)));
    p.local_gouges.push_back(r);
  }
  const std::string wf = jf::child(root, "faces");
  const json& faces = jf::array(jf::member(doc, "faces", root), wf);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    p.faces.push_back(read_face(faces[k], jf::child(wf, k)));
    for (std::size_t l = 0; l < k; ++l)
      if (p.faces[l].name == p.faces[k].name)
        throw InputError(jf::child(jf::child(wf, k), "name") + ": face \"" + p.faces[k].name + "\" appears twice");
  }
  return p;
}

Prediction read_prediction(const std::string& path) {
  return parse_prediction_json(jf::read_text(path), path);
}

}  // namespace furrow
