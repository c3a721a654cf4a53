// QIF 3.0 Results read as measurements (docs/qif.md "Reading"): documents
// laid out the way other software writes them, units, probe centres, and
// one InputError naming the file and line for anything malformed.
#include <doctest/doctest.h>

#include <cmath>

#include "base/error.hpp"
#include "io/cmm/measurement_qif.hpp"
#include "io/qif/qif_points_reader.hpp"
#include "qif_checks.hpp"
#include "qif_schema.hpp"

using namespace furrow;

namespace {

// Modelled on the layout of the qif-community sample documents: attributes
// on lines of their own, a namespace bound to a prefix, inch units with a
// conversion factor, one QIF 2-style PointFeatureActual next to a QIF 3
// PointFeatureMeasurement, a Normal on one measurement only.
const char* kForeign = R"(<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<q:QIFDocument
  xmlns:q="http://qifstandards.org/xsd/qif3"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
  idMax="40"
  versionQIF="3.0.0">
  <q:QPId>175819bb-4961-4ad0-8939-e06475685c4d</q:QPId>
  <q:FileUnits>
    <q:PrimaryUnits>
      <q:LinearUnit>
        <q:SIUnitName>meter</q:SIUnitName>
        <q:UnitName>inch</q:UnitName>
        <q:UnitConversion>
          <q:Factor>0.0254</q:Factor>
        </q:UnitConversion>
      </q:LinearUnit>
    </q:PrimaryUnits>
  </q:FileUnits>
  <q:Features>
    <q:FeatureNominals n="2">
      <q:PointFeatureNominal
        id="11">
        <q:FeatureDefinitionId>10</q:FeatureDefinitionId>
        <q:Location>1 2 3</q:Location>
        <q:Normal>0 0 2</q:Normal>
      </q:PointFeatureNominal>
      <q:PointFeatureNominal id="21">
        <q:FeatureDefinitionId>10</q:FeatureDefinitionId>
        <q:Location>-1 0.5 +4</q:Location>
        <q:Normal>1 0 0</q:Normal>
      </q:PointFeatureNominal>
    </q:FeatureNominals>
    <q:FeatureItems n="2">
      <q:PointFeatureItem id="12">
        <q:FeatureNominalId>11</q:FeatureNominalId>
        <q:FeatureName>POINT1</q:FeatureName>
      </q:PointFeatureItem>
      <q:PointFeatureItem id="22">
        <q:FeatureNominalId>21</q:FeatureNominalId>
      </q:PointFeatureItem>
    </q:FeatureItems>
  </q:Features>
  <q:Results>
    <q:MeasurementResultsSet n="1">
      <q:MeasurementResults id="30">
        <q:MeasuredFeatures n="2">
          <q:PointFeatureMeasurement id="31">
            <q:FeatureItemId> 12 </q:FeatureItemId>
            <q:Location>
              1.5 2 3.25
            </q:Location>
          </q:PointFeatureMeasurement>
          <q:PointFeatureActual id="32">
            <q:FeatureItemId>22</q:FeatureItemId>
            <q:Location>-1 0.5 4E0</q:Location>
            <q:Normal>0 3 4</q:Normal>
          </q:PointFeatureActual>
        </q:MeasuredFeatures>
        <q:InspectionStatus>
          <q:InspectionStatusEnum>PASS</q:InspectionStatusEnum>
        </q:InspectionStatus>
      </q:MeasurementResults>
    </q:MeasurementResultsSet>
  </q:Results>
</q:QIFDocument>
)";

