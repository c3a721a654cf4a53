// The prediction.json reader (the writer is prediction_file.cpp).
#include <cmath>
#include <tuple>
#include <utility>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/json_fields.hpp"
#include "machining/prediction/prediction_file.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

std::size_t count(const json& v, const std::string& where) {
  const int n = jf::integer(v, where);
  if (n < 0) throw InputError(where + ": must not be negative, got " + std::to_string(n));
  return static_cast<std::size_t>(n);
}

// [a, b], two non-negative whole numbers (z-map node counts, pass indices).
// Not read as a vector2 and converted: a finite 1e300 made that conversion
// undefined behaviour (UBSan in fuzz_prediction_json, docs/testing.md).
std::pair<int, int> count_pair(const json& v, const std::string& where) {
  const json& a = jf::array(v, where);
  if (a.size() != 2) throw InputError(where + ": expected two whole numbers, got " + std::to_string(a.size()) + " values");
  return {static_cast<int>(count(a[0], jf::child(where, 0))), static_cast<int>(count(a[1], jf::child(where, 1)))};
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

ErrorCellStatus status_from_letter(char c, const std::string& where) {
  switch (c) {
    case 'R': return ErrorCellStatus::reached;
    case 'N': return ErrorCellStatus::not_reached;
    case 'O': return ErrorCellStatus::outside;
    case 'M': return ErrorCellStatus::not_machinable;
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
      const bool reached = f.status[k] == ErrorCellStatus::reached;
      if (reached != !a[k].is_null())
        throw InputError(jf::child(wk, k) + (reached ? ": expected a number for a reached cell, got null"
                                                     : ": expected null for a cell that was not reached"));
      if (reached) (*values)[k] = jf::number(a[k], jf::child(wk, k));
    }
  }
  // Optional (files written before boundary samples were flagged): 0 each.
  f.boundary.assign(n, 0);
  if (o.contains("boundary")) {
    const std::string wb = jf::child(where, "boundary");
    const json& b = jf::array(o.at("boundary"), wb);
    if (b.size() != n)
      throw InputError(wb + ": expected " + std::to_string(n) + " values, got " + std::to_string(b.size()));
    for (std::size_t k = 0; k < n; ++k) {
      f.boundary[k] = jf::integer(b[k], jf::child(wb, k));
      if (f.boundary[k] < 0) throw InputError(jf::child(wb, k) + ": expected a count (>= 0)");
    }
  }
  // Optional (files written before the samples were counted per face). A
  // cell's status says some of its samples have that status, so a status
  // letter without a sample of its kind is a contradiction.
  if (const json* samples = jf::optional_member(o, "samples", where)) {
    const std::string wsam = jf::child(where, "samples");
    jf::object(*samples, wsam);
    f.has_samples = true;
    f.samples_reached = count(jf::member(*samples, "reached", wsam), jf::child(wsam, "reached"));
    f.samples_not_reached = count(jf::member(*samples, "not_reached", wsam), jf::child(wsam, "not_reached"));
    f.samples_not_machinable = count(jf::member(*samples, "not_machinable", wsam), jf::child(wsam, "not_machinable"));
    f.samples_outside = count(jf::member(*samples, "outside", wsam), jf::child(wsam, "outside"));
    const std::pair<ErrorCellStatus, std::size_t> kinds[] = {{ErrorCellStatus::reached, f.samples_reached},
                                                             {ErrorCellStatus::not_reached, f.samples_not_reached}};
    for (const auto& [kind, number] : kinds)
      for (std::size_t k = 0; k < n; ++k)
        if (f.status[k] == kind && number == 0)
          throw InputError(jf::child(wsam, kind == ErrorCellStatus::reached ? "reached" : "not_reached") +
                           ": 0, but cell " + std::to_string(k) + " has status '" + status_letter(kind) + "'");
  }
  for (std::size_t k = 0; k < n; ++k)
    if (f.status[k] == ErrorCellStatus::reached && !(f.max_overcut[k] <= f.mean[k] && f.mean[k] <= f.max_undercut[k]))
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
  std::tie(p.zmap.nx, p.zmap.ny) = count_pair(jf::member(z, "nodes", wz), jf::child(wz, "nodes"));
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
  if (samples.contains("boundary"))  // optional: older files have none
    sum.samples_boundary = count(samples.at("boundary"), jf::child(wsam, "boundary"));

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
    std::tie(r.pass_a, r.pass_b) = count_pair(jf::member(scallops[k], "passes", w), jf::child(w, "passes"));
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
  if (const json* rap = jf::optional_member(doc, "rapids", root)) {
    const std::string wr = jf::child(root, "rapids");
    jf::object(*rap, wr);
    p.rapids.written = true;
    p.rapids.checked = count(jf::member(*rap, "checked", wr), jf::child(wr, "checked"));
    p.rapids.unchecked = count(jf::member(*rap, "unchecked", wr), jf::child(wr, "unchecked"));
    const json& stock = jf::member(*rap, "stock", wr);
    if (!stock.is_null()) {
      const std::string ws = jf::child(wr, "stock");
      jf::object(stock, ws);
      p.rapids.has_stock = true;
      p.rapids.stock = Eigen::AlignedBox3d(jf::vector3(jf::member(stock, "min", ws), jf::child(ws, "min")),
                                           jf::vector3(jf::member(stock, "max", ws), jf::child(ws, "max")));
      if (p.rapids.stock.isEmpty()) throw InputError(ws + ": min must not exceed max on any axis");
    }
    const std::string wg = jf::child(wr, "gouges");
    const json& gouges = jf::array(jf::member(*rap, "gouges", wr), wg);
    for (std::size_t k = 0; k < gouges.size(); ++k) {
      const std::string w = jf::child(wg, k);
      const json& o = jf::object(gouges[k], w);
      RapidGougeRecord g;
      g.line = jf::integer(jf::member(o, "line", w), jf::child(w, "line"));
      g.kind = jf::string(jf::member(o, "kind", w), jf::child(w, "kind"));
      if (g.kind != "part" && g.kind != "stock")
        throw InputError(jf::child(w, "kind") + ": expected \"part\" or \"stock\", got " + quote_field(g.kind));
      g.depth = jf::number(jf::member(o, "depth", w), jf::child(w, "depth"));
      if (!(g.depth > 0)) throw InputError(jf::child(w, "depth") + ": must be positive");
      g.at.xyz = jf::vector3(jf::member(o, "xyz", w), jf::child(w, "xyz"));
      if (g.kind == "part") {
        g.at.face = jf::string(jf::member(o, "face", w), jf::child(w, "face"));
        g.at.uv = jf::vector2(jf::member(o, "uv", w), jf::child(w, "uv"));
      }
      p.rapids.gouges.push_back(g);
    }
  }
  if (const json* reg = jf::optional_member(doc, "regions", root)) {
    const std::string wr = jf::child(root, "regions");
    jf::object(*reg, wr);
    p.has_regions = true;
    p.regions_file = jf::string(jf::member(*reg, "file", wr), jf::child(wr, "file"));
    const std::string wb = jf::child(wr, "by_region");
    const json& list = jf::array(jf::member(*reg, "by_region", wr), wb);
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string w = jf::child(wb, k);
      const json& o = jf::object(list[k], w);
      RegionErrorRecord r;
      r.region = jf::integer(jf::member(o, "region", w), jf::child(w, "region"));
      r.face = jf::string(jf::member(o, "face", w), jf::child(w, "face"));
      r.curvature_class = jf::string(jf::member(o, "class", w), jf::child(w, "class"));
      r.samples = jf::integer(jf::member(o, "samples", w), jf::child(w, "samples"));
      r.reached = jf::integer(jf::member(o, "reached", w), jf::child(w, "reached"));
      const json& mean = jf::member(o, "mean", w);
      if ((r.reached > 0) == mean.is_null())
        throw InputError(jf::child(w, "mean") + ": expected a number exactly when samples were reached");
      if (r.reached > 0) r.mean = jf::number(mean, jf::child(w, "mean"));
      r.max_undercut = read_error_at(jf::member(o, "max_undercut", w), jf::child(w, "max_undercut"));
      r.max_overcut = read_error_at(jf::member(o, "max_overcut", w), jf::child(w, "max_overcut"));
      p.regions.push_back(r);
    }
  }
  const std::string wf = jf::child(root, "faces");
  const json& faces = jf::array(jf::member(doc, "faces", root), wf);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    p.faces.push_back(read_face(faces[k], jf::child(wf, k)));
    for (std::size_t l = 0; l < k; ++l)
      if (p.faces[l].name == p.faces[k].name)
        throw InputError(jf::child(jf::child(wf, k), "name") + ": face " + quote_field(p.faces[k].name) + " appears twice");
  }
  return p;
}

Prediction read_prediction(const std::string& path) {
  return parse_prediction_json(jf::read_text(path), path);
}

}  // namespace furrow
