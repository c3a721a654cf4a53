#include "io/qif/qif_document.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <regex>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/qif/qif_uuid.hpp"
#include "io/qif/xs_decimal.hpp"

// Element order: the xs:sequence of each type in the QIF 3.0 schema
// (docs/qif.md lists them); tests/io/qif/ validate every written document
// against the official XSD set with xmllint.

namespace furrow {

namespace {

// Placeholder of a UUID's length, replaced once the content is known.
const std::string kDocumentQpid = "00000000-0000-0000-0000-00000000000d";
const std::string kResultsQpid = "00000000-0000-0000-0000-00000000000r";
// Stands for the time until the QPIds are derived: they identify the
// content, which is the same for the same inputs whenever it was made.
const std::string kTime = "0000-00-00T00:00:00 (time)";
// The most digits an xs:decimal is written with (xs_decimal.hpp).
constexpr int kDecimalDigits = 24;

class Writer {
 public:
  std::string text;
  // Where the placeholders above were written (offsets into text, in
  // order), so that set_qpids replaces them without searching 100 MB of
  // numbers, which are full of "0000", and only them (a name that happens
  // to spell a placeholder stays as written).
  std::vector<std::pair<std::size_t, const std::string*>> placeholders;

  // <name>placeholder</name> on its own line, its place noted.
  void placeholder(int depth, const char* name, const std::string& which) {
    indent(depth);
    text += '<';
    text += name;
    text += '>';
    placeholders.emplace_back(text.size(), &which);
    text += which;
    text += "</";
    text += name;
    text += ">\n";
  }

  // An xs:double (the lists of PointType, UnitVectorType, ArrayPointType):
  // the shortest round-trip text, an exponent allowed.
  void number(double v) {
    if (!std::isfinite(v)) throw std::invalid_argument("QIF: a non-finite number");
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    text.append(buf, r.ptr);
  }
  void integer(std::size_t v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    text.append(buf, r.ptr);
  }
  void triple(const Eigen::Vector3d& v) {
    number(v.x());
    text += ' ';
    number(v.y());
    text += ' ';
    number(v.z());
  }
  // Character data and attribute values: markup characters escaped,
  // characters XML 1.0 forbids (C0 controls but tab, LF, CR) replaced by '?'.
  void escaped(const std::string& s) {
    for (char c : s) {
      switch (c) {
        case '&': text += "&amp;"; break;
        case '<': text += "&lt;"; break;
        case '>': text += "&gt;"; break;
        case '"': text += "&quot;"; break;
        default:
          if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
            text += '?';
          else
            text += c;
      }
    }
  }
  void indent(int depth) { text.append(2 * depth, ' '); }
  // <name>text</name> on its own line.
  void leaf(int depth, const char* name, const std::string& value) {
    indent(depth);
    text += '<';
    text += name;
    text += '>';
    escaped(value);
    text += "</";
    text += name;
    text += ">\n";
  }
  void open(int depth, const char* name) {
    indent(depth);
    text += '<';
    text += name;
    text += ">\n";
  }
  void open_n(int depth, const char* name, std::size_t n) {
    indent(depth);
    text += '<';
    text += name;
    text += " n=\"";
    integer(n);
    text += "\">\n";
  }
  void open_id(int depth, const char* name, std::size_t id) {
    indent(depth);
    text += '<';
    text += name;
    text += " id=\"";
    integer(id);
    text += "\">";
  }
  void close(int depth, const char* name) {
    indent(depth);
    close_inline(name);
  }
  void close_inline(const char* name) {
    text += "</";
    text += name;
    text += ">\n";
  }
  // <name>id</name> inline.
  void ref(const char* name, std::size_t id) {
    text += '<';
    text += name;
    text += '>';
    integer(id);
    text += "</";
    text += name;
    text += '>';
  }
  void vec(const char* name, const Eigen::Vector3d& v) {
    text += '<';
    text += name;
    text += '>';
    triple(v);
    text += "</";
    text += name;
    text += '>';
  }
  // An xs:decimal element (LinearValueType, MeasuredLinearValueType,
  // ProbeRadius): no exponent, within the 24 digits libxml2 validates
  // (docs/qif.md "Numbers").
  void decimal(const char* name, double v) {
    text += '<';
    text += name;
    text += '>';
    if (!std::isfinite(v)) throw std::invalid_argument(std::string("QIF: a non-finite ") + name);
    append_xs_decimal(text, v, kDecimalDigits);
    text += "</";
    text += name;
    text += '>';
  }
};

// A file path as an xs:anyURI: a relative URI reference (RFC 3986) whose
// bytes other than the unreserved characters and '/' are percent-encoded,
// so that a name with '%', '[', '#' or a space is still a URI (and reads
// back as the path by percent-decoding).
std::string uri_reference(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (char c : path) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) != 0 && u < 0x80) {
      out += c;
    } else if (c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += c;
    } else {
      out += '%';
      out += hex[u >> 4];
      out += hex[u & 15];
    }
  }
  return out;
}

