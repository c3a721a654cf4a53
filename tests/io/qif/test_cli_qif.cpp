// End-to-end QIF (docs/qif.md): a plan's points simulated as QIF and as CSV
// compare to the same deviations; compare --qif writes Results that read
// back as the registered points and say what comparison.json says, point by
// point; furrow plan writes plan.qif; bad QIF ends with exit 2 naming
// file:line and nothing written.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <set>
#include <pugixml.hpp>

#include "base/json_fields.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/cmm/measurement_file.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "qif_checks.hpp"
#include "qif_schema.hpp"
#include "report/report_qif.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
namespace fs = std::filesystem;

namespace {

const std::string kMould = test::source_path("examples/parts/mould.json");

std::string write_mould_plan(const std::string& dir) {
  const Part part = read_part(kMould);
  InspectionPlan plan = grid_plan(part, 12, 10, {"ruby 2 mm", 2});
  plan.part = kMould;
  write_plan(plan, dir + "/plan.json");
  return dir + "/plan.json";
}

std::vector<double> triple(const char* text) {
  std::istringstream in(text);
  std::vector<double> v(3);
  in >> v[0] >> v[1] >> v[2];
  return v;
}

}  // namespace

TEST_CASE("QIF end to end: simulated QIF compares like CSV, results.qif matches comparison.json point by point") {
  const std::string dir = test::scratch_dir("cli-qif-roundtrip");
  const std::string plan = write_mould_plan(dir);
  // Noise near the zone's half width gives FAIL points, blunders NOT_ANALYZED ones.
  const std::vector<std::string> sim = {"simulate-measurement", kMould, "--plan", plan, "--misalign",
                                        "1,-2,30,15,-5,4", "--outliers", "3", "--seed", "5",
                                        "--noise", "0.015"};
  for (const char* ext : {".csv", ".qif"}) {
    std::vector<std::string> args = sim;
    args.insert(args.end(), {"--out", dir + "/m" + ext});
    REQUIRE(test::run_furrow(args).status == 0);
  }
  const auto csv = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.csv", "--plan", plan, "--out",
                                     dir + "/csv.json"});
  const auto qif = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.qif", "--plan", plan, "--out",
                                     dir + "/qif.json", "--qif", dir + "/results.qif"});
  CHECK(qif.status == csv.status);
  CHECK(qif.status == 1);  // points out of tolerance
  const ComparisonDocument a = read_comparison(dir + "/csv.json");
  const ComparisonDocument b = read_comparison(dir + "/qif.json");
  REQUIRE(a.points.size() == 120);
  REQUIRE(b.points.size() == a.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    CAPTURE(a.points[i].id);
    CHECK(b.points[i].id == a.points[i].id);
    CHECK(std::abs(b.points[i].deviation - a.points[i].deviation) <= 1e-9);
    CHECK(b.points[i].in_tolerance == a.points[i].in_tolerance);
  }
  CHECK(b.summary.verdict == a.summary.verdict);

  // The simulated measurement and results.qif valid by the QIF 3.0 XSD,
  // then every point of results.qif against comparison.json.
  test::check_qif_valid_file(dir + "/m.qif");
  test::check_qif_valid_file(dir + "/results.qif");
  const std::string text = test::slurp(dir + "/results.qif");
  CHECK(test::check_qif_ids_and_counts(text) > 400);
  pugi::xml_document doc;
  REQUIRE(doc.load_string(text.c_str()));
  const pugi::xml_node root = doc.document_element();
  std::map<std::string, pugi::xml_node> by_id;  // QIF id -> element
  for (pugi::xpath_node n : root.select_nodes("//*[@id]")) by_id[n.node().attribute("id").value()] = n.node();
  const pugi::xml_node results = root.child("Results").child("MeasurementResultsSet").child("MeasurementResults");
  CHECK(std::string(results.child("InspectionStatus").child_value("InspectionStatusEnum")) == "FAIL");
  std::size_t measured = 0, fails = 0, not_analyzed = 0;
  for (pugi::xml_node m : results.child("MeasuredCharacteristics").child("CharacteristicMeasurements").children(
           "PointProfileCharacteristicMeasurement")) {
    const pugi::xml_node item = by_id.at(m.child_value("CharacteristicItemId"));
    const std::string point_id = item.child_value("Name");
    const ComparisonDocument::Point& p = b.points.at(b.points_by_id.at(point_id));
    const std::string status = m.child("Status").child_value("CharacteristicStatusEnum");
    CAPTURE(point_id);
    CHECK(status == (!p.in_tolerance ? "NOT_ANALYZED" : *p.in_tolerance ? "PASS" : "FAIL"));
    fails += status == "FAIL";
    not_analyzed += status == "NOT_ANALYZED";
    CHECK(std::stod(m.child_value("Value")) == p.deviation);
    // The feature measurement it names: the registered contact point.
    const pugi::xml_node fm = by_id.at(m.child("FeatureMeasurementIds").child_value("Id"));
    CHECK(triple(fm.child_value("Location")) == std::vector<double>{p.contact.x(), p.contact.y(), p.contact.z()});
    const pugi::xml_node feature_item = by_id.at(fm.child_value("FeatureItemId"));
    CHECK(std::string(feature_item.child_value("FeatureName")) == point_id);
    const pugi::xml_node nominal = by_id.at(feature_item.child_value("FeatureNominalId"));
    CHECK(triple(nominal.child_value("Location")) == std::vector<double>{p.foot.x(), p.foot.y(), p.foot.z()});
    ++measured;
  }
  CHECK(measured == b.points.size());
  CHECK(fails == b.summary.out_of_tolerance);
  CHECK(fails > 0);
  CHECK(not_analyzed > 0);
  CHECK(not_analyzed == b.points.size() - b.summary.evaluated);
  const pugi::xml_node surface =
      results.child("MeasuredCharacteristics").child("CharacteristicMeasurements").child(
          "SurfaceProfileCharacteristicMeasurement");
  CHECK(std::string(surface.child("Status").child_value("CharacteristicStatusEnum")) == "FAIL");
  CHECK(std::stod(surface.child_value("Value")) == b.summary.profile);
  CHECK(std::stod(root.child("Characteristics").child("CharacteristicDefinitions").child(
            "SurfaceProfileCharacteristicDefinition").child_value("ToleranceValue")) == 0.05);
  // The inputs with their SHA-256: the part's digest is the one of its bytes.
  bool part_listed = false;
  for (pugi::xml_node f : results.child("ExternalFileReferences").children("ExternalFileReference"))
    if (std::string(f.child("FileSpec").child_value("OtherFileSpec")) == "part") {
      part_listed = true;
      CHECK(std::string(f.child_value("URI")) == kMould);
      CHECK(std::string(f.child_value("Description")).size() == 8 + 64);  // "SHA-256 " + hex
    }
  CHECK(part_listed);
  CHECK(text.find("TimeCreated") == std::string::npos);  // comparison.json has no time

  // The alignment: ActualTransforms holds the transform that takes each
  // point as measured (a probe centre, CMM frame) to its actual - the
  // registered centre moved back by the ball radius along the normal.
  const pugi::xml_node transform = results.child("ActualTransforms").child("Transform");
  REQUIRE(transform);
  CHECK(std::string(transform.child("Attributes").child("AttributeStr").attribute("name").value()) == "alignment");
  CHECK(std::string(transform.child("Attributes").child("AttributeStr").attribute("value").value()) == "bestfit");
  Eigen::Matrix3d rotation;
  for (int k = 0; k < 3; ++k) {
    const std::vector<double> c = triple(transform.child("Rotation").child_value(k == 0 ? "XDirection"
                                                                                  : k == 1 ? "YDirection"
                                                                                           : "ZDirection"));
    REQUIRE(c.size() == 3);
    rotation.col(k) = Eigen::Vector3d(c[0], c[1], c[2]);
  }
  const std::vector<double> origin = triple(transform.child_value("Origin"));
  REQUIRE(origin.size() == 3);
  CHECK((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  CHECK(rotation.determinant() > 0);
  const double r = b.options.probe_diameter / 2;
  REQUIRE(r > 0);
  double worst = 0;
  for (const ComparisonDocument::Point& p : b.points)
    worst = std::max(worst, (rotation * p.measured + Eigen::Vector3d(origin[0], origin[1], origin[2]) - r * p.normal - p.contact).norm());
  CHECK(worst < 1e-9);

  // Read back as measurements: the registered contact points, exactly.
  MeasurementReadOptions o;
  const MeasurementSet back = read_measurements(dir + "/results.qif", o);
  CHECK(back.kind == ProbePointKind::contact);
  REQUIRE(back.points.size() == b.points.size());
  for (std::size_t i = 0; i < back.points.size(); ++i) {
    CHECK(back.points[i].id == b.points[i].id);
    CHECK(back.points[i].xyz == b.points[i].contact);
  }

  // INCONCLUSIVE has no InspectionStatusEnum value: OtherInspectionStatus.
  ComparisonDocument inconclusive = b;
  inconclusive.summary.verdict = Verdict::inconclusive;
  const std::string other = comparison_to_qif(inconclusive, {}, std::string("2026-01-02T03:04:05Z"));
  test::check_qif_valid(other, dir + "/inconclusive.qif");
  CHECK(test::check_qif_ids_and_counts(other) > 400);
  CHECK(other.find("<OtherInspectionStatus>INCONCLUSIVE</OtherInspectionStatus>") != std::string::npos);
  CHECK(other.find("<CharacteristicStatusEnum>INDETERMINATE</CharacteristicStatusEnum>") != std::string::npos);
  CHECK(other.find("<TimeCreated>2026-01-02T03:04:05Z</TimeCreated>") != std::string::npos);
  CHECK(other.find("<ReportPreparationDate>2026-01-02T03:04:05Z</ReportPreparationDate>") != std::string::npos);
  // The QPIds identify the content, not the moment it was written.
  const std::string later = comparison_to_qif(inconclusive, {}, std::string("2027-05-06T07:08:09Z"));
  CHECK(later.substr(later.find("<QPId>"), 48) == other.substr(other.find("<QPId>"), 48));
  CHECK(later != other);

  // Same inputs, same bytes.
  const auto again = test::run_furrow({"compare", kMould, "--measurements", dir + "/m.qif", "--plan", plan, "--out",
                                       dir + "/again.json", "--qif", dir + "/again.qif"});
  CHECK(again.status == qif.status);
  CHECK(test::slurp(dir + "/again.qif") == text);
}

TEST_CASE("furrow plan writes plan.qif: the alignment and plan points as nominals and the profile zone") {
  const std::string dir = test::scratch_dir("cli-qif-plan");
  REQUIRE(test::run_furrow({"partition", kMould, "--out", dir + "/regions.json", "--grid", "100x80"}).status == 0);
  const auto r = test::run_furrow({"plan", kMould, "--regions", dir + "/regions.json", "--out", dir + "/p",
                                   "--points", "40", "--tolerance", "0.1", "--outside", "0.1"});
  REQUIRE(r.status == 0);
  test::check_qif_valid_file(dir + "/p/plan.qif");
  const std::string text = test::slurp(dir + "/p/plan.qif");
  CHECK(test::check_qif_ids_and_counts(text) > 40);
  const InspectionPlan plan = read_plan(dir + "/p/plan.json");
  pugi::xml_document doc;
  REQUIRE(doc.load_string(text.c_str()));
  const pugi::xml_node root = doc.document_element();
  CHECK_FALSE(root.child("Results"));
  const pugi::xml_node features = root.child("Features");
  std::vector<pugi::xml_node> nominals, items;
  for (pugi::xml_node n : features.child("FeatureNominals").children("PointFeatureNominal")) nominals.push_back(n);
  for (pugi::xml_node n : features.child("FeatureItems").children("PointFeatureItem")) items.push_back(n);
  // The part alignment's points first (the mould's manual best fit), then the plan's.
  REQUIRE(plan.alignment);
  const std::vector<PlannedPoint> aligned = plan.alignment->points();
  REQUIRE(aligned.size() >= 3);
  const std::size_t k0 = aligned.size();
  REQUIRE(nominals.size() == k0 + plan.points.size());
  REQUIRE(items.size() == k0 + plan.points.size());
  for (std::size_t i = 0; i < k0; ++i) {
    CHECK(std::string(items[i].child_value("FeatureName")) == aligned[i].id);
    CHECK(triple(nominals[i].child_value("Location")) ==
          std::vector<double>{aligned[i].xyz.x(), aligned[i].xyz.y(), aligned[i].xyz.z()});
  }
  nominals.erase(nominals.begin(), nominals.begin() + static_cast<long>(k0));
  std::vector<pugi::xml_node> alignment_items(items.begin(), items.begin() + static_cast<long>(k0));
  items.erase(items.begin(), items.begin() + static_cast<long>(k0));
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const PlannedPoint& p = plan.points[i];
    CHECK(std::string(items[i].child_value("FeatureName")) == p.id);
    CHECK(triple(nominals[i].child_value("Location")) == std::vector<double>{p.xyz.x(), p.xyz.y(), p.xyz.z()});
    CHECK(triple(nominals[i].child_value("Normal")) == std::vector<double>{p.ijk.x(), p.ijk.y(), p.ijk.z()});
  }
  const pugi::xml_node definition =
      root.child("Characteristics").child("CharacteristicDefinitions").child("SurfaceProfileCharacteristicDefinition");
  CHECK(std::stod(definition.child_value("ToleranceValue")) == 0.1);
  CHECK(std::stod(definition.child_value("OuterDisposition")) == 0.1);  // unilateral outside
  const pugi::xml_node profiled = root.child("Characteristics").child("CharacteristicItems").child(
      "SurfaceProfileCharacteristicItem").child("FeatureItemIds");
  CHECK(std::string(profiled.attribute("n").value()) == std::to_string(plan.points.size()));
  // The profile names the plan's points only, not the alignment's.
  std::set<std::string> profiled_ids;
  for (pugi::xml_node id : profiled.children("Id")) profiled_ids.insert(id.child_value());
  for (const pugi::xml_node& item : alignment_items) CHECK(profiled_ids.count(item.attribute("id").value()) == 0);
  for (const pugi::xml_node& item : items) CHECK(profiled_ids.count(item.attribute("id").value()) == 1);
  // The Plan measures every point in the plan's execution order, then
  // evaluates the profile: step k names the item of the point with order k.
  std::map<std::string, std::string> item_name;
  for (const pugi::xml_node& item : items) item_name[item.attribute("id").value()] = item.child_value("FeatureName");
  for (const pugi::xml_node& item : alignment_items)
    item_name[item.attribute("id").value()] = item.child_value("FeatureName");
  // Steps: the alignment's points, then the plan's by order.
  std::map<int, std::string> id_by_order;
  for (std::size_t i = 0; i < k0; ++i) id_by_order[static_cast<int>(i) + 1] = aligned[i].id;
  for (const PlannedPoint& p : plan.points) id_by_order[static_cast<int>(k0) + p.order] = p.id;
  const pugi::xml_node steps = root.child("Plan").child("OrderedPlanRoot").child("Steps");
  REQUIRE(steps);
  std::vector<pugi::xml_node> numbered;
  for (pugi::xml_node n : steps.children("NumberedPlanElement")) numbered.push_back(n);
  REQUIRE(numbered.size() == k0 + plan.points.size() + 1);
  for (std::size_t k = 0; k < k0 + plan.points.size(); ++k) {
    CHECK(std::stoi(numbered[k].child_value("SequenceNumber")) == static_cast<int>(k) + 1);
    const std::string ref = numbered[k].child("MeasureSpecifiedFeatures").child("FeatureItemIds").child_value("Id");
    CHECK(item_name[ref] == id_by_order[static_cast<int>(k) + 1]);
  }
  CHECK(std::string(numbered.back().child("EvaluateSpecifiedCharacteristics").child("CharacteristicItemIds").child_value(
            "Id")) == root.child("Characteristics").child("CharacteristicItems").child(
                          "SurfaceProfileCharacteristicItem").attribute("id").value());
}

