#include "io/cmm/probe_program.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

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

void check_program(const ProbeProgram& program, const std::string& format) {
  const std::string what = format + " program";
  if (!is_name(program.name))
    throw InputError(what + ": name " + quote_field(program.name) + " must be 1-64 letters, digits, '_' or '-'");
  if (!is_label(program.probe.name))
    throw InputError(what + ": probe name \"" + program.probe.name +
                     "\" must be 1-32 letters, digits or '_' (a DMIS sensor label and an I++ tool name)");
  for (unsigned char c : program.part)
    if (c < 0x20 || c > 0x7e || c == '\'')
      throw InputError(what + ": the part name must be printable ASCII without quotes");
  auto positive = [&](double v, const char* name) {
    if (!std::isfinite(v) || !(v > 0)) throw InputError(what + ": " + name + " must be a positive number");
  };
  positive(program.probe.diameter, "probe diameter");
  positive(program.stylus_length, "stylus length");
  positive(program.approach, "approach distance");
  positive(program.retract, "retract distance");
  positive(program.search, "search distance");
  for (const ProgramStep& s : program.steps) {
    if (!is_label(s.point.id))
      throw InputError(what + ": point id " + quote_field(s.point.id) + " is not a label (1-32 letters, digits or '_')");
    check_vector(s.point.xyz, what + ": point " + s.point.id);
    check_vector(s.point.ijk, what + ": point " + s.point.id);
    if (!(s.point.ijk.norm() > 0.5)) throw InputError(what + ": point " + s.point.id + ": ijk is not a unit vector");
    for (const Eigen::Vector3d& m : s.moves_before) check_vector(m, what + ": move before " + s.point.id);
  }
  for (const Eigen::Vector3d& m : program.final_moves) check_vector(m, what + ": final move");
}

}  // namespace furrow