// Ids in document order; every block is numbered before the text is
// written, so a reference ahead (a feature measurement to its point set)
// is known when written.
struct Ids {
  std::size_t n = 0;
  std::size_t standard = 0, part = 0, feature_definition = 0;
  std::size_t nominal0 = 0, item0 = 0;
  std::size_t surface_definition = 0, point_definition = 0, surface_nominal = 0, point_nominal = 0;
  std::size_t surface_item = 0, point_item0 = 0;
  std::size_t results = 0, measurement0 = 0, point_set0 = 0, surface_measurement = 0, point_measurement0 = 0;
  std::size_t transform = 0;
  std::size_t max = 0;
};

Ids number_ids(const QifDocumentData& d, bool results) {
  Ids ids;
  ids.n = d.points.size();
  std::size_t next = 1;
  auto block = [&](std::size_t count) {
    const std::size_t first = next;
    next += count;
    return first;
  };
  if (d.profile) ids.standard = block(1);
  ids.part = block(1);
  ids.feature_definition = block(1);
  ids.nominal0 = block(ids.n);
  ids.item0 = block(ids.n);
  const bool per_point = results && d.profile;
  if (d.profile) {
    ids.surface_definition = block(1);
    if (per_point) ids.point_definition = block(1);
    ids.surface_nominal = block(1);
    if (per_point) ids.point_nominal = block(1);
    ids.surface_item = block(1);
    if (per_point) ids.point_item0 = block(ids.n);
  }
  if (results) {
    ids.results = block(1);
    ids.measurement0 = block(ids.n);
    std::size_t centres = 0;
    for (const QifPoint& p : d.points) centres += p.probe_centre.has_value();
    ids.point_set0 = block(centres);
    if (d.profile) {
      ids.surface_measurement = block(1);
      ids.point_measurement0 = block(ids.n);
    }
    if (d.alignment) ids.transform = block(1);
  }
  ids.max = next - 1;
  return ids;
}

