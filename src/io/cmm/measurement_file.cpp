#include "io/cmm/measurement_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/atomic_file.hpp"
#include "base/json_fields.hpp"
#include "io/cmm/measurement_qif.hpp"
#include "io/part_file.hpp"
#include "base/text_fields.hpp"

namespace furrow {

const char* to_string(ProbePointKind kind) {
  return kind == ProbePointKind::probe_centre ? "centre" : "contact";
}

ProbePointKind parse_probe_point_kind(const std::string& text, const std::string& where) {
  if (text == "centre" || text == "center" || text == "centres" || text == "centers")
    return ProbePointKind::probe_centre;
  if (text == "contact") return ProbePointKind::contact;
  throw InputError(where + ": " + quote_field(text) + " is neither \"centre\" nor \"contact\"");
}

namespace {

// A source line with its number, comments and blank lines already dropped.
struct Line {
  int number;
  std::string text;
};

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

std::vector<Line> content_lines(const std::string& text, const char* comment) {
  std::vector<Line> lines;
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const std::string t = trim(raw);
    if (t.empty() || t.rfind(comment, 0) == 0) continue;
    lines.push_back({number, t});
  }
  return lines;
}

double parse_number(std::string field, const std::string& name, int line, const std::string& what) {
  field = trim(field);
  std::size_t start = (field.size() > 1 && field[0] == '+') ? 1 : 0;
  double value = 0;
  const char* first = field.data() + start;
  const char* last = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (field.empty() || ec != std::errc() || ptr != last)
    fail(name, line, what + ": " + quote_field(field) + " is not a number");
  if (!std::isfinite(value)) fail(name, line, what + ": " + quote_field(field) + " is not a finite number");
  return value;
}

Eigen::Vector3d unit_direction(const Eigen::Vector3d& v, const std::string& name, int line,
                               const std::string& what) {
  const double n = v.norm();
  if (!(n > 1e-12)) fail(name, line, what + ": the direction (i, j, k) has zero length");
  return v / n;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(s);
  while (std::getline(in, field, sep)) out.push_back(field);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

void add_point(MeasurementSet& set, std::map<std::string, int>& seen, MeasuredPoint p,
               const std::string& name) {
  // After unit conversion (docs/formats.md "Limits").
  for (int a = 0; a < 3; ++a)
    limits::check_coordinate(p.xyz[a], name + ":" + std::to_string(p.line) + ": " + char('x' + a));
  if (static_cast<long>(set.points.size()) >= limits::kMaxFilePoints)
    fail(name, p.line, "more than " + std::to_string(limits::kMaxFilePoints) +
                           " measured points (docs/formats.md \"Limits\")");
  const auto [it, inserted] = seen.emplace(p.id, p.line);
  if (!inserted)
    fail(name, p.line,
         "duplicate id " + quote_field(p.id) + " (first on line " + std::to_string(it->second) + ")");
  set.points.push_back(std::move(p));
}

void parse_csv(const std::string& text, const std::string& name, double scale,
               MeasurementSet& set) {
  const std::vector<Line> lines = content_lines(text, "#");
  if (lines.empty()) throw InputError(name + ": no header line (expected id,x,y,z[,i,j,k])");
  const char* known[] = {"id", "x", "y", "z", "i", "j", "k"};
  std::map<std::string, int> column;
  // Excel writes ';' where the decimal mark is a comma.
  const char separator = csv_separator(lines[0].text);
  const std::vector<std::string> header = split(lines[0].text, separator);
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string h = to_lower(trim(header[c]));
    if (std::find(std::begin(known), std::end(known), h) == std::end(known))
      fail(name, lines[0].number,
           "unknown column " + quote_field(trim(header[c])) + " (the header names id, x, y, z, i, j, k)");
    if (!column.emplace(h, static_cast<int>(c)).second)
      fail(name, lines[0].number, "column " + quote_field(h) + " appears twice");
  }
  for (const char* c : {"x", "y", "z"})
    if (!column.count(c))
      fail(name, lines[0].number, std::string("missing column \"") + c + "\" (need x, y, z)");
  const int directions =
      static_cast<int>(column.count("i") + column.count("j") + column.count("k"));
  if (directions != 0 && directions != 3)
    fail(name, lines[0].number, "columns i, j, k come together or not at all");
  set.ids_from_file = column.count("id") > 0;

  std::map<std::string, int> seen;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const Line& line = lines[l];
    const std::vector<std::string> fields = split(line.text, separator);
    if (fields.size() != header.size())
      fail(name, line.number,
           "expected " + std::to_string(header.size()) + " fields, got " +
               std::to_string(fields.size()));
    MeasuredPoint p;
    p.line = line.number;
    auto number = [&](const char* col) {
      return parse_number(fields[column.at(col)], name, line.number, std::string("column ") + col);
    };
    p.xyz = scale * Eigen::Vector3d(number("x"), number("y"), number("z"));
    if (directions == 3)
      p.ijk = unit_direction({number("i"), number("j"), number("k")}, name, line.number, "i, j, k");
    if (set.ids_from_file) {
      p.id = trim(fields[column.at("id")]);
      if (p.id.empty()) fail(name, line.number, "empty id");
    } else {
      p.id = std::to_string(set.points.size() + 1);
    }
    add_point(set, seen, std::move(p), name);
  }
}

