#include "io/plan_file.hpp"

#include <sstream>
#include <cctype>
#include <cmath>
#include <map>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "base/atomic_file.hpp"
#include "base/json_fields.hpp"
#include "io/part_file.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

std::optional<std::size_t> InspectionPlan::find(const std::string& id) const {
  for (std::size_t k = 0; k < points.size(); ++k)
    if (points[k].id == id) return k;
  return std::nullopt;
}

std::unordered_map<std::string, std::size_t> InspectionPlan::index_by_id() const {
  std::unordered_map<std::string, std::size_t> index;
  index.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) index.emplace(points[k].id, k);
  return index;
}

namespace {

void check_id(const std::string& id, const std::string& where) {
  if (id.empty()) throw InputError(where + ": empty id");
  for (unsigned char c : id)
    if (c == ',' || std::isspace(c) || c < 0x20 || c == '(' || c == ')')
      throw InputError(where + ": id " + quote_field(id) + " contains a comma, a parenthesis or white space (ids are also CSV "
                       "fields and DMIS labels)");
}

Eigen::Vector3d unit(const Eigen::Vector3d& v, const std::string& where) {
  const double n = v.norm();
  if (!(n > 1e-12)) throw InputError(where + ": zero length (a direction is needed)");
  return std::abs(n - 1) > 1e-12 ? Eigen::Vector3d(v / n) : v;
}

PlannedPoint parse_point(const json& jp, const std::string& where, double scale) {
  jf::object(jp, where);
  auto field = [&](const char* key) -> const json& { return jf::member(jp, key, where); };
  auto at = [&](const char* key) { return jf::child(where, key); };
  PlannedPoint p;
  p.id = jf::string(field("id"), at("id"));
  check_id(p.id, at("id"));
  p.order = jf::integer(field("order"), at("order"));
  if (p.order < 1) throw InputError(at("order") + ": must be at least 1");
  p.face = jf::string(field("face"), at("face"));
  const int face_index = jf::integer(field("face_index"), at("face_index"));
  if (face_index < 0) throw InputError(at("face_index") + ": must not be negative");
  p.face_index = static_cast<std::size_t>(face_index);
  if (const json* jr = jf::optional_member(jp, "region", where)) {
    p.region = jf::integer(*jr, at("region"));
    if (*p.region < 0) throw InputError(at("region") + ": must not be negative");
  }
  p.uv = {jf::number(field("u"), at("u")), jf::number(field("v"), at("v"))};
  p.xyz = scale * jf::vector3(field("xyz"), at("xyz"));
  p.ijk = unit(jf::vector3(field("ijk"), at("ijk")), at("ijk"));
  p.approach = scale * jf::vector3(field("approach"), at("approach"));
  p.retract = scale * jf::vector3(field("retract"), at("retract"));
  if (const json* jt = jf::optional_member(jp, "tip", where)) {
    jf::object(*jt, at("tip"));
    const std::string tw = at("tip");
    p.tip = TipAngles{jf::number(jf::member(*jt, "a", tw), jf::child(tw, "a")),
                      jf::number(jf::member(*jt, "b", tw), jf::child(tw, "b"))};
    if (p.tip->a < 0 || p.tip->a > 180) throw InputError(jf::child(tw, "a") + ": must be from 0 to 180 degrees");
    if (std::abs(p.tip->b) > 360) throw InputError(jf::child(tw, "b") + ": must be from -360 to 360 degrees");
  }
  // After unit conversion (docs/formats.md "Limits").
  for (const char* key : {"xyz", "approach", "retract"}) {
    const Eigen::Vector3d& v = key[0] == 'x' ? p.xyz : key[0] == 'a' ? p.approach : p.retract;
    for (int a = 0; a < 3; ++a) limits::check_coordinate(v[a], jf::child(at(key), a));
  }
  return p;
}

UncoveredRegion parse_uncovered(const json& ju, const std::string& where) {
  jf::object(ju, where);
  auto count = [&](const char* key) {
    const int n = jf::integer(jf::member(ju, key, where), jf::child(where, key));
    if (n < 0) throw InputError(jf::child(where, key) + ": must not be negative");
    return n;
  };
  UncoveredRegion u;
  u.region = count("region");
  u.face_index = static_cast<std::size_t>(count("face_index"));
  u.planned = count("planned");
  u.required = count("required");
  if (u.required <= u.planned)
    throw InputError(jf::child(where, "required") + ": " + std::to_string(u.required) +
                     " is not above planned (" + std::to_string(u.planned) + "): the region is covered");
  if (const json* jr = jf::optional_member(ju, "reason", where)) u.reason = jf::string(*jr, jf::child(where, "reason"));
  return u;
}

char axis_letter(const json& j, const std::string& where, bool allow_none) {
  const std::string a = jf::string(j, where);
  if (a == "X" || a == "Y" || a == "Z") return a[0];
  if (allow_none && a.empty()) return 0;
  throw InputError(where + ": " + quote_field(a) + " is not an axis (\"X\", \"Y\" or \"Z\")");
}

std::vector<PlannedPoint> parse_points(const json& j, const std::string& where, double scale) {
  std::vector<PlannedPoint> points;
  const json& arr = jf::array(j, where);
  for (std::size_t k = 0; k < arr.size(); ++k) points.push_back(parse_point(arr[k], jf::child(where, k), scale));
  return points;
}

PartAlignment parse_alignment(const json& j, const std::string& where, double scale) {
  jf::object(j, where);
  PartAlignment a;
  const std::string method = jf::string(jf::member(j, "method", where), jf::child(where, "method"));
  if (method == "datums") a.method = PartAlignment::Method::datums;
  else if (method == "free_form") a.method = PartAlignment::Method::free_form;
  else throw InputError(jf::child(where, "method") + ": " + quote_field(method) + " is not \"datums\" or \"free_form\"");
  if (const json* r = jf::optional_member(j, "reason", where)) a.reason = jf::string(*r, jf::child(where, "reason"));
  if (a.method == PartAlignment::Method::datums) {
    a.origin = scale * jf::vector3(jf::member(j, "origin", where), jf::child(where, "origin"));
    const std::string dw = jf::child(where, "datums");
    const json& jd = jf::array(jf::member(j, "datums", where), dw);
    if (jd.size() != 3) throw InputError(dw + ": a 3-2-1 alignment needs 3 datums, got " + std::to_string(jd.size()));
    for (std::size_t k = 0; k < jd.size(); ++k) {
      const std::string w = jf::child(dw, k);
      jf::object(jd[k], w);
      auto field = [&](const char* key) -> const json& { return jf::member(jd[k], key, w); };
      DatumFeature d;
      d.label = jf::string(field("label"), jf::child(w, "label"));
      const std::string kind = jf::string(field("kind"), jf::child(w, "kind"));
      if (kind == "plane") d.kind = DatumFeature::Kind::plane;
      else if (kind == "line") d.kind = DatumFeature::Kind::line;
      else if (kind == "point") d.kind = DatumFeature::Kind::point;
      else throw InputError(jf::child(w, "kind") + ": " + quote_field(kind) + " is not plane, line or point");
      d.face = jf::string(field("face"), jf::child(w, "face"));
      const int fi = jf::integer(field("face_index"), jf::child(w, "face_index"));
      if (fi < 0) throw InputError(jf::child(w, "face_index") + ": must not be negative");
      d.face_index = static_cast<std::size_t>(fi);
      d.origin = scale * jf::vector3(field("origin"), jf::child(w, "origin"));
      d.direction = unit(jf::vector3(field("direction"), jf::child(w, "direction")), jf::child(w, "direction"));
      d.normal = unit(jf::vector3(field("normal"), jf::child(w, "normal")), jf::child(w, "normal"));
      d.axis = axis_letter(field("axis"), jf::child(w, "axis"), true);
      d.origin_axis = axis_letter(field("origin_axis"), jf::child(w, "origin_axis"), false);
      d.points = parse_points(field("points"), jf::child(w, "points"), scale);
      const std::size_t need = d.kind == DatumFeature::Kind::plane ? 3 : d.kind == DatumFeature::Kind::line ? 2 : 1;
      if (d.points.size() < need)
        throw InputError(jf::child(w, "points") + ": a " + kind + " needs at least " + std::to_string(need) + " points");
      a.datums.push_back(std::move(d));
    }
  } else {
    a.manual = parse_points(jf::member(j, "manual", where), jf::child(where, "manual"), scale);
    if (a.manual.size() < 3) throw InputError(jf::child(where, "manual") + ": at least 3 points are needed");
  }
  return a;
}

json points_json(const std::vector<PlannedPoint>& points);

json alignment_json(const PartAlignment& a) {
  json j;
  j["method"] = to_string(a.method);
  j["reason"] = a.reason;
  if (a.method == PartAlignment::Method::datums) {
    j["origin"] = jf::vector_json(a.origin);
    json datums = json::array();
    for (const DatumFeature& d : a.datums)
      datums.push_back({{"label", d.label},
                        {"kind", to_string(d.kind)},
                        {"face", d.face},
                        {"face_index", d.face_index},
                        {"origin", jf::vector_json(d.origin)},
                        {"direction", jf::vector_json(d.direction)},
                        {"normal", jf::vector_json(d.normal)},
                        {"axis", d.axis ? std::string(1, d.axis) : std::string()},
                        {"origin_axis", std::string(1, d.origin_axis)},
                        {"points", points_json(d.points)}});
    j["datums"] = std::move(datums);
  } else {
    j["manual"] = points_json(a.manual);
  }
  return j;
}

}  // namespace