void write_head(Writer& w, const QifDocumentData& d, const Ids& ids, const char* scope) {
  w.text += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  // QIFDocumentType: QPId, Version?, Header?, StandardsDefinitions?,
  // FileUnits?, Product?, Features?, Characteristics?, Plan?, Results?
  // (QIFDocument.xsd).
  w.text += "<QIFDocument xmlns=\"";
  w.text += kQifNamespace;
  w.text += "\" versionQIF=\"3.0.0\" idMax=\"";
  w.integer(ids.max);
  w.text += "\">\n";
  w.placeholder(1, "QPId", kDocumentQpid);
  if (d.time) {
    w.open(1, "Version");  // VersionBaseType
    w.placeholder(2, "TimeCreated", kTime);
    w.close(1, "Version");
  }
  w.open(1, "Header");  // QIFDocumentHeaderType: Application, Description, Scope
  w.open(2, "Application");
  w.leaf(3, "Name", "Furrow");
  w.close(2, "Application");
  w.leaf(2, "Description", d.description);
  w.leaf(2, "Scope", scope);
  w.close(1, "Header");
  if (ids.standard) {
    // The standard the characteristics are evaluated by (Characteristics'
    // required FormalStandardId names it): the surface profile of ISO 1101,
    // its zone of a width around the nominal, unequally disposed when an
    // OuterDisposition is given (IntermediatesPMI.xsd StandardType:
    // Organization, Designator, Title).
    w.open_n(1, "StandardsDefinitions", 1);
    w.open_id(2, "Standard", ids.standard);
    w.text += '\n';
    w.open(3, "Organization");
    w.leaf(4, "StandardsOrganizationEnum", "ISO");
    w.close(3, "Organization");
    w.leaf(3, "Designator", "1101");
    w.leaf(3, "Title", "Geometrical product specifications (GPS) - Geometrical tolerancing");
    w.close(2, "Standard");
    w.close(1, "StandardsDefinitions");
  }
  // FileUnits: PrimaryUnits with the angular and the linear unit (Units.xsd).
  w.open(1, "FileUnits");
  w.open(2, "PrimaryUnits");
  w.open(3, "AngularUnit");
  w.leaf(4, "SIUnitName", "radian");
  w.leaf(4, "UnitName", "degree");
  w.open(4, "UnitConversion");
  w.leaf(5, "Factor", "0.017453292519943295");
  w.close(4, "UnitConversion");
  w.close(3, "AngularUnit");
  w.open(3, "LinearUnit");
  w.leaf(4, "SIUnitName", "meter");
  w.leaf(4, "UnitName", "mm");
  w.open(4, "UnitConversion");
  w.leaf(5, "Factor", "0.001");
  w.close(4, "UnitConversion");
  w.close(3, "LinearUnit");
  w.close(2, "PrimaryUnits");
  w.close(1, "FileUnits");
  // Product: PartSet with the one part (QIFProduct.xsd).
  w.open(1, "Product");
  w.open_n(2, "PartSet", 1);
  w.open_id(3, "Part", ids.part);
  w.text += '\n';
  w.leaf(4, "ModelNumber", d.part_name);
  w.close(3, "Part");
  w.close(2, "PartSet");
  w.close(1, "Product");
}

void write_features(Writer& w, const QifDocumentData& d, const Ids& ids) {
  // FeaturesType: FeatureDefinitions, FeatureNominals, FeatureItems
  // (Features.xsd). One PointFeatureDefinition serves every nominal.
  w.open(1, "Features");
  w.open_n(2, "FeatureDefinitions", 1);
  w.open_id(3, "PointFeatureDefinition", ids.feature_definition);
  w.close_inline("PointFeatureDefinition");
  w.close(2, "FeatureDefinitions");
  w.open_n(2, "FeatureNominals", ids.n);
  for (std::size_t i = 0; i < ids.n; ++i) {
    const QifPoint& p = d.points[i];
    w.open_id(3, "PointFeatureNominal", ids.nominal0 + i);
    w.ref("FeatureDefinitionId", ids.feature_definition);
    w.vec("Location", p.nominal);
    w.vec("Normal", p.normal);
    w.close_inline("PointFeatureNominal");
  }
  w.close(2, "FeatureNominals");
  w.open_n(2, "FeatureItems", ids.n);
  for (std::size_t i = 0; i < ids.n; ++i) {
    w.open_id(3, "PointFeatureItem", ids.item0 + i);
    w.ref("FeatureNominalId", ids.nominal0 + i);
    w.text += "<FeatureName>";
    w.escaped(d.points[i].id);
    w.text += "</FeatureName><DeterminationMode><Checked><CheckDetails><Measured/></CheckDetails></Checked>"
              "</DeterminationMode>";
    w.close_inline("PointFeatureItem");
  }
  w.close(2, "FeatureItems");
  w.close(1, "Features");
}

void write_profile_definition(Writer& w, const char* name, std::size_t id, const QifProfile& profile) {
  // ProfileCharacteristicDefinitionBaseType: ToleranceValue, OuterDisposition?
  w.open_id(3, name, id);
  w.decimal("ToleranceValue", profile.tolerance);
  if (profile.outer_disposition) w.decimal("OuterDisposition", *profile.outer_disposition);
  w.close_inline(name);
}