void parse_xyz(const std::string& text, const std::string& name, double scale,
               MeasurementSet& set) {
  std::size_t columns = 0;
  int first_line = 0;
  std::map<std::string, int> seen;
  for (const Line& line : content_lines(text, "#")) {
    std::istringstream in(line.text);
    std::vector<std::string> fields;
    for (std::string f; in >> f;) fields.push_back(f);
    if (columns == 0) {
      if (fields.size() != 3 && fields.size() != 6)
        fail(name, line.number,
             "expected \"x y z\" or \"x y z i j k\", got " + std::to_string(fields.size()) +
                 " fields");
      columns = fields.size();
      first_line = line.number;
    } else if (fields.size() != columns) {
      fail(name, line.number,
           "expected " + std::to_string(columns) + " fields like line " +
               std::to_string(first_line) + ", got " + std::to_string(fields.size()));
    }
    double v[6];
    for (std::size_t c = 0; c < columns; ++c)
      v[c] = parse_number(fields[c], name, line.number, "field " + std::to_string(c + 1));
    MeasuredPoint p;
    p.line = line.number;
    p.id = std::to_string(set.points.size() + 1);
    p.xyz = scale * Eigen::Vector3d(v[0], v[1], v[2]);
    if (columns == 6) p.ijk = unit_direction({v[3], v[4], v[5]}, name, line.number, "i, j, k");
    add_point(set, seen, std::move(p), name);
  }
  set.ids_from_file = false;
}

// F(label)=FEAT/POINT,CART,x,y,z,i,j,k nominals and FA(label)=... actuals.
void parse_dmis_results(const std::string& text, const std::string& name, MeasurementSet& set) {
  double scale = 1;
  std::map<std::string, std::pair<Eigen::Vector3d, Eigen::Vector3d>> nominals;
  std::map<std::string, int> nominal_line;
  std::map<std::string, int> seen;
  for (const DmisStatement& st : dmis_statements(text)) {
    if (const std::optional<double> units = dmis_units_scale(st, name)) {
      scale = *units;
      continue;
    }
    const std::optional<DmisPointFeature> feature = parse_dmis_point_feature(st, name, scale);
    if (!feature) continue;
    if (!feature->actual) {
      const auto [it, inserted] = nominal_line.emplace(feature->label, st.line);
      if (!inserted)
        fail(name, st.line, "duplicate nominal F(" + quote_field(feature->label) + ") (first on line " + std::to_string(it->second) + ")");
      nominals[feature->label] = {feature->xyz, feature->ijk};
      continue;
    }
    MeasuredPoint p;
    p.id = feature->label;
    p.line = st.line;
    p.xyz = feature->xyz;
    p.ijk = feature->ijk;
    add_point(set, seen, std::move(p), name);
  }
  for (MeasuredPoint& p : set.points) {
    const auto it = nominals.find(p.id);
    if (it == nominals.end()) continue;
    p.nominal = it->second.first;
    p.nominal_ijk = it->second.second;
  }
  set.ids_from_file = true;
}

