#include "io/cmm/dmis_results.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "base/error.hpp"
#include "base/limits.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/measurement_fields.hpp"

namespace furrow {

namespace mf = measurement_fields;

namespace {

// Calls each(line, statement) for every statement (see dmis_statements);
// the view lives until the call returns.
template <class Each>
void for_each_statement(std::string_view text, Each&& each) {
  std::string pending;
  int start = 0;
  mf::for_each_line(text, [&](int number, std::string_view raw) {
    const auto comment = raw.find("$$");
    std::string_view t = mf::trimmed(comment == std::string_view::npos ? raw : raw.substr(0, comment));
    if (t.empty() && pending.empty()) return;
    const bool continues = !t.empty() && t.back() == '$';
    if (continues) t.remove_suffix(1);
    if (pending.empty() && !continues) return each(number, t);
    if (pending.empty()) start = number;
    pending.append(t);
    if (!continues) {
      each(start, std::string_view(pending));
      pending.clear();
    }
  });
  if (!pending.empty()) each(start, std::string_view(pending));
}

// `s` without blanks, into `out` (whose capacity is reused).
void compact(std::string_view s, std::string& out) {
  out.clear();
  for (char c : s)
    if (!std::isspace(static_cast<unsigned char>(c))) out += c;
}

bool istarts(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t k = 0; k < prefix.size(); ++k)
    if (std::toupper(static_cast<unsigned char>(s[k])) != prefix[k]) return false;
  return true;
}

bool iequals(std::string_view a, std::string_view upper) { return a.size() == upper.size() && istarts(a, upper); }

void split_commas(std::string_view s, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return;
    start = comma + 1;
  }
}

std::optional<double> units_scale(std::string_view up, const std::string& name, int line) {
  if (!istarts(up, "UNITS/")) return std::nullopt;
  const auto comma = up.find(',');
  const std::string_view unit = up.substr(6, comma == std::string_view::npos ? std::string_view::npos : comma - 6);
  if (iequals(unit, "MM")) return 1.0;
  if (iequals(unit, "INCH")) return 25.4;
  std::string u(unit);
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  const std::string shown = quote_field(u);  // cut when long, shown without its quotes
  mf::fail(name, line, "UNITS/" + shown.substr(1, shown.size() - 2) + " is not supported (MM or INCH)");
}

enum class Kind { point, plane, circle, cylinder };

// A feature definition F(label)=FEAT/TYPE,values (compacted statement).
struct FeatureStatement {
  bool actual = false;
  Kind kind = Kind::point;
  std::string_view label;
  std::string_view values;  // after "FEAT/TYPE,"
};

std::optional<FeatureStatement> feature_statement(std::string_view st) {
  FeatureStatement f;
  f.actual = istarts(st, "FA(");
  if (!f.actual && !istarts(st, "F(")) return std::nullopt;
  const auto close = st.find(')');
  if (close == std::string_view::npos || close + 1 >= st.size() || st[close + 1] != '=') return std::nullopt;
  const std::size_t open = f.actual ? 3 : 2;
  f.label = st.substr(open, close - open);
  const std::string_view body = st.substr(close + 2);
  static const std::pair<const char*, Kind> types[] = {
      {"FEAT/POINT,", Kind::point}, {"FEAT/PLANE,", Kind::plane}, {"FEAT/CIRCLE,", Kind::circle}, {"FEAT/CYLNDR,", Kind::cylinder}};
  for (const auto& [prefix, kind] : types)
    if (istarts(body, prefix)) {
      f.kind = kind;
      f.values = body.substr(std::char_traits<char>::length(prefix));
      return f;
    }
  return std::nullopt;  // other feature types are not ours
}

struct Numbers {
  double v[8];
};

// values[first..] as numbers (count of them already checked).
Numbers numbers(const std::vector<std::string_view>& values, std::size_t first, const std::string& name, int line) {
  Numbers n{};
  for (std::size_t c = first; c < values.size(); ++c) {
    double& v = n.v[c - first];
    if (!mf::try_number(values[c], v) || !std::isfinite(v))  // the message only when needed
      v = mf::number(values[c], name, line, "value " + std::to_string(c - first + 1));
  }
  return n;
}

Eigen::Vector3d position(const Numbers& n, double scale, const std::string& name, int line) {
  const Eigen::Vector3d p = scale * Eigen::Vector3d(n.v[0], n.v[1], n.v[2]);
  // After unit conversion (docs/formats.md "Limits").
  for (int a = 0; a < 3; ++a)
    if (!(std::abs(p[a]) <= limits::kMaxCoordinateMm))
      limits::check_coordinate(p[a], name + ":" + std::to_string(line) + ": " + char('x' + a));
  return p;
}

