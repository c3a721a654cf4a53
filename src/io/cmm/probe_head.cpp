#include "io/cmm/probe_head.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <cmath>
#include <set>
#include <sstream>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/json_cursor.hpp"
#include "base/json_fields.hpp"
#include "base/numbers.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {


// Where a head file's members are described (every object refuses others:
// a misspelt key is an error, not a silent default).
const char* const kSee = "docs/formats.md \"Probe head\"";

IndexAxis parse_axis(const JsonCursor& o, double lowest, double highest) {
  o.only({"min", "max", "step"}, kSee);
  IndexAxis axis;
  axis.min = o.number("min");
  axis.max = o.number("max");
  axis.step = o.positive("step");
  if (axis.min < lowest || axis.min > highest)
    throw InputError(o.path("min") + ": must be from " + shortest(lowest) + " to " + shortest(highest) + " degrees");
  if (axis.max < axis.min || axis.max > highest)
    throw InputError(o.path("max") + ": must be from min to " + shortest(highest) + " degrees");
  return axis;
}

}  // namespace

bool IndexAxis::on_grid(double degrees) const {
  constexpr double slack = 1e-9;
  if (!(degrees >= min - slack && degrees <= max + slack)) return false;
  const double k = (degrees - min) / step;
  return std::abs(k - std::round(k)) * step <= slack;
}

Eigen::Vector3d tip_direction(const TipAngles& tip) {
  const double a = tip.a * kPi / 180, b = tip.b * kPi / 180;
  return {std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), -std::cos(a)};
}

std::string tip_name(const TipAngles& tip) {
  auto word = [](double v) {
    std::string s = shortest(v == 0 ? 0.0 : v);  // no "-0"
    for (char& c : s) c = c == '.' ? 'P' : c == '-' ? 'M' : c;
    return s;
  };
  return "A" + word(tip.a) + "B" + word(tip.b);
}

std::optional<TipSensor> split_tip_sensor(const std::string& name) {
  static const std::regex pattern("(.+)_A(M?[0-9]+(?:P[0-9]+)?)B(M?[0-9]+(?:P[0-9]+)?)");
  std::smatch m;
  if (!std::regex_match(name, m, pattern)) return std::nullopt;
  auto value = [](std::string s) {
    for (char& c : s) c = c == 'P' ? '.' : c == 'M' ? '-' : c;
    return std::strtod(s.c_str(), nullptr);
  };
  TipSensor out{m[1], {value(m[2]), value(m[3])}};
  if (!std::isfinite(out.tip.a) || !std::isfinite(out.tip.b)) return std::nullopt;
  if (name != out.base + "_" + tip_name(out.tip)) return std::nullopt;  // not the canonical spelling
  return out;
}

std::string angle_text(double degrees) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", degrees);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

ProbeHead parse_probe_head(const std::string& text, const std::string& name) {
  const json doc = jf::parse_text(text, name);
  const JsonCursor root(doc, name);
  root.only({"head", "stylus", "extension", "probe_body", "qualified"}, kSee);
  ProbeHead h;

  const JsonCursor head = root.at("head");
  head.only({"type", "a", "b", "length", "diameter"}, kSee);
  if (head.has("type")) h.type = head.string("type");
  h.a = parse_axis(head.at("a"), 0, 180);
  h.b = parse_axis(head.at("b"), -360, 360);
  if (head.has("length")) h.head_length = head.non_negative("length");
  if (h.head_length > 0) h.head_diameter = head.positive("diameter");

  const JsonCursor stylus = root.at("stylus");
  stylus.only({"length", "ball_diameter", "stem_diameter"}, kSee);
  h.stylus_length = stylus.positive("length");
  h.ball_diameter = stylus.positive("ball_diameter");
  h.stem_diameter = stylus.positive("stem_diameter");
  if (h.stem_diameter > h.ball_diameter)
    throw InputError(stylus.path("stem_diameter") + ": must not exceed ball_diameter (" + shortest(h.ball_diameter) +
                     " mm)");
  if (!(h.stylus_length > h.ball_diameter / 2))
    throw InputError(stylus.path("length") + ": must exceed the ball radius");

  if (root.has("extension")) {
    const JsonCursor extension = root.at("extension");
    extension.only({"length", "diameter"}, kSee);
    h.extension_length = extension.non_negative("length");
    if (h.extension_length > 0) h.extension_diameter = extension.positive("diameter");
  }

  const JsonCursor body = root.at("probe_body");
  body.only({"length", "diameter"}, kSee);
  h.body_length = body.positive("length");
  h.body_diameter = body.positive("diameter");

  const std::string q_at = root.path("qualified");
  const json& jq = root.array("qualified");
  std::set<std::string> seen;
  for (std::size_t k = 0; k < jq.size(); ++k) {
    const JsonCursor q(jq[k], jf::child(q_at, k));
    q.only({"a", "b"}, kSee);
    TipAngles tip{q.number("a"), q.number("b")};
    if (!h.a.on_grid(tip.a))
      throw InputError(q.path("a") + ": " + shortest(tip.a) + " is not on the head's A grid " + shortest(h.a.min) +
                       " + k * " + shortest(h.a.step) + " up to " + shortest(h.a.max));
    if (!h.b.on_grid(tip.b))
      throw InputError(q.path("b") + ": " + shortest(tip.b) + " is not on the head's B grid " + shortest(h.b.min) +
                       " + k * " + shortest(h.b.step) + " up to " + shortest(h.b.max));
    if (!seen.insert(tip_name(tip)).second) throw InputError(q.where() + ": tip " + tip_name(tip) + " is listed twice");
    h.qualified.push_back(tip);
  }
  return h;
}

ProbeHead read_probe_head(const std::string& path) { return parse_probe_head(jf::read_text(path), path); }

}  // namespace furrow
