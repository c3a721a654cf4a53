// QIF documents valid by the official QIF 3.0 XSD set (docs/qif.md
// "Validity"): every writer's document, with numbers at the edges of the
// double range in its xs:decimal and xs:double elements, validated by
// xmllint; the check shown able to fail; xs:decimal text against strtod;
// and what the XSD cannot see (counts, ids, references) by qif_checks.hpp.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <regex>

#include "io/cmm/measurement_qif.hpp"
#include "io/qif/qif_document.hpp"
#include "io/qif/qif_points_reader.hpp"
#include "io/qif/xs_decimal.hpp"
#include "qif_checks.hpp"
#include "qif_schema.hpp"

using namespace furrow;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The XML Schema lexical space of xs:decimal (Part 2, 3.2.3.1): no exponent.
bool is_decimal_lexical(const std::string& s) {
  static const std::regex decimal(R"([+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+))");
  return std::regex_match(s, decimal);
}

// Digits of a decimal text, the integer part's lone 0 not counted.
int digit_count(const std::string& s) {
  int n = 0;
  const std::size_t start = s.find_first_not_of("+-");
  const bool lone_zero = s.compare(start, 2, "0.") == 0 || s.substr(start) == "0";
  for (std::size_t i = start + (lone_zero ? 1 : 0); i < s.size(); ++i) n += s[i] >= '0' && s[i] <= '9';
  return n;
}

const double kEdges[] = {1e-300, 5e-324, -5e-324, 1.5508968404631673e-05, 123456789012345680000.0, -0.0, 0.0,
                         -2.5, 1.7976931348623157e308, -1.7976931348623157e308, 2.2250738585072014e-308,
                         0.1, 1e21, 1e22, 9.999999999999999e23, 1e-7, 1.2345678901234567e-8, 3.552713678800501e-15};

// A Results document through every branch of the writer, the edge values in
// its decimal elements (zone, deviations, profile, probe radius) and its
// double lists (nominal, actual, probe centre, alignment).
QifDocumentData edge_document() {
  QifDocumentData d;
  d.part_name = "part <&> \"edge\".json";
  d.description = "edge values";
  d.time = "2026-11-25T12:00:00Z";
  // Paths with characters a URI cannot hold as they are (xs:anyURI).
  d.inputs = {{"part", "a b/part[1] 50%#x.json", std::string(64, 'a')},
              {"measurements", "C:\\cmm\\m\u00fc.qif", std::string(64, 'b')}};
  d.probe_radius = 1.5508968404631673e-05;
  const double decimals[] = {1e-300, 5e-324, -0.0, 1.5508968404631673e-05, 123456789012345680000.0, -2.5};
  for (std::size_t i = 0; i < 6; ++i) {
    QifPoint p;
    p.id = "P" + std::to_string(i);
    p.nominal = {1e-300, -0.0, 1.7976931348623157e308};
    p.normal = {5e-324, 0, 1};
    p.actual = Eigen::Vector3d(1.5508968404631673e-05, -5e-324, 123456789012345680000.0);
    if (i % 2 == 0) p.probe_centre = Eigen::Vector3d(-1e-300, 2.2250738585072014e-308, 1e22);
    p.deviation = decimals[i];
    p.status = i == 0 ? "NOT_ANALYZED" : i == 1 ? "FAIL" : "PASS";
    p.profiled = i != 5;
    d.points.push_back(p);
  }
  QifProfile profile;
  profile.tolerance = 1.5508968404631673e-05;
  profile.outer_disposition = 1e-300;
  profile.value = 9.999999999999999e23 / 10;
  profile.status = "INDETERMINATE";
  d.profile = profile;
  d.inspection_status = "INCONCLUSIVE";
  d.inspection_status_other = true;
  QifTraceability t;
  t.customer = "Acme & <Co>";
  t.program = "mould.dmi";
  t.operator_name = "J. Doe";
  t.report_preparer = "A. Prep";
  t.attributes = {{"serial", "SN 1"}, {"notes", "line 1\nline 2"}, {"lot", ""}};
  d.traceability = t;
  QifAlignment a;
  a.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  a.origin = {1e-300, -0.0, 5e-324};
  a.method = "bestfit";
  a.name = "CMM to part";
  d.alignment = a;
  return d;
}

