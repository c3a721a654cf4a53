#include "io/cmm/measurement_csv.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

namespace {

// The point fields a column can hold, in the order of `kFieldNames`.
enum Field { kId, kX, kY, kZ, kI, kJ, kK, kNx, kNy, kNz, kNi, kNj, kNk, kFields };
constexpr std::array<const char*, kFields> kFieldNames = {"id", "x",  "y",  "z",  "i",  "j", "k",
                                                          "nx", "ny", "nz", "ni", "nj", "nk"};

// What a header name says. `explicit_actual`: "Actual X" rather than "X".
struct ColumnKind {
  enum Role { unknown, id, actual, nominal, deviation } role = unknown;
  int axis = -1;  // 0..5 for x y z i j k
  bool explicit_actual = false;
};

bool one_of(const std::string& word, std::initializer_list<const char*> words) {
  for (const char* w : words)
    if (word == w) return true;
  return false;
}

ColumnKind::Role role_word(const std::string& w) {
  if (one_of(w, {"act", "actual", "meas", "measured", "ist", "real"})) return ColumnKind::actual;
  if (one_of(w, {"nom", "nominal", "soll", "theo", "theoretical", "target", "nominell"})) return ColumnKind::nominal;
  if (one_of(w, {"dev", "deviation", "err", "error", "abw", "delta", "diff"})) return ColumnKind::deviation;
  return ColumnKind::unknown;
}

int axis_word(const std::string& w) {
  static const std::string axes = "xyzijk";
  return w.size() == 1 && axes.find(w[0]) != std::string::npos ? static_cast<int>(axes.find(w[0])) : -1;
}

// Lower case, units in brackets dropped ("X [mm]"), '_' '-' '.' '/' ':' as
// blanks, split into words.
std::vector<std::string> header_words(const std::string& header) {
  std::string t;
  int depth = 0;
  for (char c : to_lower(header)) {
    if (c == '[' || c == '(') ++depth;
    else if (c == ']' || c == ')') depth = std::max(0, depth - 1);
    else if (depth == 0) t += (c == '_' || c == '-' || c == '.' || c == '/' || c == ':') ? ' ' : c;
  }
  std::istringstream in(t);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

ColumnKind classify(const std::string& header) {
  const std::vector<std::string> w = header_words(header);
  ColumnKind k;
  if (w.empty()) return k;
  std::string joined;
  for (const std::string& s : w) joined += (joined.empty() ? "" : " ") + s;
  if (one_of(joined, {"id", "name", "label", "point", "pt", "feature", "no", "nr", "number", "point id",
                      "point name", "pt id", "feature name", "point no", "point nr", "pointname", "pointid"})) {
    k.role = ColumnKind::id;
    return k;
  }
  auto with = [&](ColumnKind::Role role, int axis) {
    k.role = role;
    k.axis = axis;
    k.explicit_actual = role == ColumnKind::actual;
    return k;
  };
  if (w.size() == 1) {
    const std::string& s = w[0];
    if (const int a = axis_word(s); a >= 0) {  // a bare "X": the actual
      k.role = ColumnKind::actual;
      k.axis = a;
      return k;
    }
    if (s.size() >= 2) {  // "Xnom", "NomX", "Xact"
      const int first = axis_word(s.substr(0, 1)), last = axis_word(s.substr(s.size() - 1));
      if (first >= 0 && role_word(s.substr(1)) != ColumnKind::unknown) return with(role_word(s.substr(1)), first);
      if (last >= 0 && role_word(s.substr(0, s.size() - 1)) != ColumnKind::unknown)
        return with(role_word(s.substr(0, s.size() - 1)), last);
    }
  }
  if (w.size() == 2) {  // "Nominal X", "X act"
    for (int a = 0; a < 2; ++a)
      if (axis_word(w[a]) >= 0 && role_word(w[1 - a]) != ColumnKind::unknown)
        return with(role_word(w[1 - a]), axis_word(w[a]));
  }
  for (const std::string& s : w)
    if (role_word(s) == ColumnKind::deviation) return with(ColumnKind::deviation, -1);
  return k;
}

// Splits `line` at `delimiter` (' ': runs of blanks) honouring RFC 4180
// quotes. Unquoted fields are views into `line`; quoted ones are unescaped
// into `scratch`, reserved to the line's length first so no view moves.
void split_fields(std::string_view line, char delimiter, std::vector<std::string_view>& fields,
                  std::string& scratch, const std::string& name, int number) {
  fields.clear();
  scratch.clear();
  if (scratch.capacity() < line.size()) scratch.reserve(line.size());
  const bool blanks = delimiter == ' ';
  const auto is_delim = [&](char c) { return blanks ? (c == ' ' || c == '\t') : c == delimiter; };
  std::size_t p = 0;
  const std::size_t n = line.size();
  if (blanks) {
    while (p < n && is_delim(line[p])) ++p;
    if (p == n) return;
  }
  while (true) {
    std::size_t q = p;
    while (q < n && (line[q] == ' ' || line[q] == '\t') && !is_delim(line[q])) ++q;  // blanks before a quote
    if (q < n && line[q] == '"') {
      const std::size_t start = scratch.size();
      std::size_t r = q + 1;
      while (true) {
        if (r >= n)
          mf::fail(name, number, "column " + std::to_string(fields.size() + 1) + ": a quote is not closed on its line");
        if (line[r] == '"') {
          if (r + 1 < n && line[r + 1] == '"') {
            scratch += '"';
            r += 2;
            continue;
          }
          ++r;
          break;
        }
        scratch += line[r++];
      }
      while (r < n && (line[r] == ' ' || line[r] == '\t') && !is_delim(line[r])) ++r;
      if (r < n && !is_delim(line[r]))
        mf::fail(name, number, "column " + std::to_string(fields.size() + 1) + ": text after a closing quote");
      fields.emplace_back(scratch.data() + start, scratch.size() - start);
      p = r;
    } else {
      std::size_t r = p;
      while (r < n && !is_delim(line[r])) ++r;
      fields.push_back(line.substr(p, r - p));
      p = r;
    }
    if (p >= n) return;
    ++p;  // the delimiter
    if (blanks) {
      while (p < n && is_delim(line[p])) ++p;
      if (p == n) return;
    }
  }
}

// Tab if the header has one outside quotes, else ';', else ',', else blanks.
char detect_delimiter(std::string_view header) {
  int tabs = 0, semicolons = 0, commas = 0;
  bool quoted = false;
  for (char c : header) {
    if (c == '"') quoted = !quoted;
    else if (!quoted) tabs += c == '\t', semicolons += c == ';', commas += c == ',';
  }
  return tabs ? '\t' : semicolons ? ';' : commas ? ',' : ' ';
}

bool is_content(std::string_view line) {
  const std::string_view t = mf::trimmed(line);
  return !t.empty() && t[0] != '#';
}

struct Layout {
  std::array<int, kFields> column;
  std::size_t count = 0;  // fields per line
  bool directions = false, nominal = false, nominal_directions = false;
};

Layout read_header(std::string_view line, int number, char delimiter, const CsvDialect& dialect,
                   const std::string& name) {
  std::vector<std::string_view> views;
  std::string scratch;
  split_fields(line, delimiter, views, scratch, name, number);
  std::vector<std::string> header;
  for (std::string_view v : views) header.emplace_back(mf::trimmed(v));
  Layout layout;
  layout.column.fill(-1);
  layout.count = header.size();
  std::array<int, kFields> mapped_from;  // column that a dialect mapping filled
  mapped_from.fill(-1);
  for (const auto& [field, wanted] : dialect.columns) {
    const int f = static_cast<int>(std::find(kFieldNames.begin(), kFieldNames.end(), field) - kFieldNames.begin());
    int found = -1;
    for (std::size_t c = 0; c < header.size(); ++c)
      if (to_lower(header[c]) == to_lower(trim(wanted))) {
        if (found >= 0) mf::fail(name, number, "column " + quote_field(wanted) + " (mapped to " + field + ") appears twice");
        found = static_cast<int>(c);
      }
    if (found < 0)
      mf::fail(name, number, "no column " + quote_field(wanted) + " (mapped to " + field + ") in the header");
    layout.column[f] = found;
    mapped_from[f] = found;
  }
  bool table = !dialect.columns.empty();  // nominal/actual table or mapped header: extra columns allowed
  std::array<int, 6> bare, act, nom;
  bare.fill(-1), act.fill(-1), nom.fill(-1);
  int id = -1, unknown = -1;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (std::find(mapped_from.begin(), mapped_from.end(), static_cast<int>(c)) != mapped_from.end()) continue;
    const ColumnKind k = classify(header[c]);
    const int ci = static_cast<int>(c);
    auto take = [&](int& slot) {
      if (slot >= 0) mf::fail(name, number, "column " + quote_field(to_lower(header[c])) + " appears twice");
      slot = ci;
    };
    switch (k.role) {
      case ColumnKind::id: take(id); break;
      case ColumnKind::actual:
        if (k.explicit_actual) table = true;
        take(k.explicit_actual ? act[k.axis] : bare[k.axis]);
        break;
      case ColumnKind::nominal: table = true; take(nom[k.axis]); break;
      case ColumnKind::deviation: table = true; break;
      case ColumnKind::unknown: if (unknown < 0) unknown = ci; break;
    }
  }
  if (unknown >= 0 && !table)
    mf::fail(name, number, "unknown column " + quote_field(header[unknown]) +
                               " (the header names id, x, y, z, i, j, k)");
  if (layout.column[kId] < 0) layout.column[kId] = id;
  for (int a = 0; a < 6; ++a) {
    if (bare[a] >= 0 && act[a] >= 0)
      mf::fail(name, number, "columns " + quote_field(header[bare[a]]) + " and " + quote_field(header[act[a]]) +
                                 " are both the actual " + kFieldNames[kX + a]);
    if (layout.column[kX + a] < 0) layout.column[kX + a] = act[a] >= 0 ? act[a] : bare[a];
    if (layout.column[kNx + a] < 0) layout.column[kNx + a] = nom[a];
  }
  for (int a = 0; a < 3; ++a)
    if (layout.column[kX + a] < 0)
      mf::fail(name, number, std::string("missing column \"") + kFieldNames[kX + a] + "\" (need x, y, z)");
  auto count = [&](int from) {
    return (layout.column[from] >= 0) + (layout.column[from + 1] >= 0) + (layout.column[from + 2] >= 0);
  };
  if (count(kI) % 3) mf::fail(name, number, "columns i, j, k come together or not at all");
  if (count(kNx) % 3) mf::fail(name, number, "nominal columns x, y, z come together or not at all");
  if (count(kNi) % 3) mf::fail(name, number, "nominal columns i, j, k come together or not at all");
  layout.directions = count(kI) == 3;
  layout.nominal = count(kNx) == 3;
  layout.nominal_directions = count(kNi) == 3;
  return layout;
}

}  // namespace

