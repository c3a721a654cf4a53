#include "io/part_file.hpp"

#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "base/atomic_file.hpp"
#include "io/cad/cad_import.hpp"
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

double units_to_mm(const std::string& units, const std::string& where) {
  if (units == "mm" || units == "millimetre" || units == "millimeter") return 1.0;
  if (units == "inch" || units == "in") return 25.4;
  throw InputError(where + ": unknown units " + quote_field(units) + " (expected \"mm\" or \"inch\")");
}

namespace {

// Optional metadata of a face (analytic_surface.hpp); lengths in the file's units.
AnalyticSurface parse_analytic(const JsonCursor& o, double scale) {
  AnalyticSurface a;
  const std::string type = o.string("type");
  const auto t = analytic_type_from_string(type);
  if (!t)
    throw InputError(o.path("type") + ": " + quote_field(type) + " is not plane, cylinder, cone, sphere or torus");
  a.type = *t;
  a.origin = scale * o.vector3("origin");
  const Eigen::Vector3d axis = o.vector3("axis");
  if (!(axis.norm() > 0)) throw InputError(o.path("axis") + ": the axis must not be zero");
  a.axis = axis.normalized();
  const bool round = a.type != AnalyticSurface::Type::plane && a.type != AnalyticSurface::Type::cone;
  if (round) a.radius = scale * o.positive("radius");
  if (a.type == AnalyticSurface::Type::torus) a.minor_radius = scale * o.positive("minor_radius");
  if (a.type == AnalyticSurface::Type::cone) {
    const double deg = o.positive("half_angle_deg");
    if (!(deg < 90)) throw InputError(o.path("half_angle_deg") + ": a cone's half angle must be below 90 degrees");
    a.half_angle = radians(deg);
  }
  if (o.has("deviation_mm")) a.deviation = o.non_negative("deviation_mm");
  return a;
}

Face parse_face(const JsonCursor& o, double scale) {
  std::string name = o.string("name");
  const int degree_u = o.integer("degree_u");
  const int degree_v = o.integer("degree_v");
  std::vector<double> knots_u = o.numbers("knots_u");
  std::vector<double> knots_v = o.numbers("knots_v");

  const std::string cp_where = o.path("control_points");
  const json& jnet = o.array("control_points");
  if (jnet.empty()) throw InputError(cp_where + ": the control net is empty");
  std::vector<std::vector<Eigen::Vector3d>> net(jnet.size());
  for (std::size_t i = 0; i < jnet.size(); ++i) {
    const std::string row_where = jf::child(cp_where, i);
    const json& jrow = jf::array(jnet[i], row_where);
    if (jrow.empty()) throw InputError(row_where + ": the row is empty");
    net[i].reserve(jrow.size());
    for (std::size_t j = 0; j < jrow.size(); ++j)
      net[i].push_back(scale * jf::vector3(jrow[j], jf::child(row_where, j)));
  }

  std::vector<std::vector<double>> weights;
  if (o.has("weights")) {
    const json& jw = o.array("weights");
    for (std::size_t i = 0; i < jw.size(); ++i) weights.push_back(jf::numbers(jw[i], jf::child(o.path("weights"), i)));
  }

  Trim trim;
  if (o.has("trim")) {
    const std::string t_where = o.path("trim");
    const json& jt = o.array("trim");
    std::vector<UvLoop> loops;
    for (std::size_t l = 0; l < jt.size(); ++l) {
      const std::string l_where = jf::child(t_where, l);
      const json& jl = jf::array(jt[l], l_where);
      UvLoop loop;
      for (std::size_t k = 0; k < jl.size(); ++k) loop.push_back(jf::vector2(jl[k], jf::child(l_where, k)));
      loops.push_back(std::move(loop));
    }
    trim = Trim(std::move(loops), t_where);
  }

  const bool reversed = o.has("reversed") && o.boolean("reversed");
  std::string source_type = o.has("source_type") ? o.string("source_type") : std::string();

  NurbsSurface surface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), net, weights, o.where());
  Face face(std::move(name), std::move(surface), std::move(trim), reversed, std::move(source_type));
  if (o.has("analytic")) face.set_analytic(parse_analytic(o.at("analytic"), scale));
  if (o.has("orientation_established")) face.set_orientation_established(o.boolean("orientation_established"));
  return face;
}

}  // namespace