InspectionPlan parse_plan(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const std::string root = name + ":";
  jf::object(doc, root);
  if (const json* jv = jf::optional_member(doc, "version", root)) {
    const int version = jf::integer(*jv, jf::child(root, "version"));
    if (version != 1)
      throw InputError(jf::child(root, "version") + ": version " + std::to_string(version) +
                       " is not supported (this Furrow reads version 1)");
  }
  const double scale =
      units_to_mm(jf::string(jf::member(doc, "units", root), jf::child(root, "units")),
                  jf::child(root, "units"));
  InspectionPlan plan;
  if (const json* jpart = jf::optional_member(doc, "part", root))
    plan.part = jf::string(*jpart, jf::child(root, "part"));
  const std::string probe_where = jf::child(root, "probe");
  const json& jprobe = jf::object(jf::member(doc, "probe", root), probe_where);
  plan.probe.name =
      jf::string(jf::member(jprobe, "name", probe_where), jf::child(probe_where, "name"));
  plan.probe.diameter = scale * jf::positive_number(jf::member(jprobe, "diameter", probe_where),
                                                    jf::child(probe_where, "diameter"));
  if (plan.probe.diameter < limits::kMinProbeDiameterMm || plan.probe.diameter > limits::kMaxProbeDiameterMm)
  {
    std::ostringstream s;
    s << jf::child(probe_where, "diameter") << ": " << plan.probe.diameter << " mm is outside the probe range "
      << limits::kMinProbeDiameterMm << " to " << limits::kMaxProbeDiameterMm << " mm (docs/formats.md \"Limits\")";
    throw InputError(s.str());
  }

  const std::string points_where = jf::child(root, "points");
  const json& jpoints = jf::array(jf::member(doc, "points", root), points_where);
  if (jpoints.empty()) throw InputError(points_where + ": the plan has no points");
  std::map<std::string, std::size_t> ids;
  std::map<int, std::size_t> orders;
  for (std::size_t k = 0; k < jpoints.size(); ++k) {
    const std::string where = jf::child(points_where, k);
    PlannedPoint p = parse_point(jpoints[k], where, scale);
    if (const auto [it, fresh] = ids.emplace(p.id, k); !fresh)
      throw InputError(jf::child(where, "id") + ": duplicate id " + quote_field(p.id) + " (also points[" +
                       std::to_string(it->second) + "])");
    if (const auto [it, fresh] = orders.emplace(p.order, k); !fresh)
      throw InputError(jf::child(where, "order") + ": duplicate order " + std::to_string(p.order) +
                       " (also points[" + std::to_string(it->second) + "])");
    plan.points.push_back(std::move(p));
  }
  if (const json* ju = jf::optional_member(doc, "uncovered_regions", root)) {
    const std::string where = jf::child(root, "uncovered_regions");
    const json& list = jf::array(*ju, where);
    for (std::size_t k = 0; k < list.size(); ++k)
      plan.uncovered_regions.push_back(parse_uncovered(list[k], jf::child(where, k)));
  }
  if (const json* ja = jf::optional_member(doc, "alignment", root)) {
    const std::string where = jf::child(root, "alignment");
    plan.alignment = parse_alignment(*ja, where, scale);
    for (const PlannedPoint& p : plan.alignment->points())
      if (const auto [it, fresh] = ids.emplace(p.id, 0); !fresh)
        throw InputError(where + ": duplicate id " + quote_field(p.id) + " (ids are unique over points and alignment)");
  }
  return plan;
}

