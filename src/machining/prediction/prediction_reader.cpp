// The prediction.json reader (the writer is prediction_file.cpp).
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/json_cursor.hpp"
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

SurfaceLocation read_location(const JsonCursor& o) {
  SurfaceLocation s;
  s.face = o.string("face");
  s.uv = o.vector2("uv");
  s.xyz = o.vector3("xyz");
  return s;
}

// A nullable member: null when no sample had that error.
ErrorAt read_error_at(const JsonCursor& parent, const std::string& key) {
  ErrorAt e;
  if (parent.is_null(key)) return e;
  const JsonCursor o = parent.at(key);
  e.found = true;
  e.at = read_location(o);
  e.error = o.number("error");
  return e;
}

Eigen::AlignedBox3d box3(const JsonCursor& o) { return {o.vector3("min"), o.vector3("max")}; }

ErrorCellStatus status_from_letter(char c, const std::string& where) {
  switch (c) {
    case 'R': return ErrorCellStatus::reached;
    case 'N': return ErrorCellStatus::not_reached;
    case 'O': return ErrorCellStatus::outside;
    case 'M': return ErrorCellStatus::not_machinable;
  }
  throw InputError(where + ": unknown cell status '" + std::string(1, c) + "' (expected R, N, O or M)");
}

FaceGridRecord read_face(const JsonCursor& o) {
  FaceGridRecord f;
  f.name = o.string("name");
  const JsonCursor d = o.at("domain");
  const Eigen::Vector2d du = d.vector2("u"), dv = d.vector2("v");
  if (!(du.y() > du.x()) || !(dv.y() > dv.x())) throw InputError(d.where() + ": each range must be increasing");
  f.domain = {du.x(), du.y(), dv.x(), dv.y()};
  const std::string wc = o.path("cells");
  const json& cells = o.array("cells");
  if (cells.size() != 2) throw InputError(wc + ": expected [cells_u, cells_v]");
  f.cells_u = jf::integer(cells[0], jf::child(wc, 0));
  f.cells_v = jf::integer(cells[1], jf::child(wc, 1));
  if (f.cells_u < 1 || f.cells_v < 1 || double(f.cells_u) * f.cells_v > 1e8)
    throw InputError(wc + ": cell counts must be between 1 and a sane size");
  const std::size_t n = static_cast<std::size_t>(f.cells_u) * f.cells_v;
  const std::string ws = o.path("status");
  const json& rows = o.array("status");
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
    const std::string wk = o.path(key);
    const json& a = o.array(key);
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
  if (o.has("boundary")) {
    const std::string wb = o.path("boundary");
    const json& b = o.array("boundary");
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
  if (o.has("samples")) {
    const JsonCursor samples = o.at("samples");
    f.has_samples = true;
    f.samples_reached = samples.count("reached");
    f.samples_not_reached = samples.count("not_reached");
    f.samples_not_machinable = samples.count("not_machinable");
    f.samples_outside = samples.count("outside");
    const std::pair<ErrorCellStatus, std::size_t> kinds[] = {{ErrorCellStatus::reached, f.samples_reached},
                                                             {ErrorCellStatus::not_reached, f.samples_not_reached}};
    for (const auto& [kind, number] : kinds)
      for (std::size_t k = 0; k < n; ++k)
        if (f.status[k] == kind && number == 0)
          throw InputError(samples.path(kind == ErrorCellStatus::reached ? "reached" : "not_reached") +
                           ": 0, but cell " + std::to_string(k) + " has status '" + status_letter(kind) + "'");
  }
  for (std::size_t k = 0; k < n; ++k)
    if (f.status[k] == ErrorCellStatus::reached && !(f.max_overcut[k] <= f.mean[k] && f.mean[k] <= f.max_undercut[k]))
      throw InputError(o.path("mean") + "[" + std::to_string(k) +
                       "]: the mean lies outside [max_overcut, max_undercut]");
  return f;
}

}  // namespace

