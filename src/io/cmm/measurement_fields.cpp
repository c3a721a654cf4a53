#include "io/cmm/measurement_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"

namespace furrow::measurement_fields {

void fail(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

std::string_view trimmed(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

bool try_number(std::string_view field, double& out, bool decimal_comma) {
  field = trimmed(field);
  if (field.size() > 1 && field[0] == '+' && field[1] != '-' && field[1] != '+') field.remove_prefix(1);
  if (field.empty()) return false;
  char buffer[64];
  if (decimal_comma && field.find(',') != std::string_view::npos) {
    // "1,5": one comma, no point; anything else is not a number.
    if (field.size() >= sizeof buffer || field.find('.') != std::string_view::npos ||
        std::count(field.begin(), field.end(), ',') != 1)
      return false;
    std::copy(field.begin(), field.end(), buffer);
    std::replace(buffer, buffer + field.size(), ',', '.');
    field = std::string_view(buffer, field.size());
  }
  double value = 0;
  const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || ptr != field.data() + field.size()) return false;
  out = value;
  return true;
}

double number(std::string_view field, const std::string& name, int line, const std::string& what,
              bool decimal_comma) {
  double value = 0;
  if (!try_number(field, value, decimal_comma))
    fail(name, line, what + ": " + quote_field(std::string(trimmed(field))) + " is not a number");
  if (!std::isfinite(value))
    fail(name, line, what + ": " + quote_field(std::string(trimmed(field))) + " is not a finite number");
  return value;
}

Eigen::Vector3d unit_direction(const Eigen::Vector3d& v, const std::string& name, int line,
                               const std::string& what) {
  const double n = v.norm();
  if (!(n > 1e-12)) fail(name, line, what + ": the direction (i, j, k) has zero length");
  return v / n;
}

std::size_t count_char(std::string_view text, char c) {
  std::size_t n = 0;
  const char* p = text.data();
  const char* const end = p + text.size();
  while (p < end) {
    p = static_cast<const char*>(std::memchr(p, c, static_cast<std::size_t>(end - p)));
    if (!p) break;
    ++n;
    ++p;
  }
  return n;
}

std::size_t count_lines(std::string_view text) { return count_char(text, '\n') + 1; }

void add_point(MeasurementSet& set, MeasuredPoint&& p, const std::string& name) {
  // After unit conversion (docs/formats.md "Limits"); the message is built
  // only when a value is out of range.
  for (int a = 0; a < 3; ++a)
    if (!(std::abs(p.xyz[a]) <= limits::kMaxCoordinateMm))
      limits::check_coordinate(p.xyz[a], name + ":" + std::to_string(p.line) + ": " + char('x' + a));
  if (static_cast<long>(set.points.size()) >= limits::kMaxFilePoints)
    fail(name, p.line, "more than " + std::to_string(limits::kMaxFilePoints) +
                           " measured points (docs/formats.md \"Limits\")");
  set.points.push_back(std::move(p));
}

std::uint64_t label_hash(std::string_view label) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : label) h = (h ^ c) * 1099511628211ull;
  return h;
}

void check_unique_ids(const MeasurementSet& set, const std::string& name) {
  const std::vector<MeasuredPoint>& pts = set.points;
  const auto id = [&](std::size_t k) -> const std::string& { return pts[k].id; };
  const LabelKeys keys = sorted_label_keys(pts.size(), id);
  if (const auto repeat = first_repeat(keys, id))
    fail(name, pts[repeat->first].line,
         "duplicate id " + quote_field(pts[repeat->first].id) + " (first on line " +
             std::to_string(pts[repeat->second].line) + ")");
}

std::string shortest(double v) {
  if (!std::isfinite(v)) throw std::logic_error("measurement writer: a non-finite coordinate");
  return ::furrow::shortest(v);
}

}  // namespace furrow::measurement_fields