void write_characteristics(Writer& w, const QifDocumentData& d, const Ids& ids, bool per_point) {
  const QifProfile& profile = *d.profile;
  // CharacteristicAspectsListsType: FormalStandardId,
  // CharacteristicDefinitions, CharacteristicNominals, CharacteristicItems?
  // (Characteristics.xsd).
  w.open(1, "Characteristics");
  w.indent(2);
  w.ref("FormalStandardId", ids.standard);
  w.text += '\n';
  w.open_n(2, "CharacteristicDefinitions", per_point ? 2 : 1);
  write_profile_definition(w, "SurfaceProfileCharacteristicDefinition", ids.surface_definition, profile);
  if (per_point) write_profile_definition(w, "PointProfileCharacteristicDefinition", ids.point_definition, profile);
  w.close(2, "CharacteristicDefinitions");
  w.open_n(2, "CharacteristicNominals", per_point ? 2 : 1);
  w.open_id(3, "SurfaceProfileCharacteristicNominal", ids.surface_nominal);
  w.ref("CharacteristicDefinitionId", ids.surface_definition);
  w.close_inline("SurfaceProfileCharacteristicNominal");
  if (per_point) {
    w.open_id(3, "PointProfileCharacteristicNominal", ids.point_nominal);
    w.ref("CharacteristicDefinitionId", ids.point_definition);
    w.close_inline("PointProfileCharacteristicNominal");
  }
  w.close(2, "CharacteristicNominals");
  // CharacteristicItemBaseType: Name, FeatureItemIds, CharacteristicNominalId.
  w.open_n(2, "CharacteristicItems", 1 + (per_point ? ids.n : 0));
  w.open_id(3, "SurfaceProfileCharacteristicItem", ids.surface_item);
  w.text += "\n";
  w.leaf(4, "Name", "surface profile");
  std::size_t profiled = 0;
  for (const QifPoint& p : d.points) profiled += p.profiled;
  if (profiled == 0) throw std::invalid_argument("QIF: a surface profile over no point");
  w.open_n(4, "FeatureItemIds", profiled);
  for (std::size_t i = 0; i < ids.n; ++i) {
    if (!d.points[i].profiled) continue;
    w.indent(5);
    w.ref("Id", ids.item0 + i);
    w.text += '\n';
  }
  w.close(4, "FeatureItemIds");
  w.indent(4);
  w.ref("CharacteristicNominalId", ids.surface_nominal);
  w.text += '\n';
  w.close(3, "SurfaceProfileCharacteristicItem");
  if (per_point)
    for (std::size_t i = 0; i < ids.n; ++i) {
      w.open_id(3, "PointProfileCharacteristicItem", ids.point_item0 + i);
      w.text += "<Name>";
      w.escaped(d.points[i].id);
      w.text += "</Name><FeatureItemIds n=\"1\">";
      w.ref("Id", ids.item0 + i);
      w.text += "</FeatureItemIds>";
      w.ref("CharacteristicNominalId", ids.point_nominal);
      w.close_inline("PointProfileCharacteristicItem");
    }
  w.close(2, "CharacteristicItems");
  w.close(1, "Characteristics");
}

void status(Writer& w, const std::string& value) {
  // CharacteristicStatusType: the CharacteristicStatusEnum choice.
  w.text += "<Status><CharacteristicStatusEnum>";
  w.escaped(value);
  w.text += "</CharacteristicStatusEnum></Status>";
}