Prediction parse_prediction_json(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name + ":");
  Prediction p;
  if (root.string("format") != "furrow-prediction") throw InputError(root.path("format") + ": not a furrow prediction");
  const int version = root.integer("version");
  if (version != kPredictionFormatVersion)
    throw InputError(root.path("version") + ": version " + std::to_string(version) +
                     " is not supported (this furrow reads version " + std::to_string(kPredictionFormatVersion) + ")");
  if (root.string("units") != "mm") throw InputError(root.path("units") + ": predictions are written in mm");
  p.part = root.string("part");
  p.toolpath = root.string("toolpath");
  p.tool = parse_tool_json(root.raw("tool").dump(), root.path("tool"));
  if (root.has("tools") || root.has("pass_tools")) {
    const json& tools = root.array("tools");
    if (tools.size() < 2) throw InputError(root.path("tools") + ": written only for two or more tools");
    for (std::size_t k = 0; k < tools.size(); ++k) {
      const JsonCursor t(tools[k], jf::child(root.path("tools"), k));
      t.only({"number", "tool"}, "docs/formats.md \"prediction.json\"");
      ToolUseRecord use;
      use.number = t.integer("number", 0);
      use.tool = parse_tool_json(t.raw("tool").dump(), t.path("tool"));
      for (const ToolUseRecord& before : p.tools)
        if (before.number == use.number)
          throw InputError(t.path("number") + ": tool " + std::to_string(use.number) + " is listed twice");
      p.tools.push_back(use);
    }
    const json& passes = root.array("pass_tools");
    for (std::size_t k = 0; k < passes.size(); ++k) {
      const std::string where = jf::child(root.path("pass_tools"), k);
      const double index = jf::number(passes[k], where);
      if (!(index >= 0 && index < double(p.tools.size()) && index == std::floor(index)))
        throw InputError(where + ": expected an index into tools (0 to " + std::to_string(p.tools.size() - 1) + ")");
      p.pass_tools.push_back(static_cast<int>(index));
    }
  }
  p.tolerance = root.positive("tolerance");
  p.gouge_threshold = root.non_negative("gouge_threshold");

  const JsonCursor z = root.at("zmap");
  p.zmap.resolution = z.positive("resolution");
  p.zmap.origin = z.vector2("origin");
  std::tie(p.zmap.nx, p.zmap.ny) = count_pair(z.raw("nodes"), z.path("nodes"));
  p.zmap.moves = z.count("moves");
  p.zmap.cut_nodes = z.count("cut_nodes");

  const JsonCursor s = root.at("summary");
  PredictionSummary& sum = p.summary;
  sum.max_undercut = read_error_at(s, "max_undercut");
  sum.max_overcut = read_error_at(s, "max_overcut");
  sum.steps = s.count("steps");
  sum.steps_evaluated = s.count("steps_evaluated");
  sum.steps_over_tolerance = s.count("steps_over_tolerance");
  // Optional: older files do not say whether the steps converged.
  if (s.has("steps_not_converged")) sum.steps_not_converged = s.count("steps_not_converged");
  sum.max_step_error = s.number("max_step_error");
  sum.max_scallop = s.number("max_scallop");
  if (s.has("max_cusp")) sum.max_cusp = s.number("max_cusp");  // optional: older files have none
  sum.gouge_sites = s.count("gouge_sites");
  sum.local_gouge_points = s.count("local_gouge_points");
  sum.path_points = s.count("path_points");
  sum.points_without_contact = s.count("points_without_contact");
  sum.points_in_air = s.count("points_in_air");
  sum.points_below_surface = s.count("points_below_surface");
  sum.lowest_gap = s.number("lowest_gap");
  const JsonCursor samples = s.at("samples");
  sum.samples_reached = samples.count("reached");
  sum.samples_not_reached = samples.count("not_reached");
  sum.samples_not_machinable = samples.count("not_machinable");
  if (samples.has("boundary")) sum.samples_boundary = samples.count("boundary");  // optional: older files have none

  const json& steps = root.array("steps");
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const JsonCursor o(steps[k], jf::child(root.path("steps"), k));
    StepRecord r;
    r.pass = o.integer("pass");
    r.step = o.integer("step");
    r.status = o.string("status");
    if (r.status == "evaluated") {
      r.length = o.non_negative("length");
      r.undercut = read_error_at(o, "max_undercut");
      r.overcut = read_error_at(o, "max_overcut");
      r.chord_deviation = o.non_negative("chord_deviation");
      if (o.has("converged")) r.converged = o.boolean("converged");  // optional: older files have none
    }
    p.steps.push_back(r);
  }
  if (sum.steps_not_converged) {
    const auto listed = std::count_if(p.steps.begin(), p.steps.end(),
                                      [](const StepRecord& r) { return r.converged && !*r.converged; });
    if (static_cast<std::size_t>(listed) != *sum.steps_not_converged)
      throw InputError(s.path("steps_not_converged") + ": " + std::to_string(*sum.steps_not_converged) +
                       ", but steps[] has " + std::to_string(listed) + " steps with \"converged\": false");
  }
  const json& scallops = root.array("scallops");
  for (std::size_t k = 0; k < scallops.size(); ++k) {
    const JsonCursor o(scallops[k], jf::child(root.path("scallops"), k));
    ScallopRecord r;
    r.at = read_location(o);
    std::tie(r.pass_a, r.pass_b) = count_pair(o.raw("passes"), o.path("passes"));
    r.height = o.number("height");
    if (o.has("cusp")) {  // optional: older files have none
      const JsonCursor c = o.at("cusp");
      r.has_cusp = true;
      r.cusp = c.number("height");
      r.cusp_at = read_location(c);
    }
    p.scallops.push_back(r);
  }
  const json& sites = root.array("gouge_sites");
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const JsonCursor o(sites[k], jf::child(root.path("gouge_sites"), k));
    GougeSiteRecord r;
    r.id = o.integer("id");
    r.face = o.string("face");
    r.depth = o.non_negative("depth");
    r.deepest = read_location(o.at("deepest"));
    r.area = o.non_negative("area_mm2");
    r.samples = o.integer("samples");
    r.centroid = read_location(o.at("centroid"));
    const JsonCursor b = o.at("xyz_box"), u = o.at("uv_box");
    r.box = box3(b);
    r.uv_box = Eigen::AlignedBox2d(u.vector2("min"), u.vector2("max"));
    p.gouge_sites.push_back(r);
  }
  const json& local = root.array("local_gouges");
  for (std::size_t k = 0; k < local.size(); ++k) {
    const JsonCursor o(local[k], jf::child(root.path("local_gouges"), k));
    LocalGougeRecord r;
    r.at = read_location(o);
    r.pass = o.integer("pass");
    r.point = o.integer("point");
    r.line = o.integer("line");
    r.status = o.string("status");
    r.max_excess = o.number("max_excess");
    const json& arcs = o.array("directions_deg");
    for (std::size_t a = 0; a < arcs.size(); ++a)
      r.directions_deg.push_back(jf::vector2(arcs[a], jf::child(o.path("directions_deg"), a)));
    p.local_gouges.push_back(r);
  }
  if (root.has("rapids")) {
    const JsonCursor rap = root.at("rapids");
    p.rapids.written = true;
    p.rapids.checked = rap.count("checked");
    p.rapids.unchecked = rap.count("unchecked");
    if (!rap.is_null("stock")) {
      const JsonCursor stock = rap.at("stock");
      p.rapids.has_stock = true;
      p.rapids.stock = box3(stock);
      if (p.rapids.stock.isEmpty()) throw InputError(stock.where() + ": min must not exceed max on any axis");
    }
    const json& gouges = rap.array("gouges");
    for (std::size_t k = 0; k < gouges.size(); ++k) {
      const JsonCursor o(gouges[k], jf::child(rap.path("gouges"), k));
      RapidGougeRecord g;
      g.line = o.integer("line");
      g.kind = o.string("kind");
      if (g.kind != "part" && g.kind != "stock")
        throw InputError(o.path("kind") + ": expected \"part\" or \"stock\", got " + quote_field(g.kind));
      g.depth = o.number("depth");
      if (!(g.depth > 0)) throw InputError(o.path("depth") + ": must be positive");
      g.at.xyz = o.vector3("xyz");
      if (g.kind == "part") {
        g.at.face = o.string("face");
        g.at.uv = o.vector2("uv");
      }
      p.rapids.gouges.push_back(g);
    }
  }
  if (root.has("regions")) {
    const JsonCursor reg = root.at("regions");
    p.has_regions = true;
    p.regions_file = reg.string("file");
    const json& list = reg.array("by_region");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const JsonCursor o(list[k], jf::child(reg.path("by_region"), k));
      RegionErrorRecord r;
      r.region = o.integer("region");
      r.face = o.string("face");
      r.curvature_class = o.string("class");
      r.samples = o.integer("samples");
      r.reached = o.integer("reached");
      if ((r.reached > 0) == o.is_null("mean"))
        throw InputError(o.path("mean") + ": expected a number exactly when samples were reached");
      if (r.reached > 0) r.mean = o.number("mean");
      r.max_undercut = read_error_at(o, "max_undercut");
      r.max_overcut = read_error_at(o, "max_overcut");
      p.regions.push_back(r);
    }
  }
  const json& faces = root.array("faces");
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const std::string where = jf::child(root.path("faces"), k);
    p.faces.push_back(read_face(JsonCursor(faces[k], where)));
    for (std::size_t l = 0; l < k; ++l)
      if (p.faces[l].name == p.faces[k].name)
        throw InputError(jf::child(where, "name") + ": face " + quote_field(p.faces[k].name) + " appears twice");
  }
  return p;
}

Prediction read_prediction(const std::string& path) {
  return parse_prediction_json(jf::read_text(path), path);
}

}  // namespace furrow
