#include "io/cmm/probe_program.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow {

std::string fixed_number(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

namespace {

bool is_label(const std::string& s) {
  if (s.empty() || s.size() > 32) return false;
  for (unsigned char c : s)
    if (!std::isalnum(c) && c != '_') return false;
  return true;
}

bool is_name(const std::string& s) {
  if (s.empty() || s.size() > 64) return false;
  for (unsigned char c : s)
    if (!std::isalnum(c) && c != '_' && c != '-') return false;
  return true;
}

void check_vector(const Eigen::Vector3d& v, const std::string& where) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(v[k]) || std::abs(v[k]) >= 1e9)
      throw InputError(where + ": coordinate " + std::to_string(v[k]) + " cannot be written");
}

}  // namespace

std::string dmis_label(const std::string& label) {
  std::string out = label;
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

namespace {

bool is_leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

// YYYY-MM-DD, a real calendar day.
bool is_date(const std::string& s) {
  if (s.size() != 10 || s[4] != '-' || s[7] != '-') return false;
  for (std::size_t k : {0, 1, 2, 3, 5, 6, 8, 9})
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) return false;
  const int y = std::stoi(s.substr(0, 4)), m = std::stoi(s.substr(5, 2)), d = std::stoi(s.substr(8, 2));
  static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (m < 1 || m > 12 || d < 1) return false;
  return d <= days[m - 1] + (m == 2 && is_leap(y) ? 1 : 0);
}

bool is_quoted_text(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c > 0x7e || c == '\'' || c == '"') return false;
  return true;
}

}  // namespace

void validate(const ProgramSettings& s, double stylus_length) {
  if (s.revision.size() > 32 || !is_quoted_text(s.revision))
    throw InputError("--revision " + quote_field(s.revision) +
                     " must be at most 32 printable ASCII characters without quotes");
  if (!s.date.empty() && !is_date(s.date))
    throw InputError("--program-date " + quote_field(s.date) + " is not a date YYYY-MM-DD");
  if (s.head_length && (!std::isfinite(*s.head_length) || !(*s.head_length >= stylus_length)))
    throw InputError("--head-length must be at least the stylus length (" + fixed_number(stylus_length, 3) +
                     " mm): it runs from the head's centre of rotation to the ball centre");
  if (s.tolerance) {
    const PointProfileTolerance& t = *s.tolerance;
    if (!std::isfinite(t.lower) || !std::isfinite(t.upper) || t.lower > 0 || t.upper < 0 || !(t.upper - t.lower > 0))
      throw InputError("--tolerance/--outside: the point profile zone must run from a limit <= 0 to one >= 0");
  }
}

std::string tip_sensor_name(const ProbeProgram& program, const TipAngles& tip) {
  return program.probe.name + "_" + tip_name(tip);
}

const char* dmis_measure_word(DatumFeature::Kind kind) {
  switch (kind) {
    case DatumFeature::Kind::plane: return "PLANE";
    case DatumFeature::Kind::line: return "LINE";
    case DatumFeature::Kind::cylinder: return "CIRCLE";
    case DatumFeature::Kind::point: break;
  }
  return "POINT";
}