std::string dmis_compact_upper(const std::string& text) {
  std::string up = text;
  std::transform(up.begin(), up.end(), up.begin(), [](unsigned char c) { return std::toupper(c); });
  up.erase(std::remove_if(up.begin(), up.end(), [](unsigned char c) { return std::isspace(c); }), up.end());
  return up;
}

}  // namespace

MeasurementFormat measurement_format_from_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".csv") return MeasurementFormat::csv;
  if (ext == ".xyz" || ext == ".txt") return MeasurementFormat::xyz;
  if (ext == ".dmi" || ext == ".dmis" || ext == ".dmo" || ext == ".res")
    return MeasurementFormat::dmis;
  if (ext == ".qif") return MeasurementFormat::qif;  // QIF 3.0 Results (measurement_qif.hpp)
  throw InputError(path + ": unknown measurement file type " + quote_field(ext) +
                   " (expected .csv, .xyz/.txt, DMIS .dmi/.dmis/.dmo/.res or QIF .qif)");
}

MeasurementSet parse_measurements(const std::string& file_text, const std::string& name,
                                  MeasurementFormat format, const MeasurementReadOptions& options) {
  // QIF states its own units and probe (docs/qif.md).
  if (format == MeasurementFormat::qif) return parse_qif_measurements(file_text, name, options);
  // A byte-order mark (Excel's "CSV UTF-8", some CMM software) is not content.
  const std::string text = strip_bom(file_text);
  MeasurementSet set;
  set.source = name;
  const double scale = units_to_mm(options.units, name + ": units");
  switch (format) {
    case MeasurementFormat::csv:
      parse_csv(text, name, scale, set);
      break;
    case MeasurementFormat::xyz:
      parse_xyz(text, name, scale, set);
      break;
    case MeasurementFormat::dmis:
      parse_dmis_results(text, name, set);
      break;
    case MeasurementFormat::qif:
    case MeasurementFormat::automatic:
      throw std::logic_error("parse_measurements: resolve the format first");
  }
  if (set.points.empty()) throw InputError(name + ": no measured points in the file");
  set.kind = options.kind.value_or(
      format == MeasurementFormat::dmis ? ProbePointKind::contact : ProbePointKind::probe_centre);
  if (!std::isfinite(options.probe_diameter) || options.probe_diameter < 0)
    throw InputError(name + ": the probe diameter must be a non-negative number");
  if (set.kind == ProbePointKind::probe_centre && !(options.probe_diameter > 0))
    throw InputError(name +
                     ": the points are probe centres, so the probe diameter is needed "
                     "(--probe-diameter, or a plan with a probe)");
  set.probe_radius = set.kind == ProbePointKind::probe_centre ? options.probe_diameter / 2 : 0.0;
  return set;
}

MeasurementSet read_measurements(const std::string& path, const MeasurementReadOptions& options) {
  const MeasurementFormat format = options.format == MeasurementFormat::automatic
                                       ? measurement_format_from_path(path)
                                       : options.format;
  if (format == MeasurementFormat::qif) return read_qif_measurements(path, options);  // parsed in place
  return parse_measurements(json_fields::read_text(path), path, format, options);
}

namespace {

std::string shortest(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  if (ec != std::errc() || !std::isfinite(v))
    throw std::logic_error("measurement writer: a non-finite coordinate");
  return std::string(buf, ptr);
}

}  // namespace

std::string measurements_to_csv(const MeasurementSet& set) {
  const bool directions =
      !set.points.empty() && std::all_of(set.points.begin(), set.points.end(),
                                         [](const MeasuredPoint& p) { return p.ijk.has_value(); });
  std::ostringstream out;
  out << "# " << (set.kind == ProbePointKind::probe_centre ? "probe centres" : "contact points");
  if (set.kind == ProbePointKind::probe_centre)
    out << ", probe diameter " << shortest(2 * set.probe_radius) << " mm";
  out << ", units mm\n";
  out << (directions ? "id,x,y,z,i,j,k\n" : "id,x,y,z\n");
  for (const MeasuredPoint& p : set.points) {
    out << p.id << ',' << shortest(p.xyz.x()) << ',' << shortest(p.xyz.y()) << ','
        << shortest(p.xyz.z());
    if (directions)
      out << ',' << shortest(p.ijk->x()) << ',' << shortest(p.ijk->y()) << ','
          << shortest(p.ijk->z());
    out << '\n';
  }
  return out.str();
}