void parse_measurements_csv(std::string_view text, const std::string& name, double scale,
                            const CsvDialect& dialect, MeasurementSet& set) {
  int header_line = 0;
  std::string_view header;
  std::size_t body = 0;  // offset of the line after the header
  {
    std::size_t start = 0;
    int number = 0;
    while (start < text.size() && header_line == 0) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      ++number;
      std::string_view line = text.substr(start, end - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (is_content(line)) header_line = number, header = line;
      start = end + 1;
    }
    body = std::min(start, text.size());
  }
  if (header_line == 0) throw InputError(name + ": no header line (expected id,x,y,z[,i,j,k])");
  const char delimiter = dialect.delimiter.value_or(detect_delimiter(header));
  if (delimiter == ',' && dialect.decimal_comma.value_or(false))
    mf::fail(name, header_line, "a decimal comma needs a delimiter other than ','");
  const bool decimal_comma = dialect.decimal_comma.value_or(delimiter != ',');
  const Layout layout = read_header(header, header_line, delimiter, dialect, name);
  set.ids_from_file = layout.column[kId] >= 0;
  set.points.reserve(mf::count_lines(text.substr(body)));

  std::vector<std::string_view> fields;
  std::string scratch;
  const auto& col = layout.column;
  mf::for_each_line(text.substr(body), [&](int relative, std::string_view line) {
    if (!is_content(line)) return;
    const int number = header_line + relative;
    split_fields(line, delimiter, fields, scratch, name, number);
    if (fields.size() != layout.count)
      mf::fail(name, number, "expected " + std::to_string(layout.count) + " fields, got " +
                                 std::to_string(fields.size()));
    auto value = [&](int f) {
      const int c = col[f];
      double v = 0;
      if (mf::try_number(fields[c], v, decimal_comma) && std::isfinite(v)) return v;
      return mf::number(fields[c], name, number,
                        "column " + std::to_string(c + 1) + " (" + kFieldNames[f] + ")", decimal_comma);
    };
    MeasuredPoint p;
    p.line = number;
    p.xyz = scale * Eigen::Vector3d(value(kX), value(kY), value(kZ));
    if (layout.directions)
      p.ijk = mf::unit_direction({value(kI), value(kJ), value(kK)}, name, number, "i, j, k");
    if (layout.nominal) p.nominal = scale * Eigen::Vector3d(value(kNx), value(kNy), value(kNz));
    if (layout.nominal_directions)
      p.nominal_ijk = mf::unit_direction({value(kNi), value(kNj), value(kNk)}, name, number, "nominal i, j, k");
    if (set.ids_from_file) {
      p.id = std::string(mf::trimmed(fields[col[kId]]));
      if (p.id.empty()) mf::fail(name, number, "empty id");
    } else {
      p.id = std::to_string(set.points.size() + 1);
    }
    mf::add_point(set, std::move(p), name);
  });
}

std::string measurements_to_csv(const MeasurementSet& set) {
  using mf::shortest;
  const bool directions =
      !set.points.empty() && std::all_of(set.points.begin(), set.points.end(),
                                         [](const MeasuredPoint& p) { return p.ijk.has_value(); });
  std::string out;
  out.reserve(set.points.size() * 120 + 128);
  out += "# ";
  out += set.kind == ProbePointKind::probe_centre ? "probe centres" : "contact points";
  if (set.kind == ProbePointKind::probe_centre) out += ", probe diameter " + shortest(2 * set.probe_radius) + " mm";
  out += ", units mm\n";
  out += directions ? "id,x,y,z,i,j,k\n" : "id,x,y,z\n";
  for (const MeasuredPoint& p : set.points) {
    out += p.id;
    for (int a = 0; a < 3; ++a) out += ',' + shortest(p.xyz[a]);
    if (directions)
      for (int a = 0; a < 3; ++a) out += ',' + shortest((*p.ijk)[a]);
    out += '\n';
  }
  return out;
}

void write_measurements_csv(const MeasurementSet& set, const std::string& path) {
  write_file_atomically(path, measurements_to_csv(set));
}

}  // namespace furrow