void check_program(const ProbeProgram& program, const std::string& format) {
  const std::string what = format + " program";
  if (!is_name(program.name))
    throw InputError(what + ": name " + quote_field(program.name) + " must be 1-64 letters, digits, '_' or '-'");
  if (!is_label(program.probe.name))
    throw InputError(what + ": probe name \"" + program.probe.name +
                     "\" must be 1-32 letters, digits or '_' (a DMIS sensor label and an I++ tool name)");
  if (!is_quoted_text(program.part))
    throw InputError(what + ": the part name must be printable ASCII without quotes");
  ProgramSettings settings;
  settings.revision = program.revision;
  settings.date = program.date;
  settings.head_length = program.head_length;
  settings.tolerance = program.tolerance;
  try {
    validate(settings, program.stylus_length);
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
  auto positive = [&](double v, const char* name) {
    if (!std::isfinite(v) || !(v > 0)) throw InputError(what + ": " + name + " must be a positive number");
  };
  positive(program.probe.diameter, "probe diameter");
  positive(program.stylus_length, "stylus length");
  positive(program.approach, "approach distance");
  positive(program.retract, "retract distance");
  positive(program.search, "search distance");
  positive(program.move_speed, "move speed");
  positive(program.measure_speed, "measuring speed");
  if (program.tips.empty() != !program.start_tip)
    throw InputError(what + ": a program with tips needs its start tip, and only such a program has one");
  std::set<std::string> tip_names;
  for (const TipAngles& t : program.tips) {
    if (!std::isfinite(t.a) || !std::isfinite(t.b)) throw InputError(what + ": a tip angle is not a number");
    if (!tip_names.insert(tip_name(t)).second) throw InputError(what + ": tip " + tip_name(t) + " is defined twice");
  }
  if (program.start_tip && !tip_names.count(tip_name(*program.start_tip)))
    throw InputError(what + ": the start tip is not among the program's tips");
  for (const ProgramStep& step : program.steps)
    if (step.point.tip ? !tip_names.count(tip_name(*step.point.tip)) : !program.tips.empty())
      throw InputError(what + ": point " + step.point.id + (step.point.tip ? " has a tip the program does not define"
                                                                           : " has no tip in a program with tips"));
  std::set<std::string> labels;
  if (program.alignment) {
    const PartAlignment& a = *program.alignment;
    if (program.alignment_steps.size() != a.points().size())
      throw InputError(what + ": the alignment has " + std::to_string(a.points().size()) + " points but " +
                       std::to_string(program.alignment_steps.size()) + " steps");
    if (a.method == PartAlignment::Method::datums) {
      if (a.datums.size() != 3) throw InputError(what + ": a 3-2-1 alignment needs 3 datums");
      for (const DatumFeature& d : a.datums) {
        // Each datum sets a direction, an origin or both; a cylinder (a
        // circle in DMIS) sets both in-plane origins, and must have a
        // vertical axis for that.
        const bool sets_origin = d.origin_axis == 'X' || d.origin_axis == 'Y' || d.origin_axis == 'Z';
        const bool sets_axis = d.axis == 'X' || d.axis == 'Y' || d.axis == 'Z';
        const bool circle = d.kind == DatumFeature::Kind::cylinder && std::abs(std::abs(d.direction.z()) - 1) < 1e-9 &&
                            d.radius > 0 && std::isfinite(d.radius);
        if (!is_label(d.label) || d.points.empty() ||
            !(d.kind == DatumFeature::Kind::cylinder ? circle && d.origin_axis == 0 && d.axis == 0
                                                     : sets_origin || sets_axis))
          throw InputError(what + ": datum " + quote_field(d.label) + " cannot be written");
        check_vector(d.origin, what + ": datum " + d.label);
      }
      check_vector(a.origin, what + ": alignment origin");
    }
  } else if (!program.alignment_steps.empty()) {
    throw InputError(what + ": alignment steps without an alignment");
  }
  if (!program.recalled_alignment.empty() && (program.alignment || !is_label(program.recalled_alignment)))
    throw InputError(what + ": recalled alignment " + quote_field(program.recalled_alignment) +
                     (program.alignment ? " beside an alignment of its own" : " is not a label"));
  std::vector<const ProgramStep*> all;
  for (const ProgramStep& s : program.alignment_steps) all.push_back(&s);
  for (const ProgramStep& s : program.steps) all.push_back(&s);
  for (const Eigen::Vector3d& m : program.alignment_final_moves) check_vector(m, what + ": move after the alignment");
  for (const ProgramStep* step : all) {
    const ProgramStep& s = *step;
    if (!is_label(s.point.id))
      throw InputError(what + ": point id " + quote_field(s.point.id) + " is not a label (1-32 letters, digits or '_')");
    if (!labels.insert(dmis_label(s.point.id)).second)
      throw InputError(what + ": point id " + quote_field(s.point.id) +
                       " is another point's DMIS label (labels are upper case)");
    check_vector(s.point.xyz, what + ": point " + s.point.id);
    check_vector(s.point.ijk, what + ": point " + s.point.id);
    if (!(s.point.ijk.norm() > 0.5)) throw InputError(what + ": point " + s.point.id + ": ijk is not a unit vector");
    for (const Eigen::Vector3d& m : s.moves_before) check_vector(m, what + ": move before " + s.point.id);
  }
  for (const Eigen::Vector3d& m : program.final_moves) check_vector(m, what + ": final move");
}

}  // namespace furrow