void write_traceability(Writer& w, const QifDocumentData& d) {
  // InspectionTraceabilityType (Traceability.xsd), in its sequence order:
  // ..., InspectionOperator?, ReportPreparer?, ReportPreparationDate?, ...,
  // Attributes?. The customer and the CMM program are attributes: QIF's
  // CustomerOrganization requires a CustomerNumber and its InspectionProgram
  // a FormalStandardId and an Author, which a record does not know.
  static const QifTraceability kNone;
  const QifTraceability& t = d.traceability ? *d.traceability : kNone;
  std::vector<std::pair<std::string, std::string>> attributes_in_order = {{"customer", t.customer},
                                                                          {"program", t.program}};
  attributes_in_order.insert(attributes_in_order.end(), t.attributes.begin(), t.attributes.end());
  auto named = [&](const char* element, const std::string& name) {
    if (name.empty()) return;
    w.open(5, element);
    w.leaf(6, "Name", name);
    w.close(5, element);
  };
  w.open(4, "InspectionTraceability");
  named("InspectionOperator", t.operator_name);  // EmployeeType: Name first
  named("ReportPreparer", t.report_preparer);
  if (d.time) w.placeholder(5, "ReportPreparationDate", kTime);
  std::size_t attributes = 0;
  for (const auto& a : attributes_in_order) attributes += !a.second.empty();
  if (attributes > 0) {
    // AttributesType: n, then AttributeStr with the name and value attributes.
    w.open_n(5, "Attributes", attributes);
    for (const auto& [name, value] : attributes_in_order) {
      if (value.empty()) continue;
      w.indent(6);
      w.text += "<AttributeStr name=\"";
      w.escaped(name);
      w.text += "\" value=\"";
      // An attribute value's line breaks and tabs are kept as references
      // (a parser would otherwise turn them into spaces).
      for (char c : value) {
        if (c == '\n') w.text += "&#10;";
        else if (c == '\t') w.text += "&#9;";
        else if (c == '\r') w.text += "&#13;";
        else w.escaped(std::string(1, c));
      }
      w.text += "\"/>\n";
    }
    w.close(5, "Attributes");
  }
  w.close(4, "InspectionTraceability");
}

