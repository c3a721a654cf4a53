#include "io/qif/qif_points_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <pugixml.hpp>
#include <unordered_map>

#include "base/error.hpp"
#include "base/text_fields.hpp"

namespace furrow {

namespace {

using pugi::xml_node;

// An element's name without its namespace prefix.
const char* local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? colon + 1 : name;
}

bool named(xml_node n, const char* want) { return std::strcmp(local_name(n.name()), want) == 0; }

xml_node child(xml_node n, const char* want) {
  for (xml_node c = n.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && named(c, want)) return c;
  return {};
}

// Offsets of the newlines of the original text, so that a parser offset
// (in-place parsing keeps every element where it was) gives a line.
class Lines {
 public:
  explicit Lines(const std::string& text) {
    for (std::size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i + 1)) newlines_.push_back(i);
  }
  int at(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    return 1 + static_cast<int>(std::upper_bound(newlines_.begin(), newlines_.end(),
                                                 static_cast<std::size_t>(offset)) - newlines_.begin());
  }

 private:
  std::vector<std::size_t> newlines_;
};

struct Reader {
  const std::string& name;
  const Lines& lines;
  double scale = 1;  // file length unit -> mm

  int line(xml_node n) const { return lines.at(n.offset_debug()); }
  [[noreturn]] void fail(xml_node n, const std::string& what) const {
    throw InputError(name + ":" + std::to_string(line(n)) + ": " + what);
  }
  std::string tag(xml_node n) const { return std::string("<") + local_name(n.name()) + ">"; }

  double number(xml_node n, const char* text, std::size_t length) const {
    const char* first = text;
    const char* last = text + length;
    if (first != last && *first == '+') ++first;  // xs:double allows a sign
    double v = 0;
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last || !std::isfinite(v))
      fail(n, tag(n) + ": " + quote_field(std::string(text, length)) + " is not a finite number");
    return v;
  }
  double scalar(xml_node n) const {
    const std::string t = trim(n.child_value());
    return number(n, t.data(), t.size());
  }
  Eigen::Vector3d triple(xml_node n) const {
    const char* s = n.child_value();
    Eigen::Vector3d v;
    int count = 0;
    while (*s) {
      while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') ++s;
      if (!*s) break;
      const char* start = s;
      while (*s && *s != ' ' && *s != '\t' && *s != '\n' && *s != '\r') ++s;
      if (count == 3) fail(n, tag(n) + ": expected 3 numbers, found more");
      v[count++] = number(n, start, static_cast<std::size_t>(s - start));
    }
    if (count != 3) fail(n, tag(n) + ": expected 3 numbers, found " + std::to_string(count));
    return v;
  }
  Eigen::Vector3d unit(xml_node n) const {
    const Eigen::Vector3d v = triple(n);
    if (!(v.norm() > 0)) fail(n, tag(n) + ": zero direction vector");
    return v.normalized();
  }
  std::size_t id_value(xml_node n) const {
    const char* first = n.child_value();
    const char* last = first + std::strlen(first);
    while (first != last && std::isspace(static_cast<unsigned char>(*first))) ++first;
    while (last != first && std::isspace(static_cast<unsigned char>(last[-1]))) --last;
    std::size_t v = 0;
    const auto r = std::from_chars(first, last, v);
    if (first == last || r.ec != std::errc() || r.ptr != last)
      fail(n, tag(n) + ": " + quote_field(std::string(first, last)) + " is not a QIF id");
    return v;
  }
  std::size_t id_attribute(xml_node n) const {
    const pugi::xml_attribute a = n.attribute("id");
    const std::string t = a.value();
    std::size_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(n, tag(n) + ": id " + quote_field(t) + " is not a QIF id");
    return v;
  }
  xml_node required(xml_node n, const char* want) const {
    const xml_node c = child(n, want);
    if (!c) fail(n, tag(n) + " has no <" + want + ">");
    return c;
  }
};

