#include "stage/plan_stage.hpp"

#include <cctype>

#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/plan_csv.hpp"
#include "io/plan_file.hpp"
#include "planning/coverage_image.hpp"
#include "planning/plan_image.hpp"
#include "planning/plan_report.hpp"

namespace furrow {

std::string cmm_program_name(const std::string& text, const std::string& fallback) {
  std::string name;
  for (unsigned char c : text) name += (std::isalnum(c) || c == '_' || c == '-') ? static_cast<char>(c) : '_';
  if (name.size() > 64) name.resize(64);
  return name.empty() ? fallback : name;
}

PlanStage plan_stage(const Part& part, const RegionMap& map, const PlannerOptions& options, const RiskMap* risk,
                     const std::string& program, const std::string& regions_name,
                     const std::string& prediction_name, const PlanProgress& progress) {
  PlanStage out;
  out.result = plan_probe_points(part, map, options, risk, progress);
  out.coverage = plan_coverage(out.result, options.min_per_region);
  for (const RegionCoverage& r : out.coverage.uncovered())
    out.result.plan.uncovered_regions.push_back(
        {r.region, static_cast<std::size_t>(r.face), r.planned, r.required, r.reason});
  // The alignment the programs measure first (docs/cmm.md "Part alignment").
  {
    const ClosestPointFinder finder(part);
    AccessOptions access = options.access;
    access.approach = out.result.approach;
    access.retract = out.result.retract;
    access.clearance_z = out.result.clearance_z;
    DatumOptions datum_options;
    datum_options.border = out.result.border;
    out.result.plan.alignment =
        choose_alignment(part, finder, out.result.probe, access, options.datums, datum_options);
  }
  // The vertical tip measures the alignment first: the tips in program order.
  out.result.plan.tips = tips_in_use(out.result, options);
  out.program = program;
  const ProbeProgram cmm = make_probe_program(out.result, program, options);
  out.plan_json = plan_to_json_text(out.result.plan);
  const std::vector<unsigned char> png = plan_image_png(part, map, out.result);
  const std::vector<unsigned char> coverage_png = coverage_image_png(part, map, out.result, out.coverage);
  out.files = {
      {"plan.json", out.plan_json},
      {"plan.csv", plan_to_csv_text(out.result.plan)},
      {program + ".dmi", dmis_program_text(cmm)},
      {program + ".prg", ippdme_program_text(cmm)},
      {"report.json", plan_report_json(out.result, out.coverage, options, options.part_name, regions_name, prediction_name)},
      {"plan.png", std::string(png.begin(), png.end())},
      {"coverage.png", std::string(coverage_png.begin(), coverage_png.end())},
  };
  return out;
}

}  // namespace furrow
