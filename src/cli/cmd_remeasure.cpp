// furrow remeasure COMPARISON.json --out FOLDER: a plan and CMM programs that
// probe what an INCONCLUSIVE verdict left open (stage/remeasure_plan.hpp).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "base/atomic_file.hpp"
#include "base/error.hpp"
#include "base/output_set.hpp"
#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "stage/plan_options.hpp"
#include "inspection/comparison_file.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/part_file.hpp"
#include "io/plan_csv.hpp"
#include "stage/plan_stage.hpp"
#include "stage/remeasure_plan.hpp"

namespace furrow::cli {

namespace {

// The plan options a re-measuring plan takes: the stylus, the moves and
// what the programs state (the probe itself defaults to the plan's).
OptionTable<PlannerOptions> remeasure_table() {
  std::vector<std::string> keys = kProbeMotionKeys;
  keys.insert(keys.end(), kProgramKeys.begin(), kProgramKeys.end());
  return only_options(plan_option_table(), keys);
}

std::string remeasure_options_help() { return option_help_lines(describe(remeasure_table())); }

int run_remeasure(Args& args) {
  const std::string out = args.required_option("out");
  const auto part_option = args.option("part");
  const auto plan_option = args.option("plan");
  RemeasureOptions o;
  o.radius = args.positive_or("radius", o.radius);
  o.ring_points = static_cast<int>(args.integer_or("ring", o.ring_points, 0));
  const auto probe_diameter = args.number("probe-diameter");
  PlannerOptions& p = o.planner;
  const auto probe_name = args.option("probe-name");
  if (probe_name) p.probe_name = *probe_name;
  read_option_flags(args, remeasure_table(), p);
  const std::string comparison_path = args.positional("COMPARISON (comparison.json of furrow compare)");
  args.finish();

  const ComparisonDocument doc = read_comparison(comparison_path);
  // The part and plan the comparison names, unless given (paths as they
  // were given to furrow compare, i.e. relative to where it ran).
  const std::string part_path = part_option.value_or(doc.sources.part);
  const std::string plan_path = plan_option.value_or(doc.sources.plan);
  OutputSet outputs;
  outputs.add_input(comparison_path, "comparison");
  outputs.add_input(part_path, "part");
  if (!plan_path.empty()) outputs.add_input(plan_path, "plan");
  outputs.will_write(out);

  const Part part = read_part(part_path);
  check_comparison_against_part(doc, part, comparison_path);
  std::optional<InspectionPlan> plan;
  if (!plan_path.empty()) {
    plan = read_plan(plan_path);
    check_plan_against_part(*plan, part, plan_path);
  }
  // The probe: as given, else the original plan's, else the comparison's.
  if (probe_diameter)
    p.probe_diameter = *probe_diameter;
  else if (plan)
    p.probe_diameter = plan->probe.diameter;
  else if (doc.options.probe_diameter > 0)
    p.probe_diameter = doc.options.probe_diameter;
  else
    args.fail("the probe diameter is unknown (contact points and no plan): give --probe-diameter");
  // The plan's tool name when it can be one (a free-text name cannot be a
  // DMIS label: the default then, as for furrow plan).
  auto label = [](const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
  };
  if (plan && !probe_name && label(plan->probe.name)) p.probe_name = plan->probe.name;
  try {
    validate(o);
  } catch (const InputError& e) {
    args.fail(e.what());
  }

  const RemeasurePlan r = naming_inputs(comparison_path + " with " + part_path, [&] {
    return plan_remeasure(part, doc, plan ? &*plan : nullptr, o);
  });
  std::printf("%s: verdict %s, %zu open question%s\n", comparison_path.c_str(), to_string(doc.summary.verdict),
              doc.summary.inconclusive.size(), doc.summary.inconclusive.size() == 1 ? "" : "s");
  for (const RemeasureTarget& t : r.targets) {
    std::printf("  %s %s: %zu point%s", t.kind.c_str(), t.subject.c_str(), t.points.size(),
                t.points.size() == 1 ? "" : "s");
    for (const std::string& id : t.points) std::printf(" %s", id.c_str());
    std::printf("\n");
    for (const std::string& d : t.dropped) std::printf("    dropped %s\n", d.c_str());
  }
  for (const std::string& n : r.not_covered) std::printf("  not covered by re-measuring: %s\n", n.c_str());
  const InspectionPlan& planned = r.result.plan;
  if (planned.points.empty()) {
    // Nothing written: an empty plan is no program, and a folder of one
    // would look like work to do.
    std::printf("nothing to re-measure: no point is planned; %s not written\n", out.c_str());
    return kExitOk;
  }

  std::string base = std::filesystem::path(out).lexically_normal().filename().string();
  if (base.empty() || base == "." || base == "..")
    base = std::filesystem::path(out).lexically_normal().parent_path().filename().string();
  const std::string name = cmm_program_name(base, "furrow_remeasure");
  ProbeProgram program = make_probe_program(r.result, name, p);
  // The first program aligned the part with datums and saved that frame:
  // this one runs on the same set-up.
  if (plan && plan->alignment && plan->alignment->method == PartAlignment::Method::datums)
    program.recalled_alignment = "PART";
  const std::string staging = outputs.folder(out);
  write_file_atomically(staging + "/plan.json", plan_to_json_text(planned));
  write_file_atomically(staging + "/plan.csv", plan_to_csv_text(planned));
  write_file_atomically(staging + "/" + name + ".dmi", dmis_program_text(program));
  write_file_atomically(staging + "/" + name + ".prg", ippdme_program_text(program));
  outputs.publish();
  std::printf("re-measure plan: %zu points, cycle time estimate %.1f min\n", planned.points.size(),
              r.result.cycle.seconds / 60);
  std::printf("wrote %s/{plan.json, plan.csv, %s.dmi, %s.prg}\n", out.c_str(), name.c_str(), name.c_str());
  return kExitOk;
}

}  // namespace

const Command kRemeasureCommand = {
    "remeasure", "a plan and CMM programs that probe what an INCONCLUSIVE verdict left open",
    "usage: furrow remeasure COMPARISON.json --out FOLDER [--part PART] [--plan PLAN]\n"
    "                        [--radius MM] [--ring N] [--probe-diameter MM] [--probe-name NAME]\n"
    "                        [probe, move and program options]\n"
    "\n"
    "Reads the reasons of an INCONCLUSIVE comparison (furrow compare) and plans\n"
    "the points that answer them, in the part frame of the original plan:\n"
    "  a suspected blunder P: P's nominal again (same id, so the new result\n"
    "    replaces it) and N neighbours P_R1.. on a circle of MM around it,\n"
    "    projected onto the part;\n"
    "  a predicted gouge site S not measured: its centre S_C and N points S_R1..\n"
    "    inside its predicted extent;\n"
    "  a region below its minimum: the plan's points there that were not\n"
    "    evaluated (needs the plan).\n"
    "Writes FOLDER with plan.json, plan.csv, NAME.dmi (DMIS) and NAME.prg (I++\n"
    "DME), NAME being the folder's name. Measure them on the same alignment, then\n"
    "furrow compare PART --measurements FIRST --measurements AGAIN ...: files are\n"
    "merged by id, the later one wins (docs/verification.md \"Re-measuring\").\n"
    "When nothing is left to measure (PASS, FAIL, or reasons about the alignment\n"
    "only) it says so, writes nothing and exits 0.\n"
    "\n"
    "  --out FOLDER         output folder, replaced as a whole (required)\n"
    "  --part PART          the part (default: the one the comparison names)\n"
    "  --plan PLAN          the original plan (default: the one the comparison\n"
    "                       names, if any): nominals and regions of its points\n"
    "  --radius MM          ring radius around a suspect point (default 1.5)\n"
    "  --ring N             neighbours per suspect point and per site (default 6)\n"
    "  --probe-diameter MM  ball diameter (default: the plan's, else the\n"
    "                       comparison's)\n"
    "  --probe-name NAME    tool / sensor name (default: the plan's)\n"
    "\n"
    "Probe, move and program options, as for furrow plan (docs/options.md):\n",
    run_remeasure, remeasure_options_help};

}  // namespace furrow::cli