// `text` with the first element `tag`'s content replaced.
std::string with_content(std::string text, const std::string& tag, const std::string& content) {
  const std::size_t a = text.find("<" + tag + ">");
  REQUIRE(a != std::string::npos);
  const std::size_t start = a + tag.size() + 2, end = text.find("</" + tag + ">", start);
  text.replace(start, end - start, content);
  return text;
}

}  // namespace

TEST_CASE("xs:decimal text: no exponent, and strtod reads back the same double") {
  for (double v : kEdges) {
    const std::string s = xs_decimal_text(v);
    CAPTURE(s);
    CHECK(is_decimal_lexical(s));
    CHECK(same_bits(std::strtod(s.c_str(), nullptr), v));  // -0 stays -0
  }
  CHECK(xs_decimal_text(1.5508968404631673e-05) == "0.000015508968404631673");
  CHECK(xs_decimal_text(123456789012345680000.0) == "123456789012345680000");
  CHECK(xs_decimal_text(-0.0) == "-0");
  CHECK(xs_decimal_text(5e-324) == "0." + std::string(323, '0') + "5");
  CHECK(xs_decimal_text(-2.5) == "-2.5");
  // Brute force over bit patterns: every finite double of every exponent.
  std::mt19937_64 rng(7);
  int tried = 0;
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isfinite(v)) continue;
    ++tried;
    const std::string s = xs_decimal_text(v);
    if (!is_decimal_lexical(s) || !same_bits(std::strtod(s.c_str(), nullptr), v)) {
      CHECK_MESSAGE(false, s);
      break;
    }
  }
  CHECK(tried > 199000);
  CHECK_THROWS_AS(xs_decimal_text(std::numeric_limits<double>::infinity()), std::invalid_argument);
  CHECK_THROWS_AS(xs_decimal_text(std::nan("")), std::invalid_argument);
}

TEST_CASE("xs:decimal text within 24 digits: exact from 1e-7 to 1e24, rounded to 24 places below") {
  for (double v : kEdges) {
    CAPTURE(v);
    if (std::abs(v) >= 1e24) {
      CHECK_THROWS_AS(xs_decimal_text(v, 24), std::invalid_argument);
      continue;
    }
    const std::string s = xs_decimal_text(v, 24);
    CAPTURE(s);
    CHECK(is_decimal_lexical(s));
    CHECK(digit_count(s) <= 24);
    const double back = std::strtod(s.c_str(), nullptr);
    if (v == 0 || std::abs(v) >= 1e-7)
      CHECK(same_bits(back, v));
    else
      CHECK(std::abs(back - v) <= 0.5e-24);
  }
  CHECK(xs_decimal_text(3.552713678800501e-15, 24) == "0.000000000000003552713679");
  CHECK(xs_decimal_text(-5e-324, 24) == "-0");
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-7, 24);
  for (int i = 0; i < 100000; ++i) {
    const double v = std::pow(10.0, exponent(rng)) * (i % 2 ? -1 : 1);
    if (std::abs(v) >= 1e24) continue;
    const std::string s = xs_decimal_text(v, 24);
    if (digit_count(s) > 24 || !same_bits(std::strtod(s.c_str(), nullptr), v)) {
      CHECK_MESSAGE(false, s);
      break;
    }
  }
}

