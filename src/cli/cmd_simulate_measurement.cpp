// furrow simulate-measurement PART --plan plan.json: realistic CMM data for
// tests and demos (probe centres, noise, misalignment, blunders).
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
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

int run_simulate(Args& args) {
  const std::string plan_path = args.required_option("plan");
  const std::string out = args.required_option("out");
  SimulationOptions o;
  read_option_flags(args, simulation_option_table(), o);
  const auto prediction_path = args.option("prediction");
  const std::vector<std::string> bumps = args.repeated_option("bump");
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();

  for (const std::string& text : bumps) {
    const std::vector<double> b = parse_number_list(text, 5, "bump");
    if (!(b[3] > 0)) args.fail("--bump \"" + text + "\": the radius must be positive");
    o.bumps.push_back({{b[0], b[1], b[2]}, b[3], b[4]});
  }

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

std::string simulation_options_help() { return option_help_lines(describe(simulation_option_table())); }

}  // namespace

const Command kSimulateMeasurementCommand = {
    "simulate-measurement", "realistic CMM points from a plan (a test and demo aid)",
    "usage: furrow simulate-measurement PART --plan plan.json --out FILE [options]\n"
    "\n"
    "Writes what a CMM would report for the plan's points on PART: probe-ball\n"
    "centres (or contact points) with Gaussian probing noise along the normal,\n"
    "the part placed on the table with a misalignment, and a few blunders; the\n"
    "surface as machined when a prediction is given, with planted bumps. A\n"
    "test and demo aid for `furrow compare`; every random draw comes from --seed.\n"
    "\n"
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