std::string word(std::string_view v) {
  std::string u(v);
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  return quote_field(u);
}

// A point: CART,x,y,z,i,j,k.
void point_values(const FeatureStatement& f, const std::vector<std::string_view>& values, double scale,
                  const std::string& name, int line, Eigen::Vector3d& xyz, Eigen::Vector3d& ijk) {
  if (values.empty() || !iequals(values[0], "CART"))
    mf::fail(name, line, "only CART points are supported, got " + word(values.empty() ? "" : values[0]));
  if (values.size() != 7)
    mf::fail(name, line, "FEAT/POINT,CART needs x,y,z,i,j,k (6 numbers), got " + std::to_string(values.size() - 1));
  const Numbers n = numbers(values, 1, name, line);
  xyz = position(n, scale, name, line);
  ijk = mf::unit_direction({n.v[3], n.v[4], n.v[5]}, name, line, "i, j, k");
  (void)f;
}

MeasuredFeature datum_feature(const FeatureStatement& f, const std::vector<std::string_view>& values, double scale,
                              const std::string& name, int line) {
  MeasuredFeature m;
  m.label = std::string(f.label);
  m.line = line;
  std::size_t first = 1;  // index of CART
  std::string type = "PLANE";
  if (f.kind == Kind::plane) {
    m.type = MeasuredFeatureType::plane;
    first = 0;
  } else {
    m.type = f.kind == Kind::circle ? MeasuredFeatureType::circle : MeasuredFeatureType::cylinder;
    type = f.kind == Kind::circle ? "CIRCLE" : "CYLNDR";
    if (!iequals(values[0], "INNER") && !iequals(values[0], "OUTER"))
      mf::fail(name, line, "FEAT/" + type + " needs INNER or OUTER, got " + word(values[0]));
    m.inner = iequals(values[0], "INNER");
  }
  if (values.size() <= first || !iequals(values[first], "CART"))
    mf::fail(name, line, "only CART features are supported, got " + word(values.size() > first ? values[first] : ""));
  const std::size_t count = values.size() - first - 1;
  const bool ok = f.kind == Kind::plane ? count == 6 : f.kind == Kind::circle ? count == 7 : (count == 7 || count == 8);
  if (!ok) {
    const char* wanted = f.kind == Kind::plane    ? "x,y,z,i,j,k (6 numbers)"
                         : f.kind == Kind::circle ? "x,y,z,i,j,k,diam (7 numbers)"
                                                  : "x,y,z,i,j,k,diam[,length] (7 or 8 numbers)";
    mf::fail(name, line, "FEAT/" + type + (first ? ",INNER|OUTER" : "") + ",CART needs " + wanted + ", got " +
                             std::to_string(count));
  }
  const Numbers n = numbers(values, first + 1, name, line);
  m.position = position(n, scale, name, line);
  m.direction = mf::unit_direction({n.v[3], n.v[4], n.v[5]}, name, line, "i, j, k");
  if (f.kind != Kind::plane) {
    m.diameter = scale * n.v[6];
    if (!(m.diameter > 0)) mf::fail(name, line, "the diameter must be positive");
    if (count == 8) {
      m.length = scale * n.v[7];
      if (!(m.length >= 0)) mf::fail(name, line, "the length must not be negative");
    }
  }
  return m;
}

struct Nominal {
  std::string label;
  Eigen::Vector3d xyz, ijk;
  int line;
};

// Statements that may start a line with `prefix` (any case): an upper bound
// of the actuals, to reserve the points once.
std::size_t lines_starting(std::string_view text, std::string_view prefix) {
  std::size_t count = 0;
  mf::for_each_line(text, [&](int, std::string_view line) { count += istarts(mf::trimmed(line), prefix); });
  return count;
}

}  // namespace