void write_results(Writer& w, const QifDocumentData& d, const Ids& ids) {
  // ResultsType: MeasurementResultsSet (QIFResults.xsd).
  w.open(1, "Results");
  w.open_n(2, "MeasurementResultsSet", 1);
  w.open_id(3, "MeasurementResults", ids.results);
  w.text += '\n';
  // MeasurementResultsType: InspectionTraceability?, ThisResultsInstanceQPId?,
  // ExternalFileReferences?, MeasuredFeatures?, MeasuredPointSets?,
  // MeasuredCharacteristics?, ActualTransforms?, InspectionStatus.
  if (d.time || d.traceability) write_traceability(w, d);
  w.placeholder(4, "ThisResultsInstanceQPId", kResultsQpid);
  if (!d.inputs.empty()) {
    w.open_n(4, "ExternalFileReferences", d.inputs.size());
    for (const QifFile& f : d.inputs) {
      // ExternalFileReferenceType: URI, FileSpec, Description.
      w.open(5, "ExternalFileReference");
      w.leaf(6, "URI", uri_reference(f.path));
      w.open(6, "FileSpec");
      w.leaf(7, "OtherFileSpec", f.role);
      w.close(6, "FileSpec");
      w.leaf(6, "Description", "SHA-256 " + f.sha256);
      w.close(5, "ExternalFileReference");
    }
    w.close(4, "ExternalFileReferences");
  }
  w.open_n(4, "MeasuredFeatures", ids.n);
  std::size_t set_id = ids.point_set0;
  for (std::size_t i = 0; i < ids.n; ++i) {
    const QifPoint& p = d.points[i];
    if (!p.actual) throw std::invalid_argument("QIF results: point " + p.id + " has no measured location");
    // PointFeatureMeasurementType: FeatureItemId, PointList?, Location.
    w.open_id(5, "PointFeatureMeasurement", ids.measurement0 + i);
    w.ref("FeatureItemId", ids.item0 + i);
    if (p.probe_centre) {
      w.text += "<PointList n=\"1\">";
      w.ref("WholePointSetId", set_id++);
      w.text += "</PointList>";
    }
    w.vec("Location", *p.actual);
    w.close_inline("PointFeatureMeasurement");
  }
  w.close(4, "MeasuredFeatures");
  if (set_id != ids.point_set0) {
    w.open_n(4, "MeasuredPointSets", set_id - ids.point_set0);
    std::size_t id = ids.point_set0;
    for (const QifPoint& p : d.points) {
      if (!p.probe_centre) continue;
      // MeasuredPointSetType: Points, Compensated, ProbeRadius; count attribute.
      w.indent(5);
      w.text += "<MeasuredPointSet count=\"1\" id=\"";
      w.integer(id++);
      w.text += "\">";
      w.vec("Points", *p.probe_centre);
      w.text += "<Compensated>false</Compensated>";
      w.decimal("ProbeRadius", d.probe_radius);
      w.close_inline("MeasuredPointSet");
    }
    w.close(4, "MeasuredPointSets");
  }
  if (d.profile) {
    w.open(4, "MeasuredCharacteristics");
    w.open_n(5, "CharacteristicMeasurements", 1 + ids.n);
    // CharacteristicMeasurementBaseType: Status, CharacteristicItemId,
    // FeatureMeasurementIds, Value.
    w.open_id(6, "SurfaceProfileCharacteristicMeasurement", ids.surface_measurement);
    w.text += '\n';
    w.indent(7);
    status(w, d.profile->status);
    w.text += '\n';
    w.indent(7);
    w.ref("CharacteristicItemId", ids.surface_item);
    w.text += '\n';
    w.open_n(7, "FeatureMeasurementIds", ids.n);
    for (std::size_t i = 0; i < ids.n; ++i) {
      w.indent(8);
      w.ref("Id", ids.measurement0 + i);
      w.text += '\n';
    }
    w.close(7, "FeatureMeasurementIds");
    if (!d.profile->value) throw std::invalid_argument("QIF results: the profile has no measured value");
    w.indent(7);
    w.decimal("Value", *d.profile->value);
    w.text += '\n';
    w.close(6, "SurfaceProfileCharacteristicMeasurement");
    for (std::size_t i = 0; i < ids.n; ++i) {
      const QifPoint& p = d.points[i];
      if (!p.deviation) throw std::invalid_argument("QIF results: point " + p.id + " has no deviation");
      w.open_id(6, "PointProfileCharacteristicMeasurement", ids.point_measurement0 + i);
      status(w, p.status);
      w.ref("CharacteristicItemId", ids.point_item0 + i);
      w.text += "<FeatureMeasurementIds n=\"1\">";
      w.ref("Id", ids.measurement0 + i);
      w.text += "</FeatureMeasurementIds>";
      w.decimal("Value", *p.deviation);
      w.close_inline("PointProfileCharacteristicMeasurement");
    }
    w.close(5, "CharacteristicMeasurements");
    w.close(4, "MeasuredCharacteristics");
  }
  if (d.alignment) {
    // TransformListType: Transform (TransformInstanceType: Rotation?,
    // Origin?, Attributes?, Name?; id), n.
    const QifAlignment& a = *d.alignment;
    w.open_n(4, "ActualTransforms", 1);
    w.open_id(5, "Transform", ids.transform);
    w.text += '\n';
    w.indent(6);
    w.text += "<Rotation>";
    w.vec("XDirection", a.rotation.col(0));
    w.vec("YDirection", a.rotation.col(1));
    w.vec("ZDirection", a.rotation.col(2));
    w.text += "</Rotation>\n";
    w.indent(6);
    w.vec("Origin", a.origin);
    w.text += '\n';
    w.open_n(6, "Attributes", 1);
    w.indent(7);
    w.text += "<AttributeStr name=\"alignment\" value=\"";
    w.escaped(a.method);
    w.text += "\"/>\n";
    w.close(6, "Attributes");
    w.leaf(6, "Name", a.name);
    w.close(5, "Transform");
    w.close(4, "ActualTransforms");
  }
  // InspectionStatusType: InspectionStatusEnum or OtherInspectionStatus.
  w.open(4, "InspectionStatus");
  w.leaf(5, d.inspection_status_other ? "OtherInspectionStatus" : "InspectionStatusEnum", d.inspection_status);
  w.close(4, "InspectionStatus");
  w.close(3, "MeasurementResults");
  w.close(2, "MeasurementResultsSet");
  w.close(1, "Results");
}

// TimeCreated and ReportPreparationDate are xs:dateTime; a caller's time
// that is not one would make the document invalid.
void check_time(const std::optional<std::string>& time) {
  static const std::regex date_time(R"(-?[0-9]{4,}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}(\.[0-9]+)?(Z|[+-][0-9]{2}:[0-9]{2})?)");
  if (time && !std::regex_match(*time, date_time))
    throw std::invalid_argument("QIF: the time \"" + *time + "\" is not an ISO 8601 date and time (xs:dateTime)");
}

