#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "io/qif/qif_schema.hpp"
#include "results/spc_qif.hpp"
#include "results/spc_statistics.hpp"
#include "spc_batch.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

double number(const pugi::xml_node& n) { return std::strtod(n.child_value(), nullptr); }

}  // namespace

TEST_CASE("spc.qif validates against the QIF 3.0 schema and carries the figures per characteristic") {
  SpcInput in = spc_batch();
  in.parts[4].verdict = "INCONCLUSIVE";
  in.parts[7].serial = "SN <7> & \"x\"";
  const SpcResult r = compute_spc(in);
  const std::string text = spc_qif(r, {"results.sqlite", {}});
  CHECK(text == spc_qif(r, {"results.sqlite", {}}));  // deterministic, QPId included
  const std::string path = test::scratch_dir("spc-qif") + "/spc.qif";
  test::write_text(path, text);
  test::check_qif_valid_file(path);

  pugi::xml_document doc;
  REQUIRE(doc.load_string(text.c_str()));
  const pugi::xml_node root = doc.child("QIFDocument");
  // Every element with an id, to follow references.
  std::map<std::string, pugi::xml_node> by_id;
  unsigned max_id = 0;
  for (const pugi::xpath_node& n : root.select_nodes("//*[@id]")) {
    by_id[n.node().attribute("id").value()] = n.node();
    max_id = std::max(max_id, n.node().attribute("id").as_uint());
  }
  CHECK(root.attribute("idMax").as_uint() == max_id);
  // One result per part, in order, with its serial and verdict.
  const pugi::xpath_node_set results = root.select_nodes("Results/MeasurementResultsSet/MeasurementResults");
  REQUIRE(results.size() == r.parts.size());
  CHECK(std::string(results[7].node().select_node("Attributes/AttributeStr[@name='serial']").node().attribute("value").value()) ==
        "SN <7> & \"x\"");
  CHECK(std::string(results[4].node().select_node("InspectionStatus/OtherInspectionStatus").node().child_value()) ==
        "INCONCLUSIVE");
  CHECK(std::string(results[29].node().select_node("InspectionStatus/InspectionStatusEnum").node().child_value()) == "FAIL");
  // The statistics: one per characteristic, in the order of the result.
  const pugi::xpath_node_set stats =
      root.select_nodes("Statistics/StatisticalStudiesResults/CapabilityStudyResults/CharacteristicsStats/*");
  REQUIRE(stats.size() == r.characteristics.size());
  CHECK(root.select_node("Statistics//CapabilityStudyResults/NumberOfSamples").node().text().as_int() == 30);
  for (std::size_t i = 0; i < stats.size(); ++i) {
    const CharacteristicSpc& c = r.characteristics[i];
    CAPTURE(c.id);
    const pugi::xml_node s = stats[i].node();
    CHECK(std::string(s.name()) == (c.kind == "region" ? "SurfaceProfileCharacteristicStats" : "PointProfileCharacteristicStats"));
    // The measurements it rests on are this characteristic's values, in order,
    // each in the result of its part.
    std::vector<pugi::xml_node> measured;
    for (const pugi::xpath_node& id : s.select_nodes("MeasuredIds/Ids/Id")) measured.push_back(by_id.at(id.node().child_value()));
    REQUIRE(measured.size() == c.n);
    for (std::size_t j = 0; j < c.n; ++j) {
      const pugi::xml_node m = measured[j];
      const pugi::xml_node item = by_id.at(m.child("CharacteristicItemId").child_value());
      CHECK(std::string(item.child("Name").child_value()) == c.id);
      CHECK(number(m.child("Value")) == c.values[j]);
      CHECK(m.parent().parent().parent() == results[c.part_index[j]].node());
      const bool inside = c.values[j] >= c.lower && c.values[j] <= c.upper;
      CHECK(std::string(m.select_node("Status/CharacteristicStatusEnum").node().child_value()) == (inside ? "PASS" : "FAIL"));
      // The zone, through the nominal to the definition.
      const pugi::xml_node definition =
          by_id.at(by_id.at(item.child("CharacteristicNominalId").child_value()).child("CharacteristicDefinitionId").child_value());
      CHECK(std::abs(number(definition.child("ToleranceValue")) - (c.upper - c.lower)) < 1e-15);
    }
    const pugi::xml_node values = s.child("ValueStats");
    CHECK(values.child("TotalNumber").child("Value").text().as_ullong() == c.n);
    auto check = [&](const char* tag, const std::optional<double>& v) {
      CAPTURE(tag);
      const pugi::xml_node n = values.child(tag);
      CHECK(static_cast<bool>(n) == v.has_value());
      if (v && n) CHECK(number(n.child("Value")) == *v);  // exact decimal text reads back to the double
    };
    check("Average", c.mean);
    check("StandardDeviation", c.sigma_overall);
    check("EstimatedStandardDeviation", c.sigma_within);
    check("AverageRange", c.mr_mean);
    check("UpperControlLimit", c.ucl);
    check("LowerControlLimit", c.lcl);
    check("UpperControlLimitRange", c.mr_ucl);
    check("Cp", c.cp);
    check("Cpk", c.cpk);
    check("Pp", c.pp);
    check("Ppk", c.ppk);
    check("RegressionSlope", c.slope ? std::optional<double>(c.slope->value) : std::nullopt);
    check("UpperConfidenceLimit", c.slope ? c.slope->high : std::nullopt);
    // Out of control: the values that take part in a violation.
    std::size_t marked = 0;
    std::vector<bool> in_violation(c.n, false);
    for (const SpcViolation& v : c.violations)
      for (std::size_t j = v.index; j <= v.last; ++j) in_violation[j] = true;
    for (bool b : in_violation) marked += b;
    if (c.sigma_within && *c.sigma_within > 0)
      CHECK(values.child("NumberOutOfControl").child("Value").text().as_ullong() == marked);
    CHECK(s.select_nodes("Attributes/AttributeStr").size() == c.violations.size());
  }
}

TEST_CASE("spc.qif of a selection without parts is a valid document without statistics") {
  SpcInput in;
  in.characteristics.push_back({"P1", "point", -0.05, 0.05, {}, {}});
  const std::string text = spc_qif(compute_spc(in), {"results.sqlite", {}});
  const std::string path = test::scratch_dir("spc-qif-empty") + "/spc.qif";
  test::write_text(path, text);
  test::check_qif_valid_file(path);
  CHECK(text.find("<Statistics>") == std::string::npos);
}
