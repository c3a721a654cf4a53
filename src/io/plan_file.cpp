#include "io/plan_file.hpp"

#include <sstream>
#include <cctype>
#include <cmath>
#include <map>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "base/atomic_file.hpp"
#include "base/json_cursor.hpp"
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

PlannedPoint parse_point(const JsonCursor& o, double scale) {
  PlannedPoint p;
  p.id = o.string("id");
  check_id(p.id, o.path("id"));
  p.order = o.integer("order");
  if (p.order < 1) throw InputError(o.path("order") + ": must be at least 1");
  p.face = o.string("face");
  const int face_index = o.integer("face_index");
  if (face_index < 0) throw InputError(o.path("face_index") + ": must not be negative");
  p.face_index = static_cast<std::size_t>(face_index);
  if (o.has("region")) {
    p.region = o.integer("region");
    if (*p.region < 0) throw InputError(o.path("region") + ": must not be negative");
  }
  p.uv = {o.number("u"), o.number("v")};
  p.xyz = scale * o.vector3("xyz");
  p.ijk = unit(o.vector3("ijk"), o.path("ijk"));
  p.approach = scale * o.vector3("approach");
  p.retract = scale * o.vector3("retract");
  if (o.has("tip")) {
    const JsonCursor t = o.at("tip");
    p.tip = TipAngles{t.number("a"), t.number("b")};
    if (p.tip->a < 0 || p.tip->a > 180) throw InputError(t.path("a") + ": must be from 0 to 180 degrees");
    if (std::abs(p.tip->b) > 360) throw InputError(t.path("b") + ": must be from -360 to 360 degrees");
  }
  // After unit conversion (docs/formats.md "Limits").
  for (const char* key : {"xyz", "approach", "retract"}) {
    const Eigen::Vector3d& v = key[0] == 'x' ? p.xyz : key[0] == 'a' ? p.approach : p.retract;
    for (int a = 0; a < 3; ++a) limits::check_coordinate(v[a], jf::child(o.path(key), a));
  }
  return p;
}

UncoveredRegion parse_uncovered(const JsonCursor& o) {
  auto count = [&](const char* key) {
    const int n = o.integer(key);
    if (n < 0) throw InputError(o.path(key) + ": must not be negative");
    return n;
  };
  UncoveredRegion u;
  u.region = count("region");
  u.face_index = static_cast<std::size_t>(count("face_index"));
  u.planned = count("planned");
  u.required = count("required");
  if (u.required <= u.planned)
    throw InputError(o.path("required") + ": " + std::to_string(u.required) + " is not above planned (" +
                     std::to_string(u.planned) + "): the region is covered");
  if (o.has("reason")) u.reason = o.string("reason");
  return u;
}

char axis_letter(const JsonCursor& o, const std::string& key, bool allow_none) {
  const std::string a = o.string(key);
  if (a == "X" || a == "Y" || a == "Z") return a[0];
  if (allow_none && a.empty()) return 0;
  throw InputError(o.path(key) + ": " + quote_field(a) + " is not an axis (\"X\", \"Y\" or \"Z\")");
}

std::vector<PlannedPoint> parse_points(const JsonCursor& o, const std::string& key, double scale) {
  std::vector<PlannedPoint> points;
  const json& arr = o.array(key);
  for (std::size_t k = 0; k < arr.size(); ++k)
    points.push_back(parse_point(JsonCursor(arr[k], jf::child(o.path(key), k)), scale));
  return points;
}