TEST_CASE("bad QIF measurements: exit 2 naming the file and line, nothing written") {
  const std::string dir = test::scratch_dir("cli-qif-bad");
  const std::string path = dir + "/m.qif";
  test::write_text(path, "<?xml version=\"1.0\"?>\n<QIFDocument>\n  <Features>\n  </Results>\n</QIFDocument>\n");
  const auto r = test::run_furrow({"compare", kMould, "--measurements", path, "--out", dir + "/c.json", "--qif",
                                   dir + "/r.qif"});
  CHECK(r.status == 2);
  CHECK(r.err == "error: " + path + ":4: malformed XML: Start-end tags mismatch\n");
  CHECK_FALSE(fs::exists(dir + "/c.json"));
  CHECK_FALSE(fs::exists(dir + "/r.qif"));
  test::write_text(path, "<QIFDocument versionQIF=\"3.0.0\" idMax=\"1\"><QPId>x</QPId></QIFDocument>\n");
  const auto empty = test::run_furrow({"compare", kMould, "--measurements", path, "--out", dir + "/c.json"});
  CHECK(empty.status == 2);
  CHECK(empty.err.find(path + ": no measured points") != std::string::npos);
  CHECK(test::line_count(empty.err) == 1);
}

TEST_CASE("furrow run (the demo) writes results.qif timed like report.json and plan/plan.qif") {
  const std::string dir = test::scratch_dir("cli-qif-demo");
  const auto r = test::run_furrow({"demo", "--out", dir + "/out"});
  REQUIRE((r.status == 0 || r.status == 1 || r.status == 4));
  test::check_qif_valid_file(dir + "/out/results.qif");
  test::check_qif_valid_file(dir + "/out/plan/plan.qif");
  const std::string text = test::slurp(dir + "/out/results.qif");
  CHECK(test::check_qif_ids_and_counts(text) > 100);
  CHECK(test::check_qif_ids_and_counts(test::slurp(dir + "/out/plan/plan.qif")) > 10);
  const json_fields::json report = json_fields::load_file(dir + "/out/report.json");
  const ComparisonDocument c = read_comparison(dir + "/out/comparison.json");
  pugi::xml_document doc;
  REQUIRE(doc.load_string(text.c_str()));
  const pugi::xml_node root = doc.document_element();
  const std::string generated = report["generated"].get<std::string>();
  CHECK(std::string(root.child("Version").child_value("TimeCreated")) == generated);
  const pugi::xml_node results = root.child("Results").child("MeasurementResultsSet").child("MeasurementResults");
  CHECK(std::string(results.child("InspectionTraceability").child_value("ReportPreparationDate")) == generated);
  const pugi::xml_node status = results.child("InspectionStatus");
  if (c.summary.verdict == Verdict::inconclusive)
    CHECK(std::string(status.child_value("OtherInspectionStatus")) == "INCONCLUSIVE");
  else
    CHECK(std::string(status.child_value("InspectionStatusEnum")) == to_string(c.summary.verdict));
  std::size_t measured = 0;
  for (pugi::xml_node m : results.child("MeasuredFeatures").children("PointFeatureMeasurement")) {
    (void)m;
    ++measured;
  }
  CHECK(measured == c.points.size());
}