// Millimetres per file length unit (Units.xsd LinearUnit).
double linear_scale(const Reader& r, xml_node root) {
  const xml_node unit = child(child(child(root, "FileUnits"), "PrimaryUnits"), "LinearUnit");
  if (!unit) return 1;
  if (const xml_node factor = child(child(unit, "UnitConversion"), "Factor")) {
    const double f = r.scalar(factor);
    if (!(f > 0)) r.fail(factor, "<Factor> of the linear unit must be positive");
    return f * 1000;  // the factor converts to the SI unit, the metre
  }
  const std::string u = to_lower(trim(child(unit, "UnitName").child_value()));
  if (u == "mm" || u == "millimeter" || u == "millimetre") return 1;
  if (u == "cm" || u == "centimeter" || u == "centimetre") return 10;
  if (u == "m" || u == "meter" || u == "metre") return 1000;
  if (u == "in" || u == "inch" || u == "inches") return 25.4;
  r.fail(unit, "linear unit " + quote_field(u) + " is not mm, cm, m or inch and has no <UnitConversion>");
}

// Elements by QIF id. Ids are dense in practice (1..idMax), so a table
// indexed by id is both faster and smaller than a hash map for a large
// document; an id beyond the table (idMax wrong or absent) goes to the map.
class Index {
 public:
  Index(std::size_t id_max, std::size_t text_size)
      : dense_(std::min(id_max, text_size / 8) + 1) {}  // an id takes more than 8 bytes of text
  void put(std::size_t id, xml_node n) {
    if (id < dense_.size()) dense_[id] = n;
    else sparse_.emplace(id, n);
  }
  xml_node find(std::size_t id) const {
    if (id < dense_.size()) return dense_[id];
    const auto it = sparse_.find(id);
    return it == sparse_.end() ? xml_node() : it->second;
  }

 private:
  std::vector<xml_node> dense_;
  std::unordered_map<std::size_t, xml_node> sparse_;
};

void index_children(const Reader& r, xml_node list, Index& index) {
  for (xml_node c = list.first_child(); c; c = c.next_sibling())
    if (c.type() == pugi::node_element && c.attribute("id")) index.put(r.id_attribute(c), c);
}

bool ends_with(const char* text, const char* suffix) {
  const std::size_t a = std::strlen(text), b = std::strlen(suffix);
  return a >= b && std::strcmp(text + a - b, suffix) == 0;
}

// The element `reference` names, which must be of the kind whose name ends
// in `kind` ("FeatureItem", "FeatureNominal", "MeasuredPointSet").
xml_node resolve(const Reader& r, const Index& index, xml_node reference, const char* kind, const char* what) {
  const xml_node n = index.find(r.id_value(reference));
  if (!n || !ends_with(local_name(n.name()), kind))
    r.fail(reference, r.tag(reference) + " " + trim(reference.child_value()) + " names no " + what);
  return n;
}

}  // namespace