std::string error_of(const std::string& text) {
  try {
    parse_qif_points(text, "m.qif");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A minimal Results document with one measured point; `location` and
// `units` vary.
std::string one_point(const std::string& location, const std::string& units = "") {
  return "<QIFDocument xmlns=\"http://qifstandards.org/xsd/qif3\" versionQIF=\"3.0.0\" idMax=\"5\">\n" + units +
         "<Features><FeatureNominals n=\"1\"><PointFeatureNominal id=\"2\"><FeatureDefinitionId>1"
         "</FeatureDefinitionId><Location>0 0 0</Location><Normal>0 0 1</Normal></PointFeatureNominal>"
         "</FeatureNominals>\n<FeatureItems n=\"1\"><PointFeatureItem id=\"3\"><FeatureNominalId>2"
         "</FeatureNominalId><FeatureName>A</FeatureName></PointFeatureItem></FeatureItems></Features>\n"
         "<Results><MeasurementResultsSet n=\"1\"><MeasurementResults id=\"4\"><MeasuredFeatures n=\"1\">\n"
         "<PointFeatureMeasurement id=\"5\"><FeatureItemId>3</FeatureItemId>\n"
         "<Location>" + location + "</Location></PointFeatureMeasurement>\n"
         "</MeasuredFeatures></MeasurementResults></MeasurementResultsSet></Results></QIFDocument>\n";
}

}  // namespace

TEST_CASE("QIF results from other software read: prefixed namespace, inch units, QIF 2 and 3 names") {
  const QifMeasuredPoints q = parse_qif_points(kForeign, "foreign.qif");
  REQUIRE(q.points.size() == 2);
  CHECK_FALSE(q.probe_radius);
  const QifMeasuredPoint& a = q.points[0];
  CHECK(a.id == "POINT1");
  // 1 inch = 25.4 mm, the factor 0.0254 m per file unit.
  CHECK(a.xyz.x() == doctest::Approx(38.1).epsilon(1e-15));
  CHECK(a.xyz.y() == doctest::Approx(50.8).epsilon(1e-15));
  CHECK(a.xyz.z() == doctest::Approx(82.55).epsilon(1e-15));
  CHECK(a.line == 47);  // the <q:PointFeatureMeasurement> line
  REQUIRE(a.nominal);
  CHECK((*a.nominal - Eigen::Vector3d(25.4, 50.8, 76.2)).norm() < 1e-12);
  REQUIRE(a.ijk);  // no Normal on the measurement: the nominal's, unit length
  CHECK((*a.ijk - Eigen::Vector3d(0, 0, 1)).norm() == 0);
  const QifMeasuredPoint& b = q.points[1];
  CHECK(b.id == "item 22");  // the item has no FeatureName
  CHECK((b.xyz - Eigen::Vector3d(-25.4, 12.7, 101.6)).norm() < 1e-12);
  REQUIRE(b.ijk);  // the measurement's own Normal (0 3 4)/5
  CHECK((*b.ijk - Eigen::Vector3d(0, 0.6, 0.8)).norm() < 1e-15);
  REQUIRE(b.nominal_ijk);
  CHECK((*b.nominal_ijk - Eigen::Vector3d(1, 0, 0)).norm() == 0);

  // Through the measurement file dispatch: contact points, ids from the file.
  MeasurementReadOptions o;
  const MeasurementSet set = parse_measurements(kForeign, "foreign.QIF", MeasurementFormat::qif, o);
  CHECK(set.kind == ProbePointKind::contact);
  CHECK(set.ids_from_file);
  CHECK(set.points.size() == 2);
  CHECK(measurement_format_from_path("x/Results.QIF") == MeasurementFormat::qif);
  o.kind = ProbePointKind::probe_centre;
  CHECK_THROWS_WITH_AS(parse_measurements(kForeign, "foreign.qif", MeasurementFormat::qif, o),
                       "foreign.qif: the file holds compensated contact points, not probe centres (--points)",
                       InputError);
}

TEST_CASE("QIF length units: by factor, by name, millimetres when absent, others refused") {
  const auto unit = [](const std::string& name, const std::string& factor) {
    return "<FileUnits><PrimaryUnits><LinearUnit><UnitName>" + name + "</UnitName>" +
           (factor.empty() ? "" : "<UnitConversion><Factor>" + factor + "</Factor></UnitConversion>") +
           "</LinearUnit></PrimaryUnits></FileUnits>\n";
  };
  CHECK(parse_qif_points(one_point("1 2 3"), "m.qif").points[0].xyz == Eigen::Vector3d(1, 2, 3));
  CHECK((parse_qif_points(one_point("1 2 3", unit("in", "")), "m.qif").points[0].xyz -
         Eigen::Vector3d(25.4, 50.8, 76.2)).norm() < 1e-12);
  CHECK(parse_qif_points(one_point("1 2 3", unit("m", "")), "m.qif").points[0].xyz ==
        Eigen::Vector3d(1000, 2000, 3000));
  CHECK(parse_qif_points(one_point("2 2 2", unit("whatever", "0.001")), "m.qif").points[0].xyz ==
        Eigen::Vector3d(2, 2, 2));
  CHECK(error_of(one_point("1 2 3", unit("furlong", ""))) ==
        "m.qif:2: linear unit \"furlong\" is not mm, cm, m or inch and has no <UnitConversion>");
}

TEST_CASE("malformed QIF: one InputError naming the file and the line") {
  CHECK(error_of("<QIFDocument>\n<Features>\n</Feature>\n") == "m.qif:3: malformed XML: Start-end tags mismatch");
  CHECK(error_of("<?xml version=\"1.0\"?>\n<DMIS/>\n") ==
        "m.qif:2: not a QIF document (the root element is <DMIS>, expected <QIFDocument>)");
  CHECK(error_of(one_point("1 2")) == "m.qif:6: <Location>: expected 3 numbers, found 2");
  CHECK(error_of(one_point("1 2 3 4")) == "m.qif:6: <Location>: expected 3 numbers, found more");
  CHECK(error_of(one_point("1 x 3")) == "m.qif:6: <Location>: \"x\" is not a finite number");
  CHECK(error_of(one_point("1 INF 3")) == "m.qif:6: <Location>: \"INF\" is not a finite number");
  std::string dangling = one_point("1 2 3");
  dangling.replace(dangling.find("<FeatureItemId>3<"), 17, "<FeatureItemId>9<");
  CHECK(error_of(dangling) == "m.qif:5: <FeatureItemId> 9 names no feature item");
  std::string none = one_point("1 2 3");
  none.replace(none.find("PointFeatureMeasurement id"), 23, "LineFeatureMeasurement ");
  none.replace(none.find("</PointFeatureMeasurement>"), 26, "</LineFeatureMeasurement >");
  CHECK(error_of(none) ==
        "m.qif: no measured points (no PointFeatureMeasurement in Results/MeasurementResultsSet/"
        "MeasurementResults/MeasuredFeatures)");
}

TEST_CASE("probe centres written as QIF come back bit for bit, as centres with the probe radius") {
  MeasurementSet set;
  set.source = "sim";
  set.kind = ProbePointKind::probe_centre;
  set.probe_radius = 1;
  set.ids_from_file = true;
  InspectionPlan plan;
  plan.probe = {"ruby", 2};
  for (int i = 0; i < 5; ++i) {
    PlannedPoint p;
    p.id = "P" + std::to_string(i);
    p.xyz = Eigen::Vector3d(0.1 * i, 1.0 / 3 + i, -2.0 / 7);
    p.ijk = Eigen::Vector3d(0, std::sin(0.1 * i), std::cos(0.1 * i));
    plan.points.push_back(p);
    MeasuredPoint m;
    m.id = p.id;
    m.xyz = p.centre(1) + Eigen::Vector3d(1e-3 / 3, 0, 1e-17);
    m.ijk = p.ijk;
    set.points.push_back(m);
  }
  const std::string text = measurements_to_qif(set, &plan, "part.json");
  test::check_qif_valid(text, test::scratch_dir("qif-measurements") + "/m.qif");
  CHECK(test::check_qif_ids_and_counts(text) > 5);
  MeasurementReadOptions o;
  o.probe_diameter = 2;
  const MeasurementSet back = parse_measurements(text, "m.qif", MeasurementFormat::qif, o);
  CHECK(back.kind == ProbePointKind::probe_centre);
  CHECK(back.probe_radius == 1);
  REQUIRE(back.points.size() == set.points.size());
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    CHECK(back.points[i].id == set.points[i].id);
    CHECK(back.points[i].xyz == set.points[i].xyz);  // shortest round-trip text: exact
    CHECK(*back.points[i].nominal == plan.points[i].xyz);
    CHECK(*back.points[i].nominal_ijk == plan.points[i].ijk.normalized());
  }
  o.probe_diameter = 3;
  CHECK_THROWS_AS(parse_measurements(text, "m.qif", MeasurementFormat::qif, o), InputError);
  // The same set again: the same bytes (the QPIds come from the content).
  CHECK(measurements_to_qif(set, &plan, "part.json") == text);
  set.points[0].xyz.x() += 1e-12;
  const std::string other = measurements_to_qif(set, &plan, "part.json");
  CHECK(other.substr(other.find("<QPId>"), 50) != text.substr(text.find("<QPId>"), 50));
  // A point that is neither in the plan nor carries a nominal cannot be a QIF feature.
  plan.points.pop_back();
  CHECK_THROWS_WITH_AS(measurements_to_qif(set, &plan, "part.json"),
                       "sim: point \"P4\" has no nominal (not in the plan): a QIF point feature needs one",
                       InputError);
}