InspectionPlan read_plan(const std::string& path) { return parse_plan(jf::read_text(path), path); }

std::string plan_to_json_text(const InspectionPlan& plan) {
  json doc;
  doc["version"] = 1;
  doc["units"] = "mm";
  if (!plan.part.empty()) doc["part"] = plan.part;
  doc["probe"] = {{"name", plan.probe.name},
                  {"diameter", jf::finite(plan.probe.diameter, "probe diameter")}};
  doc["points"] = points_json(plan.points);
  if (plan.alignment) doc["alignment"] = alignment_json(*plan.alignment);
  if (!plan.uncovered_regions.empty()) {
    json list = json::array();
    for (const UncoveredRegion& u : plan.uncovered_regions)
      list.push_back({{"region", u.region},
                      {"face_index", u.face_index},
                      {"planned", u.planned},
                      {"required", u.required},
                      {"reason", u.reason}});
    doc["uncovered_regions"] = std::move(list);
  }
  return jf::to_text(doc);
}

namespace {

json points_json(const std::vector<PlannedPoint>& list) {
  json points = json::array();
  for (const PlannedPoint& p : list) {
    json jp;
    jp["id"] = p.id;
    jp["order"] = p.order;
    jp["face"] = p.face;
    jp["face_index"] = p.face_index;
    if (p.region) jp["region"] = *p.region;
    jp["u"] = jf::finite(p.uv.x(), "u");
    jp["v"] = jf::finite(p.uv.y(), "v");
    jp["xyz"] = jf::vector_json(p.xyz);
    jp["ijk"] = jf::vector_json(p.ijk);
    jp["approach"] = jf::vector_json(p.approach);
    jp["retract"] = jf::vector_json(p.retract);
    if (p.tip) jp["tip"] = {{"a", jf::finite(p.tip->a, "tip a")}, {"b", jf::finite(p.tip->b, "tip b")}};
    points.push_back(std::move(jp));
  }
  return points;
}

}  // namespace