TEST_CASE("every QIF writer's document validates by the QIF 3.0 XSD, edge values included, and reads back") {
  const std::string dir = test::scratch_dir("qif-schema-writers");
  const QifDocumentData d = edge_document();
  const std::string results = qif_results_text(d);
  test::check_qif_valid(results, dir + "/results.qif");
  CHECK(test::check_qif_ids_and_counts(results) > 30);
  // Decimal elements carry no exponent; the double lists keep their shortest text.
  CHECK(results.find("<Value>0.000015508968404631673</Value>") != std::string::npos);
  CHECK(results.find("<ToleranceValue>0.000015508968404631673</ToleranceValue>") != std::string::npos);
  CHECK(results.find("<Value>-0</Value>") != std::string::npos);
  CHECK(results.find("<URI>a%20b/part%5B1%5D%2050%25%23x.json</URI>") != std::string::npos);
  CHECK(results.find("<URI>C%3A%5Ccmm%5Cm%C3%BC.qif</URI>") != std::string::npos);
  CHECK(results.find("<Value>123456789012345680000</Value>") != std::string::npos);
  // (to_chars writes a double's exact integer digits where that is shorter
  // than the exponent form.)
  CHECK(results.find("<Location>1.5508968404631673e-05 -5e-324 123456789012345683968</Location>") !=
        std::string::npos);
  // The reader reads back what the writer wrote, bit for bit.
  const QifMeasuredPoints back = parse_qif_points(results, "results.qif");
  REQUIRE(back.points.size() == d.points.size());
  REQUIRE_FALSE(back.probe_radius);  // only half the points have a centre: the Locations are read
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    CHECK(back.points[i].id == d.points[i].id);
    for (int k = 0; k < 3; ++k) {
      CHECK(same_bits(back.points[i].xyz[k], (*d.points[i].actual)[k]));
      CHECK(same_bits((*back.points[i].nominal)[k], d.points[i].nominal[k]));
    }
  }

  QifDocumentData plan = d;
  for (QifPoint& p : plan.points) {
    p.actual.reset();
    p.probe_centre.reset();
    p.deviation.reset();
  }
  plan.profile->value.reset();
  plan.traceability.reset();
  plan.alignment.reset();
  plan.inputs.clear();
  const std::string plan_text = qif_plan_text(plan);
  test::check_qif_valid(plan_text, dir + "/plan.qif");
  CHECK(test::check_qif_ids_and_counts(plan_text) > 10);

  // Measured points only (simulate-measurement): no characteristic, no
  // standard; probe centres and contact points.
  InspectionPlan ip;
  ip.probe = {"ruby", 2};
  MeasurementSet set;
  set.source = "sim";
  set.ids_from_file = true;
  set.kind = ProbePointKind::probe_centre;
  set.probe_radius = 1;
  for (int i = 0; i < 4; ++i) {
    PlannedPoint p;
    p.id = "P" + std::to_string(i);
    p.xyz = Eigen::Vector3d(kEdges[i], kEdges[i + 4], 1.0 / 3);
    p.ijk = Eigen::Vector3d(0, 0, 1);
    ip.points.push_back(p);
    MeasuredPoint m;
    m.id = p.id;
    m.xyz = p.centre(1) + Eigen::Vector3d(1e-300, -0.0, 1e-17);
    m.ijk = p.ijk;
    set.points.push_back(m);
  }
  const std::string centres = measurements_to_qif(set, &ip, "part.json");
  test::check_qif_valid(centres, dir + "/centres.qif");
  CHECK(test::check_qif_ids_and_counts(centres) > 8);
  set.kind = ProbePointKind::contact;
  const std::string contacts = measurements_to_qif(set, &ip, "part.json");
  test::check_qif_valid(contacts, dir + "/contacts.qif");
  const QifMeasuredPoints read = parse_qif_points(contacts, "contacts.qif");
  REQUIRE(read.points.size() == set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(same_bits(read.points[i].xyz[k], set.points[i].xyz[k]));
}