PartAlignment parse_alignment(const JsonCursor& o, double scale) {
  PartAlignment a;
  const std::string method = o.string("method");
  if (method == "datums") a.method = PartAlignment::Method::datums;
  else if (method == "free_form") a.method = PartAlignment::Method::free_form;
  else throw InputError(o.path("method") + ": " + quote_field(method) + " is not \"datums\" or \"free_form\"");
  if (o.has("reason")) a.reason = o.string("reason");
  if (a.method == PartAlignment::Method::datums) {
    a.origin = scale * o.vector3("origin");
    const json& jd = o.array("datums");
    if (jd.size() != 3)
      throw InputError(o.path("datums") + ": a 3-2-1 alignment needs 3 datums, got " + std::to_string(jd.size()));
    for (std::size_t k = 0; k < jd.size(); ++k) {
      const JsonCursor f(jd[k], jf::child(o.path("datums"), k));
      DatumFeature d;
      d.label = f.string("label");
      const std::string kind = f.string("kind");
      if (kind == "plane") d.kind = DatumFeature::Kind::plane;
      else if (kind == "line") d.kind = DatumFeature::Kind::line;
      else if (kind == "point") d.kind = DatumFeature::Kind::point;
      else if (kind == "cylinder") d.kind = DatumFeature::Kind::cylinder;
      else throw InputError(f.path("kind") + ": " + quote_field(kind) + " is not plane, line, point or cylinder");
      d.face = f.string("face");
      const int fi = f.integer("face_index");
      if (fi < 0) throw InputError(f.path("face_index") + ": must not be negative");
      d.face_index = static_cast<std::size_t>(fi);
      d.origin = scale * f.vector3("origin");
      d.direction = unit(f.vector3("direction"), f.path("direction"));
      d.normal = unit(f.vector3("normal"), f.path("normal"));
      d.axis = axis_letter(f, "axis", true);
      d.origin_axis = axis_letter(f, "origin_axis", true);
      d.points = parse_points(f, "points", scale);
      if (d.kind == DatumFeature::Kind::cylinder) d.radius = scale * f.positive("radius");
      if (!d.axis && !d.origin_axis && d.kind != DatumFeature::Kind::cylinder)
        throw InputError(f.path("origin_axis") + ": datum " + d.label + " sets neither a direction (axis) nor an origin");
      const std::size_t need = d.kind == DatumFeature::Kind::plane || d.kind == DatumFeature::Kind::cylinder ? 3
                               : d.kind == DatumFeature::Kind::line                                     ? 2
                                                                                                        : 1;
      if (d.points.size() < need)
        throw InputError(f.path("points") + ": a " + kind + " needs at least " + std::to_string(need) + " points");
      a.datums.push_back(std::move(d));
    }
  } else {
    a.manual = parse_points(o, "manual", scale);
    if (a.manual.size() < 3) throw InputError(o.path("manual") + ": at least 3 points are needed");
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
    for (const DatumFeature& d : a.datums) {
      json entry = {{"label", d.label},
                    {"kind", to_string(d.kind)},
                    {"face", d.face},
                    {"face_index", d.face_index},
                    {"origin", jf::vector_json(d.origin)},
                    {"direction", jf::vector_json(d.direction)},
                    {"normal", jf::vector_json(d.normal)},
                    {"axis", d.axis ? std::string(1, d.axis) : std::string()},
                    {"origin_axis", d.origin_axis ? std::string(1, d.origin_axis) : std::string()},
                    {"points", points_json(d.points)}};
      if (d.kind == DatumFeature::Kind::cylinder) entry["radius"] = jf::finite(d.radius, "datum radius");
      datums.push_back(std::move(entry));
    }
    j["datums"] = std::move(datums);
  } else {
    j["manual"] = points_json(a.manual);
  }
  return j;
}


}  // namespace