void write_plan(const InspectionPlan& plan, const std::string& path) {
  write_file_atomically(path, plan_to_json_text(plan));
}

void check_plan_against_part(const InspectionPlan& plan, const Part& part, const std::string& name,
                             double tolerance) {
  std::vector<PlannedPoint> all = plan.points;
  if (plan.alignment)
    for (const PlannedPoint& p : plan.alignment->points()) all.push_back(p);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const PlannedPoint& p = all[k];
    const std::string where = name + ": " + (k < plan.points.size() ? "points[" + std::to_string(k) + "]" : std::string("alignment point")) +
                              " (id " + p.id + ")";
    if (p.face_index >= part.faces.size())
      throw InputError(where + ": face_index " + std::to_string(p.face_index) +
                       " but the part has " + std::to_string(part.faces.size()) + " faces");
    const Face& face = part.faces[p.face_index];
    if (face.name() != p.face)
      throw InputError(where + ": face " + quote_field(p.face) + " but face " +
                       std::to_string(p.face_index) + " of the part is " + quote_field(face.name()));
    const double off = (face.surface().point(p.uv.x(), p.uv.y()) - p.xyz).norm();
    if (!(off <= tolerance))
      throw InputError(where + ": xyz is " + std::to_string(off) +
                       " mm from the face point at its (u, v); the plan was made for another part");
  }
}

}  // namespace furrow
