#include "results/spc_json.hpp"

#include "base/json_fields.hpp"

namespace furrow {
namespace {

using nlohmann::json;
namespace jf = json_fields;

json optional_number(const std::optional<double>& v, const char* what) {
  return v ? jf::finite(*v, what) : json(nullptr);
}

json characteristic_json(const CharacteristicSpc& c) {
  json j;
  j["id"] = c.id;
  j["kind"] = c.kind;
  j["lower"] = jf::finite(c.lower, "lower");
  j["upper"] = jf::finite(c.upper, "upper");
  j["n"] = c.n;
  j["part_index"] = c.part_index;
  json values = json::array();
  for (double v : c.values) values.push_back(jf::finite(v, "value"));
  j["values"] = values;
  j["mean"] = optional_number(c.mean, "mean");
  j["sigma_within"] = optional_number(c.sigma_within, "sigma_within");
  j["sigma_overall"] = optional_number(c.sigma_overall, "sigma_overall");
  j["mr_mean"] = optional_number(c.mr_mean, "mr_mean");
  j["mr_ucl"] = optional_number(c.mr_ucl, "mr_ucl");
  j["lcl"] = optional_number(c.lcl, "lcl");
  j["ucl"] = optional_number(c.ucl, "ucl");
  j["cp"] = optional_number(c.cp, "cp");
  j["cpk"] = optional_number(c.cpk, "cpk");
  j["pp"] = optional_number(c.pp, "pp");
  j["ppk"] = optional_number(c.ppk, "ppk");
  if (c.slope) {
    j["slope"] = {{"value", jf::finite(c.slope->value, "slope")},
                  {"low", optional_number(c.slope->low, "slope low")},
                  {"high", optional_number(c.slope->high, "slope high")}};
  } else {
    j["slope"] = nullptr;
  }
  json violations = json::array();
  for (const SpcViolation& v : c.violations)
    violations.push_back({{"rule", v.rule}, {"index", v.index}, {"last", v.last}, {"serial", v.serial}});
  j["violations"] = violations;
  j["notes"] = c.notes;
  return j;
}

}  // namespace

std::string spc_json(const SpcResult& result, const SpcSelection& selection) {
  json doc;
  doc["format"] = "furrow-spc";
  doc["version"] = 1;
  doc["units"] = "mm";
  doc["constants"] = {{"d2", kSpcD2}, {"D4", kSpcD4}, {"slope_confidence", kSpcSlopeConfidence}};
  json criteria = json::object();
  for (const auto& [option, value] : selection.criteria) criteria[option] = value;
  doc["selection"] = {{"source", selection.source}, {"criteria", criteria}};
  json parts = json::array();
  for (std::size_t i = 0; i < result.parts.size(); ++i) {
    const PartRecord& p = result.parts[i];
    parts.push_back({{"index", i},
                     {"serial", p.serial},
                     {"date", p.date},
                     {"verdict", p.verdict},
                     {"operator", p.operator_name},
                     {"cmm", p.cmm},
                     {"furrow_version", p.furrow_version ? json(*p.furrow_version) : json(nullptr)}});
  }
  doc["parts"] = parts;
  json characteristics = json::array();
  std::size_t violations = 0;
  for (const CharacteristicSpc& c : result.characteristics) {
    characteristics.push_back(characteristic_json(c));
    violations += c.violations.size();
  }
  doc["characteristics"] = characteristics;
  json worst = json::array();
  for (std::size_t i : worst_first(result)) worst.push_back(result.characteristics[i].id);
  doc["summary"] = {{"parts", result.parts.size()},
                    {"characteristics", result.characteristics.size()},
                    {"violations", violations},
                    {"violation_in_latest_part", violation_in_latest_part(result)},
                    {"worst_first", worst}};
  return jf::to_text(doc);
}

}  // namespace furrow
