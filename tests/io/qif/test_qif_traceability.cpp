// The inspection record's place in a QIF Results document:
// InspectionTraceability valid by the QIF 3.0 XSD, the customer and the CMM
// program as attributes (their QIF elements require what a record does not
// know), the attribute values escaped so that an XML parser reads back
// exactly the text given.
#include <doctest/doctest.h>

#include <pugixml.hpp>

#include "io/qif/qif_document.hpp"
#include "qif_checks.hpp"
#include "qif_schema.hpp"

using namespace furrow;

namespace {

QifDocumentData one_point() {
  QifDocumentData d;
  d.part_name = "part.json";
  d.description = "test";
  QifPoint p;
  p.id = "P1";
  p.nominal = {1, 2, 3};
  p.actual = Eigen::Vector3d(1, 2, 3.001);
  p.deviation = 0.001;
  p.status = "PASS";
  d.points.push_back(p);
  QifProfile profile;
  profile.tolerance = 0.05;
  profile.value = 0.002;
  profile.status = "PASS";
  d.profile = profile;
  d.inspection_status = "PASS";
  return d;
}

}  // namespace

TEST_CASE("the record goes into InspectionTraceability valid by the schema and reads back exactly") {
  QifDocumentData d = one_point();
  d.time = "2026-11-25T12:00:00Z";
  QifTraceability t;
  t.customer = "Acme & <Co>";
  t.program = "mould.dmi";
  t.operator_name = "J. \"Jo\" Doe";
  t.report_preparer = "A. Prep";
  t.attributes = {{"serial", "SN 1"}, {"notes", "line 1\nline 2\ttab \"q\""}, {"lot", ""}};
  d.traceability = t;
  const std::string text = qif_results_text(d);
  test::check_qif_valid(text, test::scratch_dir("qif-traceability") + "/record.qif");
  CHECK(test::check_qif_ids_and_counts(text) > 5);

  pugi::xml_document doc;
  REQUIRE(doc.load_string(text.c_str()));
  const pugi::xml_node tr =
      doc.child("QIFDocument").child("Results").child("MeasurementResultsSet").child("MeasurementResults").child(
          "InspectionTraceability");
  REQUIRE(tr);
  std::vector<std::string> order;
  for (pugi::xml_node c = tr.first_child(); c; c = c.next_sibling()) order.push_back(c.name());
  CHECK(order == std::vector<std::string>{"InspectionOperator", "ReportPreparer", "ReportPreparationDate",
                                          "Attributes"});
  CHECK(std::string(tr.child("InspectionOperator").child_value("Name")) == "J. \"Jo\" Doe");
  CHECK(std::string(tr.child("ReportPreparer").child_value("Name")) == "A. Prep");
  CHECK(std::string(tr.child_value("ReportPreparationDate")) == "2026-11-25T12:00:00Z");
  const pugi::xml_node attributes = tr.child("Attributes");
  CHECK(attributes.attribute("n").as_int() == 4);  // the empty lot is left out
  std::vector<std::pair<std::string, std::string>> read;
  for (pugi::xml_node a = attributes.first_child(); a; a = a.next_sibling())
    read.emplace_back(a.attribute("name").value(), a.attribute("value").value());
  CHECK(read == std::vector<std::pair<std::string, std::string>>{{"customer", "Acme & <Co>"},
                                                                 {"program", "mould.dmi"},
                                                                 {"serial", "SN 1"},
                                                                 {"notes", "line 1\nline 2\ttab \"q\""}});
}

TEST_CASE("without a record nor a time there is no InspectionTraceability but a record alone gives one") {
  QifDocumentData d = one_point();
  CHECK(qif_results_text(d).find("InspectionTraceability") == std::string::npos);
  QifTraceability t;
  t.operator_name = "J. Doe";
  d.traceability = t;
  const std::string text = qif_results_text(d);
  test::check_qif_valid(text, test::scratch_dir("qif-traceability-operator") + "/operator.qif");
  CHECK(test::check_qif_ids_and_counts(text) > 5);
  CHECK(text.find("<InspectionTraceability>") != std::string::npos);
  CHECK(text.find("<ReportPreparationDate>") == std::string::npos);
  CHECK(text.find("<Attributes") == std::string::npos);
}