InspectionPlan parse_plan(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name + ":");
  if (root.has("version")) {
    const int version = root.integer("version");
    if (version != 1)
      throw InputError(root.path("version") + ": version " + std::to_string(version) +
                       " is not supported (this Furrow reads version 1)");
  }
  const double scale = units_to_mm(root.string("units"), root.path("units"));
  InspectionPlan plan;
  if (root.has("part")) plan.part = root.string("part");
  const JsonCursor probe = root.at("probe");
  plan.probe.name = probe.string("name");
  plan.probe.diameter = scale * probe.positive("diameter");
  if (plan.probe.diameter < limits::kMinProbeDiameterMm || plan.probe.diameter > limits::kMaxProbeDiameterMm) {
    std::ostringstream s;
    s << probe.path("diameter") << ": " << plan.probe.diameter << " mm is outside the probe range "
      << limits::kMinProbeDiameterMm << " to " << limits::kMaxProbeDiameterMm << " mm (docs/formats.md \"Limits\")";
    throw InputError(s.str());
  }

  const std::string points_where = root.path("points");
  const json& jpoints = root.array("points");
  if (jpoints.empty()) throw InputError(points_where + ": the plan has no points");
  std::map<std::string, std::size_t> ids;
  std::map<int, std::size_t> orders;
  for (std::size_t k = 0; k < jpoints.size(); ++k) {
    const std::string where = jf::child(points_where, k);
    PlannedPoint p = parse_point(JsonCursor(jpoints[k], where), scale);
    if (const auto [it, fresh] = ids.emplace(p.id, k); !fresh)
      throw InputError(jf::child(where, "id") + ": duplicate id " + quote_field(p.id) + " (also points[" +
                       std::to_string(it->second) + "])");
    if (const auto [it, fresh] = orders.emplace(p.order, k); !fresh)
      throw InputError(jf::child(where, "order") + ": duplicate order " + std::to_string(p.order) +
                       " (also points[" + std::to_string(it->second) + "])");
    plan.points.push_back(std::move(p));
  }
  if (root.has("uncovered_regions")) {
    const json& list = root.array("uncovered_regions");
    for (std::size_t k = 0; k < list.size(); ++k)
      plan.uncovered_regions.push_back(
          parse_uncovered(JsonCursor(list[k], jf::child(root.path("uncovered_regions"), k))));
  }
  if (root.has("tips")) {
    const json& list = root.array("tips");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const JsonCursor t(list[k], jf::child(root.path("tips"), k));
      t.only({"a", "b", "qualified"}, "docs/formats.md \"Plan\"");
      PlanTip tip{{t.number("a"), t.number("b")}, t.boolean("qualified")};
      if (tip.angles.a < 0 || tip.angles.a > 180) throw InputError(t.path("a") + ": must be from 0 to 180 degrees");
      if (std::abs(tip.angles.b) > 360) throw InputError(t.path("b") + ": must be from -360 to 360 degrees");
      plan.tips.push_back(tip);
    }
  }
  if (root.has("setup")) {
    const JsonCursor st = root.at("setup");
    st.only({"index", "resting_face", "part_to_setup"}, "docs/formats.md \"Plan\"");
    PlanSetupRecord r;
    r.index = st.integer("index", 1);
    if (st.has("resting_face")) r.resting_face = static_cast<std::size_t>(st.integer("resting_face", 0));
    const JsonCursor motion = st.at("part_to_setup");
    motion.only({"rotation", "translation"}, "docs/formats.md \"Plan\"");
    const json& rows = motion.array("rotation");
    if (rows.size() != 3) throw InputError(motion.path("rotation") + ": needs 3 rows of 3 numbers");
    for (std::size_t i = 0; i < 3; ++i)
      r.rotation.row(static_cast<Eigen::Index>(i)) =
          jf::vector3(rows[i], jf::child(motion.path("rotation"), i)).transpose();
    if (!((r.rotation.transpose() * r.rotation - Eigen::Matrix3d::Identity()).norm() < 1e-9) ||
        !(r.rotation.determinant() > 0))
      throw InputError(motion.path("rotation") + ": not a rotation (orthonormal rows, determinant +1)");
    r.translation = scale * motion.vector3("translation");
    plan.setup = r;
  }
  if (root.has("alignment")) {
    const JsonCursor alignment = root.at("alignment");
    plan.alignment = parse_alignment(alignment, scale);
    for (const PlannedPoint& p : plan.alignment->points())
      if (const auto [it, fresh] = ids.emplace(p.id, 0); !fresh)
        throw InputError(alignment.where() + ": duplicate id " + quote_field(p.id) +
                         " (ids are unique over points and alignment)");
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
  if (!plan.tips.empty()) {
    json list = json::array();
    for (const PlanTip& t : plan.tips)
      list.push_back({{"a", jf::finite(t.angles.a, "tip a")}, {"b", jf::finite(t.angles.b, "tip b")},
                      {"qualified", t.qualified}});
    doc["tips"] = std::move(list);
  }
  if (plan.setup) {
    json st;
    st["index"] = plan.setup->index;
    if (plan.setup->resting_face) st["resting_face"] = *plan.setup->resting_face;
    json rows = json::array();
    for (Eigen::Index i = 0; i < 3; ++i) rows.push_back(jf::vector_json(Eigen::Vector3d(plan.setup->rotation.row(i).transpose())));
    st["part_to_setup"] = {{"rotation", std::move(rows)}, {"translation", jf::vector_json(plan.setup->translation)}};
    doc["setup"] = std::move(st);
  }
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
    const Eigen::Vector3d xyz = plan.setup ? plan.setup->to_part(p.xyz) : p.xyz;
    const double off = (face.surface().point(p.uv.x(), p.uv.y()) - xyz).norm();
    if (!(off <= tolerance))
      throw InputError(where + ": xyz is " + std::to_string(off) +
                       " mm from the face point at its (u, v); the plan was made for another part");
  }
}

}  // namespace furrow
