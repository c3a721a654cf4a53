// furrow simulate-measurement PART --plan plan.json: realistic CMM data for
// tests and demos (probe centres, noise, misalignment, blunders).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "stage/scan_simulate_stage.hpp"
#include "stage/scan_simulation_options.hpp"
#include "stage/simulation_options.hpp"
#include "inspection/measurement_simulation.hpp"
#include "inspection/prediction_comparison.hpp"
#include "base/output_set.hpp"
#include "base/error.hpp"
#include "base/text_fields.hpp"
#include "io/cmm/measurement_qif.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/prediction_file.hpp"

namespace furrow::cli {

namespace {

// --bump X,Y,Z,R,H, repeated.
std::vector<SurfaceBump> bumps_of(Args& args, const std::vector<std::string>& texts) {
  std::vector<SurfaceBump> bumps;
  for (const std::string& text : texts) {
    const std::vector<double> b = parse_number_list(text, 5, "bump");
    if (!(b[3] > 0)) args.fail("--bump \"" + text + "\": the radius must be positive");
    bumps.push_back({{b[0], b[1], b[2]}, b[3], b[4]});
  }
  return bumps;
}

// --scan: a scanner's point cloud of PART as a PLY (docs/scan_simulation.md).
int run_simulate_scan(Args& args) {
  const std::string out = args.required_option("out");
  SimulationOptions common;
  read_option_flags(args, simulation_option_table(), common);
  ScanSimulationOptions o;
  read_option_flags(args, scan_simulation_option_table(), o);
  const std::vector<std::string> bump_texts = args.repeated_option("bump");
  const bool plan_given = args.option("plan").has_value(), prediction_given = args.option("prediction").has_value();
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  if (plan_given) args.fail("--plan: a scan follows no plan (it takes every point the scanner sees)");
  if (prediction_given) args.fail("--prediction: not taken with --scan (plant bumps with --bump)");
  const SimulationOptions probe_defaults;
  if (common.noise_sigma != probe_defaults.noise_sigma)
    args.fail("--noise is the probing noise; a scan's noise along the line of sight is --scan-noise");
  if (common.blunders != 0 || common.anonymous || common.kind != probe_defaults.kind)
    args.fail("--blunders, --points and --anonymous are for probe points; a scan's blunders are --spray");
  const std::string extension = std::filesystem::path(out).extension().string();
  if (to_lower(extension) != ".ply") args.fail("--out " + out + ": a scan is written as PLY (.ply)");
  o.scanner.part_to_scanner = common.misalignment;
  o.scanner.seed = common.seed;
  o.scanner.bumps = bumps_of(args, bump_texts);

  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.will_write(out);
  const Part part = read_part(part_path);
  const SimulatedScanFile simulated =
      simulate_scan_stage(part, o, std::filesystem::path(part_path).filename().string());
  const SimulatedScan& scan = simulated.scan;
  outputs.file(out, simulated.ply);
  outputs.publish();
  const ScanRayCounts& c = scan.counts;
  std::printf("%zu points (%zu spray) of %zu rays: %zu missed the part, %zu grazing, %zu from behind, %zu not "
              "solved; noise %g mm along the line of sight, seed %u -> %s\n",
              c.points, c.spray, c.rays, c.missed, c.grazing, c.from_behind, c.not_solved, o.scanner.noise_sigma,
              o.scanner.seed, out.c_str());
  return kExitOk;
}

int run_simulate(Args& args) {
  if (args.flag("scan")) return run_simulate_scan(args);
  const std::string plan_path = args.required_option("plan");
  const std::string out = args.required_option("out");
  SimulationOptions o;
  read_option_flags(args, simulation_option_table(), o);
  const auto prediction_path = args.option("prediction");
  const std::vector<std::string> bumps = args.repeated_option("bump");
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  o.bumps = bumps_of(args, bumps);

  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(plan_path, "plan");
  if (prediction_path) outputs.add_input(*prediction_path, "prediction");
  outputs.will_write(out);
  // The format its extension names, refused before any work when unknown
  // (after the check that the output is no input, which says more).
  MeasurementFormat format = MeasurementFormat::csv;
  try {
    format = measurement_output_format(out);
  } catch (const InputError& e) {
    args.fail(std::string("--out ") + e.what());
  }
  const Part part = read_part(part_path);
  const InspectionPlan plan = read_plan(plan_path);
  check_plan_against_part(plan, part, plan_path);
  PredictedSurfaceOffsets machined;
  if (prediction_path) {
    const Prediction prediction = read_prediction(*prediction_path);
    check_prediction_against_part(prediction, part, *prediction_path, part_path);
    machined = predicted_surface_offsets(plan, prediction);
    o.surface_offset = machined.lookup(plan);
  }
  SimulatedMeasurement sim = simulate_measurement(plan, o, plan_path);
  // DMIS results carry the nominal F(label) of each point, as a CMM running
  // the plan's DMIS program writes them; a scan (--anonymous) has none.
  if (!o.anonymous) {
    const auto index = plan.index_by_id();
    for (std::size_t k = 0; k < sim.set.points.size(); ++k) {
      const PlannedPoint& p = plan.points[index.at(sim.plan_ids[k])];
      sim.set.points[k].nominal = p.xyz;
      sim.set.points[k].nominal_ijk = p.ijk;
    }
  }
  outputs.file(out, format == MeasurementFormat::qif ? measurements_to_qif(sim.set, &plan, part_path)
                                                    : measurements_text(sim.set, format));
  outputs.publish();
  std::printf("%zu points (%s, probe %g mm), %d blunders, noise %g mm, seed %u -> %s\n",
              sim.set.points.size(), to_string(sim.set.kind), plan.probe.diameter, o.blunders,
              o.noise_sigma, o.seed, out.c_str());
  if (prediction_path)
    std::printf("machined surface from %s: %zu points where the tool reached, %zu not reached "
                "(nominal there)\n",
                prediction_path->c_str(), machined.reached, machined.not_reached);
  for (std::size_t k = 0; k < o.bumps.size(); ++k) {
    const SurfaceBump& b = o.bumps[k];
    std::printf("bump: %+.4f mm within %g mm of (%g, %g, %g): %zu planned points\n", b.height,
                b.radius, b.centre.x(), b.centre.y(), b.centre.z(), sim.bump_points[k]);
  }
  return kExitOk;
}

std::string simulation_options_help() {
  return option_help_lines(describe(simulation_option_table())) +
         "\nScan options (with --scan; a scan takes --misalign, --seed and --bump too):\n" +
         option_help_lines(describe(scan_simulation_option_table()));
}

}  // namespace

const Command kSimulateMeasurementCommand = {
    "simulate-measurement", "realistic CMM points from a plan (a test and demo aid)",
    "usage: furrow simulate-measurement PART --plan plan.json --out FILE [options]\n"
    "       furrow simulate-measurement PART --scan --out FILE.ply [options]\n"
    "\n"
    "Writes what a CMM would report for the plan's points on PART: probe-ball\n"
    "centres (or contact points) with Gaussian probing noise along the normal,\n"
    "the part placed on the table with a misalignment, and a few blunders; the\n"
    "surface as machined when a prediction is given, with planted bumps. A\n"
    "test and demo aid for `furrow compare`; every random draw comes from --seed.\n"
    "With --scan, writes instead what a scanner looking along --view reports:\n"
    "the first surface each ray of its stripes meets, exactly on the part, with\n"
    "noise along the line of sight and spray, in the scanner's frame (--misalign),\n"
    "as a binary PLY (docs/scan_simulation.md).\n"
    "\n"
    "  --scan               simulate a scan instead of probe points\n"
    "  --plan FILE          plan.json (points, normals, probe)\n"
    "  --prediction FILE    prediction.json of PART: the machined surface is the\n"
    "                       nominal one plus the predicted error along the normal\n"
    "                       (nominal where the tool never reached; counted)\n"
    "  --bump X,Y,Z,R,H     add a smooth bump (H > 0, material left) or dent\n"
    "                       (H < 0) of height H mm, cosine profile within R mm of\n"
    "                       the part point (X,Y,Z); repeatable\n"
    "  --out FILE           measurements to write, in the format the extension names:\n"
    "                       .csv (CSV), .dmo/.dms/.out (DMIS output: F() nominals\n"
    "                       and FA() actuals), .res/.log (I++ DME response log),\n"
    "                       .qif (QIF 3.0 Results, docs/qif.md); numbers read back\n"
    "                       exactly (docs/formats.md)\n"
    "\n"
    "Simulation options (a job file's \"measurements\": {\"simulate\": ...} members,\n"
    "docs/options.md):\n",
    run_simulate, simulation_options_help};

}  // namespace furrow::cli