QifMeasuredPoints parse_qif_points(std::string text, const std::string& name) {
  // The DOM holds every element of the file; a leaf's text is kept in its
  // element (parse_embed_pcdata), which halves the nodes of a large file.
  const Lines lines(text);
  Reader r{name, lines};
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed =
      doc.load_buffer_inplace(text.data(), text.size(), pugi::parse_default | pugi::parse_embed_pcdata,
                              pugi::encoding_auto);
  if (!parsed)
    throw InputError(name + ":" + std::to_string(lines.at(parsed.offset)) + ": malformed XML: " +
                     parsed.description());
  const xml_node root = doc.document_element();
  if (!named(root, "QIFDocument"))
    r.fail(root, "not a QIF document (the root element is " + r.tag(root) + ", expected <QIFDocument>)");
  r.scale = linear_scale(r, root);

  // One index for the whole document: QIF ids are unique in it.
  Index index(root.attribute("idMax").as_ullong(0), text.size());
  const xml_node features = child(root, "Features");
  index_children(r, child(features, "FeatureNominals"), index);
  index_children(r, child(features, "FeatureItems"), index);

  QifMeasuredPoints out;
  // Uncompensated probe centres are used only when every point has one
  // (a one-point MeasuredPointSet, Compensated false, one ProbeRadius for
  // all); otherwise every point is its Location, the compensated point.
  std::vector<Eigen::Vector3d> centres;
  bool all_centres = true;
  std::vector<char> has_location;
  const xml_node set = child(child(root, "Results"), "MeasurementResultsSet");
  for (xml_node results = set.first_child(); results; results = results.next_sibling()) {
    if (results.type() != pugi::node_element || !named(results, "MeasurementResults")) continue;
    index_children(r, child(results, "MeasuredPointSets"), index);
    const xml_node measured = child(results, "MeasuredFeatures");
    for (xml_node m = measured.first_child(); m; m = m.next_sibling()) {
      if (m.type() != pugi::node_element ||
          !(named(m, "PointFeatureMeasurement") || named(m, "PointFeatureActual")))
        continue;
      QifMeasuredPoint p;
      p.line = r.line(m);
      const xml_node item = resolve(r, index, r.required(m, "FeatureItemId"), "FeatureItem", "feature item");
      const std::string feature_name = trim(child(item, "FeatureName").child_value());
      p.id = feature_name.empty() ? "item " + std::to_string(r.id_attribute(item)) : feature_name;
      if (const xml_node nominal_id = child(item, "FeatureNominalId")) {
        const xml_node nominal = resolve(r, index, nominal_id, "FeatureNominal", "feature nominal");
        if (const xml_node l = child(nominal, "Location")) p.nominal = r.triple(l) * r.scale;
        if (const xml_node n = child(nominal, "Normal")) p.nominal_ijk = r.unit(n);
      }
      const xml_node location = child(m, "Location");
      if (location) p.xyz = r.triple(location) * r.scale;
      has_location.push_back(location ? 1 : 0);
      if (all_centres) {
        // A point list that names anything but such a set is not used: the
        // Location is the measurement's result, the point list its detail.
        const xml_node whole = child(child(m, "PointList"), "WholePointSetId");
        const xml_node ps = whole ? index.find(r.id_value(whole)) : xml_node();
        const xml_node radius = child(ps, "ProbeRadius");
        const xml_node points = child(ps, "Points");
        all_centres = ps && named(ps, "MeasuredPointSet") && trim(child(ps, "Compensated").child_value()) == "false" &&
                      radius && points && ps.attribute("count").as_int(-1) == 1;
        if (all_centres) {
          const double rr = r.scalar(radius) * r.scale;
          all_centres = rr > 0 && (!out.probe_radius || std::abs(*out.probe_radius - rr) <= 1e-12 * rr);
          if (all_centres) {
            out.probe_radius = rr;
            centres.push_back(r.triple(points) * r.scale);
          }
        }
        if (!all_centres) {
          out.probe_radius.reset();
          std::vector<Eigen::Vector3d>().swap(centres);
        }
      }
      if (const xml_node n = child(m, "Normal")) p.ijk = r.unit(n);
      else p.ijk = p.nominal_ijk;
      out.points.push_back(std::move(p));
    }
  }
  if (all_centres && !out.points.empty()) {
    for (std::size_t i = 0; i < out.points.size(); ++i) out.points[i].xyz = centres[i];
  } else {
    out.probe_radius.reset();
    for (std::size_t i = 0; i < out.points.size(); ++i)
      if (!has_location[i])
        throw InputError(name + ":" + std::to_string(out.points[i].line) + ": point " +
                         quote_field(out.points[i].id) + " has no <Location> (and not every point has an "
                         "uncompensated probe centre)");
  }
  if (out.points.empty())
    throw InputError(name +
                     ": no measured points (no PointFeatureMeasurement in Results/MeasurementResultsSet/"
                     "MeasurementResults/MeasuredFeatures)");
  return out;
}

QifMeasuredPoints read_qif_points(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path + ": cannot open the file (missing or unreadable)");
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path + ": reading the file failed");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(text.data(), size)) throw InputError(path + ": reading the file failed");
  return parse_qif_points(std::move(text), path);
}

}  // namespace furrow
