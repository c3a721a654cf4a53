#include "inspection/reference_points.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "base/error.hpp"
#include "base/json_cursor.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

// "zx" -> "xz": each axis once, in axis order.
std::string axes(const std::string& text, const std::string& where) {
  std::string out;
  for (char axis : {'x', 'y', 'z'}) {
    const auto n = std::count(text.begin(), text.end(), axis);
    if (n > 1) throw InputError(where + ": axis " + std::string(1, axis) + " given twice in " + quote_field(text));
    if (n == 1) out += axis;
  }
  if (out.size() != text.size() || out.empty())
    throw InputError(where + ": expected the axes the point fixes, some of x, y and z (e.g. \"z\", \"xy\"), got " +
                     quote_field(text));
  return out;
}

}  // namespace

std::size_t ReferencePointSystem::constraints() const {
  std::size_t n = 0;
  for (const ReferencePoint& p : points) n += p.directions.size();
  return n;
}

ReferencePointSystem parse_reference_points(const std::string& text, const std::string& name) {
  namespace jf = json_fields;
  const jf::json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name + ":");
  root.only({"format", "version", "points", "description"}, "docs/formats.md \"RPS file\"");
  if (root.string("format") != "furrow-rps")
    throw InputError(root.path("format") + ": expected \"furrow-rps\"");
  if (root.integer("version") != 1) throw InputError(root.path("version") + ": this furrow reads version 1");
  root.optional_string("description");
  ReferencePointSystem rps;
  rps.source = name;
  const jf::json& list = root.array("points");
  std::set<std::string> ids;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const JsonCursor p(list[k], jf::child(root.path("points"), k));
    p.only({"id", "nominal", "normal", "directions", "weight"}, "docs/formats.md \"RPS file\"");
    ReferencePoint r;
    r.id = trim(p.string("id"));
    if (r.id.empty()) throw InputError(p.path("id") + ": an empty id");
    if (!ids.insert(r.id).second) throw InputError(p.path("id") + ": " + quote_field(r.id) + " is given twice");
    r.nominal = p.vector3("nominal");
    for (int a = 0; a < 3; ++a) limits::check_coordinate(r.nominal[a], p.path("nominal"));
    const Eigen::Vector3d n = p.vector3("normal");
    if (!(n.norm() > 1e-9) || !std::isfinite(n.norm()))
      throw InputError(p.path("normal") + ": expected the outward surface normal, a non-zero vector");
    r.normal = n.normalized();
    r.directions = axes(p.string("directions"), p.path("directions"));
    if (const auto w = p.optional_number("weight")) {
      if (!(*w > 0) || *w > limits::kMaxWeight)
        throw InputError(p.path("weight") + ": expected a weight above 0 and at most 1e6");
      r.weight = *w;
    }
    p.finish("docs/formats.md \"RPS file\"");
    rps.points.push_back(r);
  }
  root.finish("docs/formats.md \"RPS file\"");
  if (rps.constraints() < 6)
    throw InputError(root.path("points") + ": the points fix " + std::to_string(rps.constraints()) +
                     " coordinates; a part has 6 degrees of freedom (a 3-2-1 RPS: three points fixing z, two "
                     "fixing y, one fixing x)");
  return rps;
}

ReferencePointSystem read_reference_points(const std::string& path) {
  return parse_reference_points(json_fields::read_text(path), path);
}

}  // namespace furrow