void parse_dmis_results(std::string_view text, const std::string& name, MeasurementSet& set) {
  double scale = 1;
  std::string datum, buffer;
  std::vector<Nominal> nominals;
  std::vector<std::string_view> values;
  set.points.reserve(lines_starting(text, "FA("));
  nominals.reserve(lines_starting(text, "F("));
  for_each_statement(text, [&](int line, std::string_view raw) {
    compact(raw, buffer);
    const std::string_view st = buffer;
    if (const std::optional<double> units = units_scale(st, name, line)) {
      scale = *units;
      return;
    }
    if (istarts(st, "D(")) {
      const auto close = st.find(')');
      if (close != std::string_view::npos && istarts(st.substr(close + 1), "=DATSET/")) datum = std::string(st.substr(2, close - 2));
      return;
    }
    const std::optional<FeatureStatement> f = feature_statement(st);
    if (!f) return;
    if (f->label.empty()) mf::fail(name, line, "empty feature label");
    split_commas(f->values, values);
    if (f->kind != Kind::point) {
      if (!f->actual) return;  // nominals of datum features: the CMM's business
      MeasuredFeature m = datum_feature(*f, values, scale, name, line);
      m.datum = datum;
      set.features.push_back(std::move(m));
      return;
    }
    Eigen::Vector3d xyz, ijk;
    point_values(*f, values, scale, name, line, xyz, ijk);
    if (!f->actual) {
      nominals.push_back({std::string(f->label), xyz, ijk, line});
      return;
    }
    MeasuredPoint p;
    p.id = std::string(f->label);
    p.line = line;
    p.xyz = xyz;
    p.ijk = ijk;
    p.datum = datum;
    mf::add_point(set, std::move(p), name);
  });
  // Labels unique among the features and among the nominals (the earliest
  // repeat in the file is reported); nominals attached to points by label.
  const auto feature_label = [&](std::size_t k) -> const std::string& { return set.features[k].label; };
  if (const auto r = mf::first_repeat(mf::sorted_label_keys(set.features.size(), feature_label), feature_label))
    mf::fail(name, set.features[r->first].line, "duplicate feature " + quote_field(set.features[r->first].label) +
                                                    " (first on line " + std::to_string(set.features[r->second].line) + ")");
  const auto nominal_label = [&](std::size_t k) -> const std::string& { return nominals[k].label; };
  const mf::LabelKeys keys = mf::sorted_label_keys(nominals.size(), nominal_label);
  if (const auto r = mf::first_repeat(keys, nominal_label))
    mf::fail(name, nominals[r->first].line, "duplicate nominal F(" + quote_field(nominals[r->first].label) +
                                                ") (first on line " + std::to_string(nominals[r->second].line) + ")");
  for (MeasuredPoint& p : set.points) {
    const std::uint64_t h = mf::label_hash(p.id);
    auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(h, std::uint32_t{0}));
    for (; it != keys.end() && it->first == h; ++it)
      if (nominals[it->second].label == p.id) {
        p.nominal = nominals[it->second].xyz;
        p.nominal_ijk = nominals[it->second].ijk;
        break;
      }
  }
  set.ids_from_file = true;
}

std::string dmis_results_text(const MeasurementSet& set) {
  using mf::shortest;
  for (const MeasuredPoint& p : set.points)
    if (p.id.empty() || !std::all_of(p.id.begin(), p.id.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; }))
      throw InputError("DMIS: point id " + quote_field(p.id) + " is not a DMIS label (letters, digits, '_')");
  std::string out;
  out.reserve(set.points.size() * 240 + 256);
  out += "$$ Furrow measurements: ";
  out += set.kind == ProbePointKind::probe_centre ? "probe centres, probe diameter " + shortest(2 * set.probe_radius) + " mm"
                                                 : std::string("contact points");
  out += "\r\nDMISMN/'furrow measurements',05.2\r\nUNITS/MM,ANGDEC\r\n";
  auto six = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    for (int k = 0; k < 3; ++k) out += ',' + shortest(a[k]);
    for (int k = 0; k < 3; ++k) out += ',' + shortest(b[k]);
    out += "\r\n";
  };
  for (const MeasuredPoint& p : set.points) {
    const Eigen::Vector3d ijk = p.nominal_ijk ? *p.nominal_ijk : p.ijk ? *p.ijk : Eigen::Vector3d::UnitZ();
    if (p.nominal) {
      out += "F(" + p.id + ")=FEAT/POINT,CART";
      six(*p.nominal, ijk);
    }
    out += "FA(" + p.id + ")=FEAT/POINT,CART";
    six(p.xyz, p.ijk ? *p.ijk : ijk);
  }
  out += "ENDFIL\r\n";
  return out;
}

std::vector<DmisStatement> dmis_statements(const std::string& text) {
  std::vector<DmisStatement> out;
  const std::string clean = strip_bom(text);
  for_each_statement(clean, [&](int line, std::string_view st) { out.push_back({line, std::string(st)}); });
  return out;
}

std::optional<DmisPointFeature> parse_dmis_point_feature(const DmisStatement& st, const std::string& name,
                                                         double scale) {
  std::string buffer;
  compact(st.text, buffer);
  const std::optional<FeatureStatement> f = feature_statement(buffer);
  if (!f || f->kind != Kind::point) return std::nullopt;
  if (f->label.empty()) mf::fail(name, st.line, "empty feature label");
  std::vector<std::string_view> values;
  split_commas(f->values, values);
  DmisPointFeature out;
  out.actual = f->actual;
  out.label = std::string(f->label);
  point_values(*f, values, scale, name, st.line, out.xyz, out.ijk);
  return out;
}

}  // namespace furrow