TEST_CASE("QIF point lists used only when every point has an uncompensated centre, else the Locations") {
  // As in a CMM's results: most points list their raw probe centre, one has
  // no list, one names itself; the Locations are the compensated points.
  const std::string text = R"(<QIFDocument xmlns="http://qifstandards.org/xsd/qif3" versionQIF="3.0.0" idMax="30">
<Features><FeatureNominals n="3">
<PointFeatureNominal id="2"><FeatureDefinitionId>1</FeatureDefinitionId><Location>0 0 0</Location><Normal>0 0 1</Normal></PointFeatureNominal>
<PointFeatureNominal id="3"><FeatureDefinitionId>1</FeatureDefinitionId><Location>1 0 0</Location><Normal>0 0 1</Normal></PointFeatureNominal>
<PointFeatureNominal id="4"><FeatureDefinitionId>1</FeatureDefinitionId><Location>2 0 0</Location><Normal>0 0 1</Normal></PointFeatureNominal>
</FeatureNominals><FeatureItems n="3">
<PointFeatureItem id="5"><FeatureNominalId>2</FeatureNominalId><FeatureName>A</FeatureName></PointFeatureItem>
<PointFeatureItem id="6"><FeatureNominalId>3</FeatureNominalId><FeatureName>B</FeatureName></PointFeatureItem>
<PointFeatureItem id="7"><FeatureNominalId>4</FeatureNominalId><FeatureName>C</FeatureName></PointFeatureItem>
</FeatureItems></Features>
<Results><MeasurementResultsSet n="1"><MeasurementResults id="10"><MeasuredFeatures n="3">
<PointFeatureMeasurement id="11"><FeatureItemId>5</FeatureItemId><PointList n="1"><WholePointSetId>21</WholePointSetId></PointList><Location>0 0 0.01</Location></PointFeatureMeasurement>
<PointFeatureMeasurement id="12"><FeatureItemId>6</FeatureItemId><Location>1 0 0.02</Location></PointFeatureMeasurement>
<PointFeatureMeasurement id="13"><FeatureItemId>7</FeatureItemId><PointList n="1"><WholePointSetId>13</WholePointSetId></PointList><Location>2 0 0.03</Location></PointFeatureMeasurement>
</MeasuredFeatures><MeasuredPointSets n="1">
<MeasuredPointSet count="1" id="21"><Points>0 0 2.51</Points><Compensated>false</Compensated><ProbeRadius>2.5</ProbeRadius></MeasuredPointSet>
</MeasuredPointSets></MeasurementResults></MeasurementResultsSet></Results></QIFDocument>
)";
  const QifMeasuredPoints q = parse_qif_points(text, "cmm.qif");
  CHECK_FALSE(q.probe_radius);
  REQUIRE(q.points.size() == 3);
  CHECK(q.points[0].xyz == Eigen::Vector3d(0, 0, 0.01));
  CHECK(q.points[1].xyz == Eigen::Vector3d(1, 0, 0.02));
  CHECK(q.points[2].xyz == Eigen::Vector3d(2, 0, 0.03));
  // Without the Location of a point that has no centre: nothing to read for it.
  std::string missing = text;
  missing.replace(missing.find("<Location>1 0 0.02</Location>"), 29, "");
  CHECK(error_of(missing) ==
        "m.qif:13: point \"B\" has no <Location> (and not every point has an uncompensated probe centre)");
}
