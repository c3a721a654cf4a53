#include "io/cmm/probe_head.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <cmath>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "base/numbers.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

std::string shortest(double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

// The keys an object may hold: a misspelt key is an error, not a silent default.
void only_keys(const json& object, std::initializer_list<const char*> keys, const std::string& where) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) throw InputError(jf::child(where, it.key()) + ": unknown field");
  }
}

IndexAxis parse_axis(const json& j, const std::string& where, double lowest, double highest) {
  jf::object(j, where);
  only_keys(j, {"min", "max", "step"}, where);
  IndexAxis axis;
  axis.min = jf::number(jf::member(j, "min", where), jf::child(where, "min"));
  axis.max = jf::number(jf::member(j, "max", where), jf::child(where, "max"));
  axis.step = jf::positive_number(jf::member(j, "step", where), jf::child(where, "step"));
  if (axis.min < lowest || axis.min > highest)
    throw InputError(jf::child(where, "min") + ": must be from " + shortest(lowest) + " to " + shortest(highest) + " degrees");
  if (axis.max < axis.min || axis.max > highest)
    throw InputError(jf::child(where, "max") + ": must be from min to " + shortest(highest) + " degrees");
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
  jf::object(doc, name);
  only_keys(doc, {"head", "stylus", "extension", "probe_body", "qualified"}, name);
  ProbeHead h;
  auto field = [&](const json& object, const std::string& where, const char* key) {
    return jf::positive_number(jf::member(object, key, where), jf::child(where, key));
  };

  const std::string head_at = jf::child(name, "head");
  const json& jh = jf::object(jf::member(doc, "head", name), head_at);
  only_keys(jh, {"type", "a", "b", "length", "diameter"}, head_at);
  if (const json* t = jf::optional_member(jh, "type", head_at)) h.type = jf::string(*t, jf::child(head_at, "type"));
  h.a = parse_axis(jf::member(jh, "a", head_at), jf::child(head_at, "a"), 0, 180);
  h.b = parse_axis(jf::member(jh, "b", head_at), jf::child(head_at, "b"), -360, 360);
  if (const json* l = jf::optional_member(jh, "length", head_at))
    h.head_length = jf::non_negative_number(*l, jf::child(head_at, "length"));
  if (h.head_length > 0) h.head_diameter = field(jh, head_at, "diameter");

  const std::string stylus_at = jf::child(name, "stylus");
  const json& js = jf::object(jf::member(doc, "stylus", name), stylus_at);
  only_keys(js, {"length", "ball_diameter", "stem_diameter"}, stylus_at);
  h.stylus_length = field(js, stylus_at, "length");
  h.ball_diameter = field(js, stylus_at, "ball_diameter");
  h.stem_diameter = field(js, stylus_at, "stem_diameter");
  if (h.stem_diameter > h.ball_diameter)
    throw InputError(jf::child(stylus_at, "stem_diameter") + ": must not exceed ball_diameter (" +
                     shortest(h.ball_diameter) + " mm)");
  if (!(h.stylus_length > h.ball_diameter / 2))
    throw InputError(jf::child(stylus_at, "length") + ": must exceed the ball radius");

  if (const json* je = jf::optional_member(doc, "extension", name)) {
    const std::string at = jf::child(name, "extension");
    jf::object(*je, at);
    only_keys(*je, {"length", "diameter"}, at);
    h.extension_length = jf::non_negative_number(jf::member(*je, "length", at), jf::child(at, "length"));
    if (h.extension_length > 0) h.extension_diameter = field(*je, at, "diameter");
  }

  const std::string body_at = jf::child(name, "probe_body");
  const json& jb = jf::object(jf::member(doc, "probe_body", name), body_at);
  only_keys(jb, {"length", "diameter"}, body_at);
  h.body_length = field(jb, body_at, "length");
  h.body_diameter = field(jb, body_at, "diameter");

  const std::string q_at = jf::child(name, "qualified");
  const json& jq = jf::array(jf::member(doc, "qualified", name), q_at);
  if (jq.empty()) throw InputError(q_at + ": at least one qualified tip is needed");
  std::set<std::string> seen;
  for (std::size_t k = 0; k < jq.size(); ++k) {
    const std::string at = jf::child(q_at, k);
    jf::object(jq[k], at);
    only_keys(jq[k], {"a", "b"}, at);
    TipAngles tip{jf::number(jf::member(jq[k], "a", at), jf::child(at, "a")),
                  jf::number(jf::member(jq[k], "b", at), jf::child(at, "b"))};
    if (!h.a.on_grid(tip.a))
      throw InputError(jf::child(at, "a") + ": " + shortest(tip.a) + " is not on the head's A grid " + shortest(h.a.min) +
                       " + k * " + shortest(h.a.step) + " up to " + shortest(h.a.max));
    if (!h.b.on_grid(tip.b))
      throw InputError(jf::child(at, "b") + ": " + shortest(tip.b) + " is not on the head's B grid " + shortest(h.b.min) +
                       " + k * " + shortest(h.b.step) + " up to " + shortest(h.b.max));
    if (!seen.insert(tip_name(tip)).second) throw InputError(at + ": tip " + tip_name(tip) + " is listed twice");
    h.qualified.push_back(tip);
  }
  return h;
}

ProbeHead read_probe_head(const std::string& path) { return parse_probe_head(jf::read_text(path), path); }

}  // namespace furrow