TEST_CASE("the schema check fails on an exponent in a decimal, an element out of order, a bad enumeration") {
  const std::string dir = test::scratch_dir("qif-schema-negative");
  const std::string good = qif_results_text(edge_document());
  test::check_qif_valid(good, dir + "/good.qif");
  const auto rejected = [&](const std::string& text, const std::string& name, const std::string& error) {
    test::write_text(dir + "/" + name, text);
    const test::QifValidation v = test::validate_qif_file(dir + "/" + name);
    CAPTURE(v.errors);
    CHECK_FALSE(v.valid);
    CHECK(v.verdict == dir + "/" + name + " fails to validate");
    CHECK(v.errors.find(error) != std::string::npos);
  };
  // The profile's measured value in exponent notation, as the writer once did.
  rejected(with_content(good, "Value", "1.5508968404631673e-05"), "exponent.qif",
           "'1.5508968404631673e-05' is not a valid value of the atomic type 'xs:decimal'");
  // Characteristics without the FormalStandardId it requires first.
  std::string no_standard = good;
  const std::size_t at = no_standard.find("<FormalStandardId>");
  REQUIRE(at != std::string::npos);
  no_standard.erase(at, no_standard.find('\n', at) + 1 - at);
  rejected(no_standard, "no_standard.qif",
           "Element '{http://qifstandards.org/xsd/qif3}CharacteristicDefinitions': This element is not expected. "
           "Expected is ( {http://qifstandards.org/xsd/qif3}FormalStandardId ).");
  rejected(with_content(good, "CharacteristicStatusEnum", "INCONCLUSIVE"), "enum.qif",
           "'INCONCLUSIVE' is not an element of the set");
  // Where the schema allows exponents - an xs:double list - another
  // program's document may use them: still valid, and read as written.
  const std::string foreign = with_content(good, "Location", "1.5E-05 -2e0 +3.25e+1");
  test::check_qif_valid(foreign, dir + "/foreign.qif");
  const QifMeasuredPoints q = parse_qif_points(foreign, "foreign.qif");
  REQUIRE_FALSE(q.points.empty());
  CHECK(*q.points[0].nominal == Eigen::Vector3d(1.5e-05, -2, 32.5));
}

TEST_CASE("the QIF id and count checks catch counts, ids and references") {
  const auto checked = [&](std::string from, const std::string& to) {
    std::string text = "<QIFDocument xmlns=\"http://qifstandards.org/xsd/qif3\" versionQIF=\"3.0.0\" idMax=\"3\">"
                       "<QPId>0b0e7c1a-1111-8222-9333-444455556666</QPId><Features>"
                       "<FeatureDefinitions n=\"1\"><PointFeatureDefinition id=\"1\"/></FeatureDefinitions>"
                       "<FeatureNominals n=\"1\">"
                       "<PointFeatureNominal id=\"2\"><FeatureDefinitionId>1</FeatureDefinitionId>"
                       "<Location>0 0 0</Location></PointFeatureNominal></FeatureNominals>"
                       "</Features><Results><MeasurementResultsSet n=\"1\"><MeasurementResults id=\"3\">"
                       "<InspectionStatus><InspectionStatusEnum>PASS</InspectionStatusEnum></InspectionStatus>"
                       "</MeasurementResults></MeasurementResultsSet></Results></QIFDocument>";
    if (!from.empty()) text.replace(text.find(from), from.size(), to);
    return test::qif_ids_and_counts(text);
  };
  using Problems = std::vector<std::string>;
  CHECK(checked("", "").problems.empty());
  CHECK(checked("", "").references == 1);
  CHECK(checked("<FeatureNominals n=\"1\">", "<FeatureNominals n=\"2\">").problems ==
        Problems{"FeatureNominals: n=2 but 1 children"});
  CHECK(checked("idMax=\"3\"", "idMax=\"2\"").problems ==
        Problems{"MeasurementResults: id 3 outside 1..idMax", "idMax is not the largest id"});
  CHECK(checked("<FeatureDefinitionId>1<", "<FeatureDefinitionId>7<").problems ==
        Problems{"FeatureDefinitionId 7 names no element"});
  CHECK(checked("id=\"2\"", "id=\"1\"").problems == Problems{"PointFeatureNominal: duplicate id 1"});
}