Part parse_part_json(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name + ":");
  Part part;
  part.source_units = root.string("units");
  const double scale = units_to_mm(part.source_units, root.path("units"));
  const std::string faces_where = root.path("faces");
  const json& jfaces = root.array("faces");
  if (jfaces.empty()) throw InputError(faces_where + ": the part has no faces");
  for (std::size_t f = 0; f < jfaces.size(); ++f) {
    Face face = parse_face(JsonCursor(jfaces[f], jf::child(faces_where, f)), scale);
    if (part.find_face(face.name()))
      throw InputError(jf::child(jf::child(faces_where, f), "name") + ": duplicate face name " +
                       quote_field(face.name()));
    part.faces.push_back(std::move(face));
  }
  return part;
}

Part read_part_json(const std::string& path) {
  return parse_part_json(jf::read_text(path), path);
}

Part read_part(const std::string& path) {
  if (is_cad_file(path)) return import_cad(path).part;
  return read_part_json(path);
}

json analytic_json(const AnalyticSurface& a) {
  json j;
  j["type"] = to_string(a.type);
  j["origin"] = jf::vector_json(a.origin);
  j["axis"] = jf::vector_json(a.axis);
  if (a.type != AnalyticSurface::Type::plane && a.type != AnalyticSurface::Type::cone)
    j["radius"] = jf::finite(a.radius, "radius");
  if (a.type == AnalyticSurface::Type::torus) j["minor_radius"] = jf::finite(a.minor_radius, "minor radius");
  if (a.type == AnalyticSurface::Type::cone) j["half_angle_deg"] = jf::finite(degrees(a.half_angle), "half angle");
  j["deviation_mm"] = jf::finite(a.deviation, "deviation");
  return j;
}

std::string part_to_json_text(const Part& part) {
  json jfaces = json::array();
  for (const Face& face : part.faces) {
    const NurbsSurface& s = face.surface();
    json jf_face;
    jf_face["name"] = face.name();
    if (!face.source_type().empty()) jf_face["source_type"] = face.source_type();
    if (const auto& a = face.analytic()) jf_face["analytic"] = analytic_json(*a);
    jf_face["degree_u"] = s.degree_u();
    jf_face["degree_v"] = s.degree_v();
    jf_face["knots_u"] = s.knots_u();
    jf_face["knots_v"] = s.knots_v();
    json net = json::array();
    json weights = json::array();
    for (int i = 0; i < s.num_u(); ++i) {
      json row = json::array();
      json wrow = json::array();
      for (int j = 0; j < s.num_v(); ++j) {
        row.push_back(jf::vector_json(s.control_point(i, j)));
        wrow.push_back(s.weight(i, j));
      }
      net.push_back(std::move(row));
      weights.push_back(std::move(wrow));
    }
    jf_face["control_points"] = std::move(net);
    if (s.is_rational()) jf_face["weights"] = std::move(weights);
    if (!face.trim().empty()) {
      json loops = json::array();
      for (const UvLoop& loop : face.trim().loops()) {
        json jl = json::array();
        for (const auto& p : loop) jl.push_back(jf::vector_json(p));
        loops.push_back(std::move(jl));
      }
      jf_face["trim"] = std::move(loops);
    }
    if (face.reversed()) jf_face["reversed"] = true;
    if (face.orientation_established()) jf_face["orientation_established"] = true;
    jfaces.push_back(std::move(jf_face));
  }
  json doc;
  doc["units"] = "mm";
  doc["faces"] = std::move(jfaces);
  return jf::to_text(doc);
}

void write_part_json(const Part& part, const std::string& path) {
  write_file_atomically(path, part_to_json_text(part));
}

}  // namespace furrow