// The placeholders replaced by UUIDs derived from the text around them,
// then the time's by the time. The UUIDs have the placeholders' length and
// go in place; the time, when its length differs, costs one copy of the text.
void set_qpids(Writer& w, const std::optional<std::string>& time) {
  std::string& text = w.text;
  const std::string digest = qif_sha256_hex(text);
  const std::string document = uuid_from_content(digest + " QPId");
  const std::string results = uuid_from_content(digest + " ThisResultsInstanceQPId");
  const std::string& time_text = time ? *time : kTime;  // an xs:dateTime (check_time): nothing to escape
  auto replacement = [&](const std::string* which) -> const std::string& {
    if (which == &kDocumentQpid) return document;
    if (which == &kResultsQpid) return results;
    return time_text;
  };
  bool same_length = true;
  for (const auto& [at, which] : w.placeholders) same_length &= replacement(which).size() == which->size();
  if (same_length) {
    for (const auto& [at, which] : w.placeholders) text.replace(at, which->size(), replacement(which));
    return;
  }
  std::string out;
  out.reserve(text.size() + w.placeholders.size() * time_text.size());
  std::size_t from = 0;
  for (const auto& [at, which] : w.placeholders) {
    out.append(text, from, at - from);
    out += replacement(which);
    from = at + which->size();
  }
  out.append(text, from, std::string::npos);
  text = std::move(out);
}

}  // namespace

std::string qif_results_text(const QifDocumentData& d) {
  check_time(d.time);
  const Ids ids = number_ids(d, true);
  Writer w;
  w.text.reserve(1400 * (d.points.size() + 4));  // about 1270 bytes a point: no reallocation
  write_head(w, d, ids, "Results");
  write_features(w, d, ids);
  if (d.profile) write_characteristics(w, d, ids, true);
  write_results(w, d, ids);
  w.text += "</QIFDocument>\n";
  set_qpids(w, d.time);
  return std::move(w.text);
}

// PlanType (QIFPlan.xsd): its one required member, PlanRoot, here an
// OrderedPlanRoot (OrderedActionGroupType: Steps, a NumberedPlanElementsType)
// whose steps measure each point feature in the order given — the plan's
// execution order — and then evaluate the surface profile.
void write_plan(Writer& w, const QifDocumentData& d, const Ids& ids) {
  w.open(1, "Plan");
  w.open(2, "OrderedPlanRoot");
  w.open_n(3, "Steps", ids.n + (d.profile ? 1 : 0));
  std::size_t step = 0;
  auto begin_step = [&] {
    w.indent(4);
    w.text += "<NumberedPlanElement><SequenceNumber>";
    w.integer(++step);
    w.text += "</SequenceNumber>";
  };
  for (std::size_t i = 0; i < ids.n; ++i) {
    begin_step();
    w.text += "<MeasureSpecifiedFeatures><FeatureItemIds n=\"1\">";
    w.ref("Id", ids.item0 + i);
    w.text += "</FeatureItemIds></MeasureSpecifiedFeatures></NumberedPlanElement>\n";
  }
  if (d.profile) {
    begin_step();
    w.text += "<EvaluateSpecifiedCharacteristics><CharacteristicItemIds n=\"1\">";
    w.ref("Id", ids.surface_item);
    w.text += "</CharacteristicItemIds></EvaluateSpecifiedCharacteristics></NumberedPlanElement>\n";
  }
  w.close(3, "Steps");
  w.close(2, "OrderedPlanRoot");
  w.close(1, "Plan");
}

std::string qif_plan_text(const QifDocumentData& d) {
  check_time(d.time);
  const Ids ids = number_ids(d, false);
  Writer w;
  w.text.reserve(400 * (d.points.size() + 4));
  write_head(w, d, ids, "Plan");
  write_features(w, d, ids);
  if (d.profile) write_characteristics(w, d, ids, false);
  write_plan(w, d, ids);
  w.text += "</QIFDocument>\n";
  set_qpids(w, d.time);
  return std::move(w.text);
}

}  // namespace furrow
