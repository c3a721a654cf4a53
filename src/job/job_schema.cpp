#include "job/job_schema.hpp"

#include "base/json_fields.hpp"
#include "base/option_table.hpp"
#include "job/job.hpp"
#include "stage/compare_options.hpp"
#include "stage/compensate_options.hpp"
#include "stage/partition_options.hpp"
#include "stage/plan_options.hpp"
#include "stage/prediction_options.hpp"
#include "stage/scan_options.hpp"
#include "stage/scan_simulation_options.hpp"
#include "stage/simulation_options.hpp"
#include "stage/toolpath_options.hpp"

namespace furrow {

namespace {

using nlohmann::json;

json typed(const char* type, const char* description) { return {{"type", type}, {"description", description}}; }

json path(const char* description) { return {{"type", "string"}, {"minLength", 1}, {"description", description}}; }

json one_of(const std::vector<json>& choices) {
  json out = {{"oneOf", json::array()}};
  for (const json& c : choices) out["oneOf"].push_back(c);
  return out;
}

json object(json properties, std::initializer_list<const char*> required = {}) {
  json o = {{"type", "object"}, {"properties", std::move(properties)}, {"additionalProperties", false}};
  if (required.size()) o["required"] = json::array();
  for (const char* r : required) o["required"].push_back(r);
  return o;
}

json toolpath_schema() {
  const json generate = section_schema(describe(toolpath_option_table()));
  return one_of({path("a tool-path file (G-code, APT CL data or CSV)"),
                 object({{"file", path("the tool-path file")},
                         {"units", {{"enum", {"mm", "inch"}}}},
                         {"tools", path("the tool table of a program that changes tools")}},
                        {"file"}),
                 object({{"generate", generate}}, {"generate"})});
}

json tolerance_schema() {
  return one_of({{{"type", "number"}, {"exclusiveMinimum", 0}, {"description", "the zone's width in mm"}},
                 object({{"zone", {{"type", "number"}, {"exclusiveMinimum", 0}}},
                         {"outside", {{"type", "number"}, {"minimum", 0}}}},
                        {"zone"})});
}

json measurements_schema() {
  const json files = one_of({path("a measurement file"),
                             {{"type", "array"}, {"items", path("a measurement file")}, {"minItems", 1}}});
  const json columns = object({{"id", {{"type", "string"}}}, {"x", {{"type", "string"}}}, {"y", {{"type", "string"}}},
                               {"z", {{"type", "string"}}}, {"i", {{"type", "string"}}}, {"j", {{"type", "string"}}},
                               {"k", {{"type", "string"}}}, {"nx", {{"type", "string"}}},
                               {"ny", {{"type", "string"}}}, {"nz", {{"type", "string"}}}});
  const json read = object({{"file", files},
                            {"points", {{"type", {"string", "null"}}}},
                            {"probe_diameter", {{"type", {"number", "null"}}, {"exclusiveMinimum", 0}}},
                            {"units", {{"enum", {"mm", "inch"}}}},
                            {"delimiter", {{"type", {"string", "null"}}}},
                            {"decimal_comma", {{"type", {"boolean", "null"}}}},
                            {"columns", {{"anyOf", {columns, {{"type", "null"}}}}}},
                            {"dialect", {{"type", {"string", "null"}}}},
                            {"ipp_program", {{"type", {"string", "null"}}}}},
                           {"file"});
  const json bump = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 5}, {"maxItems", 5}};
  const json simulate = section_schema(
      describe(simulation_option_table()),
      {{"prediction", typed("boolean", "the machined surface is nominal + predicted error")},
       {"bumps", {{"type", "array"}, {"items", bump}, {"description", "[[x, y, z, radius, height], ...] in mm"}}}});
  std::vector<OptionDoc> scanner = describe(scan_simulation_option_table());
  for (OptionDoc& d : describe(scan_simulation_placement_table())) scanner.push_back(std::move(d));
  const json simulate_scan = section_schema(
      scanner, {{"bumps", {{"type", "array"}, {"items", bump}, {"description", "[[x, y, z, radius, height] in mm, ...]"}}}});
  json scan = section_schema(describe(scan_option_table()),
                             {{"file", path("the scan (PLY or PCD), compared as furrow compare --scan does")},
                              {"simulate", simulate_scan},
                              {"units", {{"enum", {"mm", "inch"}}}}});
  // A file, or a simulated scan the job writes as scan.ply: one of the two.
  scan["oneOf"] = json::array({{{"required", {"file"}}}, {{"required", {"simulate"}}}});
  // null, as absent: the job stops after the plan (what a run without measurements echoes).
  return one_of({files, read, object({{"simulate", simulate}}, {"simulate"}), object({{"scan", scan}}, {"scan"}),
                 {{"type", "null"}}});
}

json compensate_schema() {
  json c = section_schema(describe(compensate_option_table()),
                          {{"out", path("the compensated program's file name in the output folder (its record goes "
                                        "beside it as .json)")}});
  c["required"] = json::array({"out"});
  return c;
}

}  // namespace

std::string job_schema_json() {
  json properties = {
      {"version", {{"const", kJobFormatVersion}}},
      {"name", {{"type", "string"}, {"minLength", 1}}},
      {"description", typed("string", "free text, recorded in the report")},
      {"part", path("the part file (JSON, STEP, IGES)")},
      {"tool", path("the tool JSON")},
      {"toolpath", toolpath_schema()},
      {"tolerance", tolerance_schema()},
      {"partition", section_schema(describe(partition_option_table()))},
      {"prediction", section_schema(describe(prediction_option_table()),
                                    {{"map_scale", {{"type", "number"}, {"exclusiveMinimum", 0}}}})},
      {"plan", section_schema(describe(plan_option_table()),
                              {{"prediction", typed("boolean", "a risk-weighted plan from the prediction")},
                               {"allow_uncovered", typed("boolean", "an uncovered region does not fail the job")},
                               {"head", path("an indexable probe head file (docs/formats.md \"Probe head\")")}})},
      {"measurements", measurements_schema()},
      {"comparison", section_schema(describe(compare_option_table()),
                                    {{"prediction", typed("boolean", "predicted vs measured, gouge confirmation")},
                                     {"rps", path("the reference point system of \"align\": \"rps\"")}})},
      {"compensate", compensate_schema()},
      {"record", one_of({path("an inspection record file"), {{"type", "object"}}})},
      {"output", path("the output folder, replaced as a whole")},
      {"pdf", {{"type", "boolean"}}},
      {"paper", {{"enum", {"a4", "letter"}}}}};
  json schema = object(std::move(properties), {"part", "tool", "toolpath", "tolerance", "output"});
  schema["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  schema["$id"] = "https://furrow.example/docs/job.schema.json";
  schema["title"] = "Furrow job file (furrow run)";
  schema["description"] = "Written by `furrow help --job-schema` from the stages' option tables; docs/formats.md "
                          "\"Job file\" and docs/options.md describe the members.";
  return json_fields::to_text(schema);
}

}  // namespace furrow