void write_measurements_csv(const MeasurementSet& set, const std::string& path) {
  write_file_atomically(path, measurements_to_csv(set));
}


std::vector<DmisStatement> dmis_statements(const std::string& text) {
  std::vector<DmisStatement> out;
  std::istringstream in(strip_bom(text));
  std::string raw, pending;
  int number = 0, start = 0;
  while (std::getline(in, raw)) {
    ++number;
    const auto comment = raw.find("$$");
    std::string t = trim(comment == std::string::npos ? raw : raw.substr(0, comment));
    if (t.empty() && pending.empty()) continue;
    if (pending.empty()) start = number;
    const bool continues = !t.empty() && t.back() == '$';
    if (continues) t.pop_back();
    pending += t;
    if (!continues) {
      out.push_back({start, pending});
      pending.clear();
    }
  }
  if (!pending.empty()) out.push_back({start, pending});
  return out;
}

std::optional<double> dmis_units_scale(const DmisStatement& st, const std::string& name) {
  const std::string up = dmis_compact_upper(st.text);
  if (up.rfind("UNITS/", 0) != 0) return std::nullopt;
  const auto comma = up.find(',');
  const std::string unit = up.substr(6, comma == std::string::npos ? std::string::npos : comma - 6);
  if (unit == "MM") return 1.0;
  if (unit == "INCH") return 25.4;
  const std::string shown = quote_field(unit);  // cut when long, shown without its quotes
  fail(name, st.line, "UNITS/" + shown.substr(1, shown.size() - 2) + " is not supported (MM or INCH)");
}

std::optional<DmisPointFeature> parse_dmis_point_feature(const DmisStatement& st, const std::string& name,
                                                         double scale) {
  const std::string up = dmis_compact_upper(st.text);
  const bool actual = up.rfind("FA(", 0) == 0;
  if (!actual && up.rfind("F(", 0) != 0) return std::nullopt;
  const auto close = up.find(')');
  const auto equals = up.find('=');
  if (close == std::string::npos || equals != close + 1) return std::nullopt;  // not a feature definition
  const std::string body = up.substr(equals + 1);
  if (body.rfind("FEAT/POINT,", 0) != 0) return std::nullopt;  // other feature types are not ours
  // The label as written (case kept), from the original text.
  std::string original = st.text;
  original.erase(std::remove_if(original.begin(), original.end(), [](unsigned char c) { return std::isspace(c); }),
                 original.end());
  DmisPointFeature f;
  f.actual = actual;
  f.label = original.substr(actual ? 3 : 2, close - (actual ? 3 : 2));
  if (f.label.empty()) fail(name, st.line, "empty feature label");
  // Values from the statement as written, so messages quote the user's text.
  const std::vector<std::string> fields = split(original.substr(equals + 1 + 11), ',');
  if (fields.empty() || to_lower(fields[0]) != "cart")
    fail(name, st.line, "only CART points are supported, got " + quote_field(fields.empty() ? std::string() : fields[0]));
  if (fields.size() != 7)
    fail(name, st.line, "FEAT/POINT,CART needs x,y,z,i,j,k (6 numbers), got " + std::to_string(fields.size() - 1));
  double v[6];
  for (int c = 0; c < 6; ++c) v[c] = parse_number(fields[c + 1], name, st.line, "value " + std::to_string(c + 1));
  f.xyz = scale * Eigen::Vector3d(v[0], v[1], v[2]);
  // After unit conversion (docs/formats.md "Limits").
  for (int a = 0; a < 3; ++a)
    limits::check_coordinate(f.xyz[a], name + ":" + std::to_string(st.line) + ": " + char('x' + a));
  f.ijk = unit_direction({v[3], v[4], v[5]}, name, st.line, "i, j, k");
  return f;
}

}  // namespace furrow
