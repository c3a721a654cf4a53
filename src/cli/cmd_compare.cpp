// furrow compare PART --measurements M: register CMM points to the part,
// deviations against a profile tolerance, comparison.json.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "cli/results_storage.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_merge.hpp"
#include "inspection/setup_merge.hpp"
#include "base/output_set.hpp"
#include "io/cmm/csv_dialect.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "partition/regions_file.hpp"
#include "report/qa_report.hpp"
#include "report/report_qif.hpp"
#include "stage/compare_options.hpp"
#include "stage/compare_stage.hpp"
#include "io/scan/scan_read.hpp"
#include "inspection/scan_comparison_file.hpp"
#include "inspection/scan_deviation_cloud.hpp"
#include "stage/scan_compare_stage.hpp"
#include "stage/scan_options.hpp"

namespace furrow::cli {

namespace {

// furrow compare PART --scan FILE: a dense scan instead of probe points
// (docs/scan.md). The probe-point options that have no meaning for a cloud
// are refused by name rather than ignored.
int run_compare_scan(Args& args, const std::string& scan_path) {
  for (const char* other : {"measurements", "plan", "qif", "rps", "points", "probe-diameter",
                            "dialect", "delimiter", "columns", "ipp-program"})
    if (args.option(other)) args.fail(std::string("--") + other + " does not apply to --scan");
  if (args.flag("decimal-comma")) args.fail("--decimal-comma does not apply to --scan");
  const auto regions_path = args.option("regions");
  const auto prediction_path = args.option("prediction");
  const auto deviations_path = args.option("deviations");
  const std::string out = args.required_option("out");
  const double tolerance = args.positive_or("tolerance", 0.05);
  const auto outside = args.number("outside");
  const std::string units = args.option_or("units", "mm");
  CompareOptions options;
  read_option_flags(args, compare_option_table(), options);
  ScanPreprocessOptions preprocessing;
  read_option_flags(args, scan_option_table(), preprocessing);
  const ResultsStorageOptions storage = read_results_storage(args);
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  // Before any work: a database that is not Furrow's stops the command here.
  const std::unique_ptr<ResultsDatabase> db = open_results_storage(args, storage, !storage.serial.empty());
  if (options.align != AlignMethod::bestfit) args.fail("--scan is registered by a best fit (--align bestfit)");
  const double mm_per_unit = units_to_mm(units, "--units");
  options.tolerance = ToleranceZone::make(tolerance, outside.value_or(tolerance / 2), "--tolerance/--outside");
  scale_registration_to_tolerance(options);
  if (isatty(STDERR_FILENO))
    options.registration.progress = [](const std::string& what) {
      std::fprintf(stderr, "\rcompare: %-24s", what.c_str());
    };

  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(scan_path, "scan");
  if (regions_path) outputs.add_input(*regions_path, "regions");
  if (prediction_path) outputs.add_input(*prediction_path, "prediction");
  outputs.will_write(out);
  if (deviations_path) outputs.will_write(*deviations_path);

  const Part part = read_part(part_path);
  std::optional<RegionMap> regions;
  if (regions_path) {
    regions = read_regions(*regions_path);
    regions->check_belongs_to(part, *regions_path, part_path);
  }
  std::optional<Prediction> prediction;
  if (prediction_path) {
    prediction = read_prediction(*prediction_path);
    check_prediction_against_part(*prediction, part, *prediction_path, part_path);
  }
  const ScanCloud cloud = read_scan(scan_path, mm_per_unit);
  const ScanComparison c = naming_inputs(part_path + " with " + scan_path, [&] {
    return compare_scan_stage(part, cloud, regions ? &*regions : nullptr, prediction ? &*prediction : nullptr,
                              options, preprocessing);
  });
  if (options.registration.progress) std::fprintf(stderr, "\r%-34s\r", "");
  ScanComparisonSources sources;
  sources.part = part_path;
  sources.scan = scan_path;
  sources.regions = regions_path.value_or("");
  sources.deviations = deviations_path.value_or("");
  sources.prediction = prediction_path.value_or("");
  sources.units = units;
  if (deviations_path) outputs.file(*deviations_path, scan_deviation_ply(c, cloud));
  outputs.file(out, scan_comparison_json(c, sources));
  outputs.publish(out);
  if (db) store_comparison_file(*db, out, record_context(storage.serial, std::nullopt), std::cout);

  const ComparisonSummary& s = c.summary;
  const RegistrationResult& r = c.registration;
  std::printf("scan: %zu points read (%s, %s), %zu not finite; %zu spray far, %zu spray near, %zu off the part; "
              "%zu compared\n",
              c.read, cloud.format.c_str(), cloud.coordinate_type.c_str(), c.not_finite, c.pre.spray_far,
              c.pre.spray_near, c.off_part, c.evaluated);
  if (c.pre.view == ScanViewKind::none)
    std::printf("line of sight: none (no --viewpoint, --view-direction or PCD VIEWPOINT): no grazing rejection, "
                "the fit not weighted by incidence\n");
  else
    std::printf("line of sight: %s (%g, %g, %g), %s: %zu grazing beyond %g deg, %zu without a normal; "
                "fit weights %s\n",
                to_string(c.pre.view), c.pre.view_vector.x(), c.pre.view_vector.y(), c.pre.view_vector.z(),
                c.pre.view_source == "file" ? "the file's VIEWPOINT" : "given", c.grazing, preprocessing.max_incidence_deg,
                c.pre.no_normal, c.pre.fit_weights.empty() ? "none" : "cos(incidence)");
  std::printf("registration: %s (%s start), %zu voxel points (%g mm), rms %.4f -> %.4f mm, %zu in the fit\n",
              r.status.c_str(), to_string(r.coarse.method), c.pre.fit.size(), preprocessing.voxel, r.rms_before,
              r.rms_after, r.in_fit_count());
  std::printf("deviation: min %.4f  max %.4f  mean %.4f  sigma %.4f mm; profile %.4f mm\n", s.deviations.min,
              s.deviations.max, s.deviations.mean, s.deviations.sigma, s.profile);
  std::printf("tolerance %.4f mm [%.4f, %.4f]: %zu in, %zu out\n", c.tolerance.width, c.tolerance.lower(),
              c.tolerance.upper(), s.in_tolerance, s.out_of_tolerance);
  if (c.verification) {
    const ResidualStatistics& o = c.verification->compared.overall;
    std::printf("prediction: %zu points compared, residual rms %.4f mm, normalised rms %.2f, "
                "%.1f %% within %g sigma -> %s\n",
                o.count, o.rms, o.normalised_rms, 100 * o.within_share, options.prediction.within_sigmas,
                to_string(o.verdict));
    std::size_t by_status[3] = {0, 0, 0};
    for (const ScanGougeSite& site : c.verification->sites) ++by_status[static_cast<int>(site.check.status)];
    std::printf("gouge sites: %zu confirmed, %zu not confirmed, %zu not measured\n", by_status[0], by_status[1],
                by_status[2]);
    // The sites that decide the verdict, the first ten (all in comparison.json).
    std::size_t listed = 0, more = 0;
    for (const ScanGougeSite& site : c.verification->sites) {
      const GougeSiteCheck& g = site.check;
      if (g.status == GougeSiteStatus::not_confirmed) continue;
      if (++listed > 10) {
        ++more;
        continue;
      }
      std::printf("  %s %s:", g.id.c_str(), to_string(g.status));
      if (g.measured_depth) std::printf(" read %.4f mm deep over %zu points;", *g.measured_depth, site.read_points);
      if (g.predicted_depth) std::printf(" predicted %.4f mm", *g.predicted_depth);
      std::printf("\n");
    }
    if (more) std::printf("  ... and %zu more\n", more);
  }
  std::printf("%s\n", to_string(s.verdict));
  for (const InconclusiveReason& why : s.inconclusive) std::printf("  %s\n", why.text.c_str());
  return exit_status(s.verdict, s.alignment);
}

int run_compare(Args& args) {
  if (const auto scan = args.option("scan")) return run_compare_scan(args, *scan);
  if (args.option("deviations")) args.fail("--deviations is the deviation cloud of --scan");
  // Several files: merged by id in the order given (measurement_merge.hpp).
  const std::vector<std::string> measurement_files = args.repeated_option("measurements");
  if (measurement_files.empty()) args.fail("--measurements or --scan is required");
  // Several plans: one per setup, the measurement files in the same order
  // (inspection/setup_merge.hpp).
  const std::vector<std::string> plan_paths = args.repeated_option("plan");
  const std::optional<std::string> plan_path =
      plan_paths.empty() ? std::nullopt : std::optional<std::string>(plan_paths.front());
  const auto regions_path = args.option("regions");
  const auto prediction_path = args.option("prediction");
  const std::string out = args.required_option("out");
  const auto qif_path = args.option("qif");  // QIF 3.0 Results next to comparison.json (docs/qif.md)
  const auto rps_path = args.option("rps");  // the reference point system of --align rps
  const double tolerance = args.positive_or("tolerance", 0.05);
  const auto outside = args.number("outside");
  const auto points = args.option("points");
  const auto probe_diameter = args.number("probe-diameter");
  const auto units_option = args.option("units");
  const auto dialect_path = args.option("dialect");
  const auto delimiter = args.option("delimiter");
  const bool decimal_comma = args.flag("decimal-comma");
  const auto columns = args.option("columns");
  const auto ipp_program = args.option("ipp-program");
  CompareOptions options;
  read_option_flags(args, compare_option_table(), options);
  const ResultsStorageOptions storage = read_results_storage(args);
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  // Before any work: a database that is not Furrow's stops the command here.
  const std::unique_ptr<ResultsDatabase> db = open_results_storage(args, storage, !storage.serial.empty());

  options.tolerance =
      ToleranceZone::make(tolerance, outside.value_or(tolerance / 2), "--tolerance/--outside");
  scale_registration_to_tolerance(options);
  if (isatty(STDERR_FILENO))
    options.registration.progress = [](const std::string& what) {
      std::fprintf(stderr, "\rcompare: %-24s", what.c_str());
    };

  // The CSV dialect, checked before any file is read: a saved one, with the
  // options given on top (docs/formats.md "Measurements").
  MeasurementReadOptions read;
  CsvDialect dialect = dialect_path ? read_csv_dialect(*dialect_path) : CsvDialect{};
  if (units_option && dialect.units && *dialect.units != *units_option)
    args.fail("--units " + *units_option + " contradicts the units \"" + *dialect.units + "\" of " + *dialect_path);
  read.dialect = merge_csv_dialect(
      dialect, delimiter ? std::optional<char>(parse_csv_delimiter(*delimiter, "--delimiter")) : std::nullopt,
      decimal_comma ? std::optional<bool>(true) : std::nullopt,
      columns ? parse_csv_columns(*columns, "--columns") : std::map<std::string, std::string>{}, "--decimal-comma");
  read.units = units_option.value_or(dialect.units.value_or("mm"));
  units_to_mm(read.units, "--units");
  if (ipp_program) read.ippdme_program = *ipp_program;
  if (plan_paths.size() > 1 && plan_paths.size() != measurement_files.size())
    args.fail(std::to_string(plan_paths.size()) + " plans (--plan) but " + std::to_string(measurement_files.size()) +
              " measurement files: with several setups give one plan per file, in the same order");
  if (plan_paths.size() > 1 && options.align != AlignMethod::bestfit)
    args.fail(std::string("--align ") + to_string(options.align) +
              ": the setups' points are fitted together best-fit; each setup's datums are in its own frame");
  if ((options.align == AlignMethod::rps) != rps_path.has_value())
    args.fail(rps_path ? "--rps is for --align rps" : "--align rps needs the reference point system (--rps FILE)");

  OutputSet outputs;
  outputs.add_input(part_path, "part");
  for (const std::string& m : measurement_files) outputs.add_input(m, "measurements");
  if (dialect_path) outputs.add_input(*dialect_path, "dialect");
  if (rps_path) outputs.add_input(*rps_path, "rps");
  if (ipp_program) outputs.add_input(*ipp_program, "I++ DME program");
  for (const std::string& p : plan_paths) outputs.add_input(p, "plan");
  if (regions_path) outputs.add_input(*regions_path, "regions");
  if (prediction_path) outputs.add_input(*prediction_path, "prediction");
  outputs.will_write(out);
  if (qif_path) outputs.will_write(*qif_path);

  if (rps_path) options.rps = read_reference_points(*rps_path);
  const Part part = read_part(part_path);
  std::optional<InspectionPlan> plan;
  std::vector<InspectionPlan> setup_plans;
  for (const std::string& p : plan_paths) {
    setup_plans.push_back(read_plan(p));
    check_plan_against_part(setup_plans.back(), part, p);
  }
  // A plan of a further setup, or several: one plan in the part frame.
  const bool setups = plan_paths.size() > 1 || (!setup_plans.empty() && setup_plans.front().setup &&
                                                setup_plans.front().setup->index > 1);
  if (setups)
    plan = merge_setup_plans(setup_plans, plan_paths);
  else if (!setup_plans.empty())
    plan = setup_plans.front();
  std::optional<RegionMap> regions;
  if (regions_path) {
    regions = read_regions(*regions_path);
    regions->check_belongs_to(part, *regions_path, part_path);
  }
  std::optional<Prediction> prediction;
  if (prediction_path) {
    prediction = read_prediction(*prediction_path);
    check_prediction_against_part(*prediction, part, *prediction_path, part_path);
  }
  if (points) read.kind = parse_probe_point_kind(*points, "--points");
  read.probe_diameter = probe_diameter ? *probe_diameter : plan ? plan->probe.diameter : 0.0;
  std::vector<MeasurementSet> sets;
  for (std::size_t k = 0; k < measurement_files.size(); ++k) {
    sets.push_back(read_measurements(measurement_files[k], read));
    // Measured in setup k's frame (its program's alignment): to the part frame.
    if (setups) {
      const InspectionPlan& own = setup_plans[plan_paths.size() > 1 ? k : 0];
      sets.back() = measurements_in_part_frame(std::move(sets.back()), own.setup);
    }
  }
  MergedMeasurements merged = merge_measurements(sets);
  if (measurement_files.size() > 1)  // recorded with several files only (comparison_file.hpp)
    for (const std::string& m : measurement_files) merged.sha256.push_back(digest_file("measurements", m).sha256);
  // With datums, the datum points set the frame and the rest are compared.
  MeasurementSet set;
  try {
    set = prepare_alignment(options, merged.set, plan ? &*plan : nullptr, plan_path.value_or(""));
  } catch (const DatumFrameError& e) {  // degenerate datum data: the computation did not succeed
    std::fprintf(stderr, "error: no datum frame: %s\n", e.what());
    return kExitInternal;
  }
  restrict_to(merged, set);
  const std::string measurements = set.source;

  const Comparison c = naming_inputs(part_path + " with " + measurements, [&] {
    return compare_stage(part, set, plan ? &*plan : nullptr, regions ? &*regions : nullptr,
                         prediction ? &*prediction : nullptr, options);
  });
  if (options.registration.progress) std::fprintf(stderr, "\r%-34s\r", "");
  ComparisonSources sources;
  sources.part = part_path;
  sources.measurements = measurements;
  for (const std::string& p : plan_paths) sources.plan += (sources.plan.empty() ? "" : " + ") + p;
  sources.regions = regions_path.value_or("");
  sources.prediction = prediction_path.value_or("");
  sources.measurement_units = read.units;
  sources.merged = &merged;
  std::string json = comparison_to_json_text(c, set, part, options, sources);
  if (qif_path) {  // from comparison.json's own content, so the two files say the same
    std::vector<InputDigest> inputs = {digest_file("part", part_path)};
    for (const std::string& m : measurement_files) inputs.push_back(digest_file("measurements", m));
    for (const std::string& p : plan_paths) inputs.push_back(digest_file("plan", p));
    if (regions_path) inputs.push_back(digest_file("regions", *regions_path));
    if (prediction_path) inputs.push_back(digest_file("prediction", *prediction_path));
    outputs.file(*qif_path, comparison_to_qif(parse_comparison(json, out), inputs, std::nullopt));
  }
  outputs.file(out, json);
  outputs.publish(out);
  if (db) {
    store_comparison_file(*db, out, record_context(storage.serial, std::nullopt), std::cout);
  }

  const ComparisonSummary& s = c.summary;
  const RegistrationResult& r = c.registration;
  std::printf("alignment: %s\n", to_string(c.align));
  if (c.datum_frame)
    for (const DatumFit& d : c.datum_frame->datums) {
      std::printf("datum %s (%s, %zu point%s): ", d.label.c_str(), to_string(d.kind), d.point_ids.size(),
                  d.point_ids.size() == 1 ? "" : "s");
      if (d.kind == DatumFeature::Kind::point)
        std::printf("sets the last origin\n");
      else
        std::printf("%s %.4f mm\n",
                    d.kind == DatumFeature::Kind::plane      ? "flatness"
                    : d.kind == DatumFeature::Kind::cylinder ? "roundness"
                                                             : "straightness",
                    d.form_error);
    }
  if (c.datum_frame)
    for (const ReferencePointFit& f : c.datum_frame->reference_points)
      std::printf("rps %s (fixes %s): largest residual %.4f mm\n", f.id.c_str(), f.directions.c_str(),
                  f.residual.cwiseAbs().maxCoeff());
  std::printf("registration: %s (%s start), rms %.4f -> %.4f mm, %zu of %zu points in the fit\n",
              r.status.c_str(), to_string(r.coarse.method), r.rms_before, r.rms_after, s.in_fit,
              s.points);
  for (const WeakDirection& w : r.observability.weak) {
    const double sd = w.sigma_mm(r.sigma);
    std::printf("weakly constrained: %s (%s", w.describe().c_str(), w.held ? "held at the start" : "fitted");
    if (std::isfinite(sd)) std::printf(", 1 sigma %.4f mm", sd);
    std::printf(")%s\n", w.from_points ? ": the measured faces would fix it, the points do not" : "");
  }
  std::printf("deviation: min %.4f  max %.4f  mean %.4f  sigma %.4f mm; profile %.4f mm\n",
              s.deviations.min, s.deviations.max, s.deviations.mean, s.deviations.sigma, s.profile);
  if (c.bestfit_profile)
    std::printf("profile: %s frame %.4f mm (form + location), best fit %.4f mm (form)\n", to_string(c.align),
                s.profile, *c.bestfit_profile);
  std::printf("tolerance %.4f mm [%.4f, %.4f]: %zu in, %zu out, %zu outliers\n",
              c.tolerance.width, c.tolerance.lower(), c.tolerance.upper(), s.in_tolerance,
              s.out_of_tolerance, s.outliers);
  if (c.prediction) {
    const ResidualStatistics& o = c.prediction->overall;
    std::printf("prediction: %zu points compared, residual rms %.4f mm, normalised rms %.2f, "
                "%.1f %% within %g sigma -> %s\n",
                o.count, o.rms, o.normalised_rms, 100 * o.within_share, options.prediction.within_sigmas,
                to_string(o.verdict));
    std::size_t by_status[3] = {0, 0, 0};
    for (const GougeSiteCheck& site : c.gouges->sites) ++by_status[static_cast<int>(site.status)];
    std::printf("gouge sites: %zu confirmed, %zu not confirmed, %zu not measured; %zu unexplained overcuts\n",
                by_status[0], by_status[1], by_status[2], s.unexplained_overcuts);
  }
  for (const MeasurementReplacement& m : merged.replaced)
    std::printf("re-measured: %s from %s replaces %s\n", m.id.c_str(), merged.files[m.by_file].c_str(),
                merged.files[m.file].c_str());
  std::printf("%s\n", to_string(s.verdict));
  for (const InconclusiveReason& r : s.inconclusive) std::printf("  %s\n", r.text.c_str());
  return exit_status(s.verdict, s.alignment);
}

std::string compare_options_help() {
  return option_help_lines(describe(compare_option_table())) +
         "\nScan pre-processing (--scan only; docs/scan.md):\n" + option_help_lines(describe(scan_option_table())) +
         "\nResults database (docs/results_database.md, docs/options.md), after comparison.json is\n"
         "written; the same comparison again is not stored twice:\n" +
         option_help_lines(describe(results_storage_option_table()));
}

}  // namespace

const Command kCompareCommand = {
    "compare", "register CMM points to the part, deviations against a profile tolerance",
    "usage: furrow compare PART --measurements FILE --out comparison.json [options]\n"
    "       furrow compare PART --scan CLOUD.ply --out comparison.json [--deviations OUT.ply]\n"
    "                      [--regions REGIONS.json] [--prediction PREDICTION.json] [options]\n"
    "\n"
    "Registers measured points (CSV, XYZ text, DMIS results or an I++ DME\n"
    "response log; docs/formats.md \"Measurements\")\n"
    "to PART by a robust best fit with probe compensation, computes each point's\n"
    "signed deviation along the nominal normal (+ material left, - removed) and\n"
    "checks it against a surface profile tolerance. Writes comparison.json. Exit\n"
    "status: 0 PASS (every evaluated point in tolerance, no predicted gouge\n"
    "confirmed, nothing left unseen), 1 FAIL, 4 INCONCLUSIVE (nothing failed, but\n"
    "a suspected blunder lies outside the zone, a predicted gouge was not\n"
    "measured, a plan region has fewer evaluated points than its minimum, a\n"
    "point the best fit follows instead of checking it, or the points do not\n"
    "determine the alignment: the reasons say what to\n"
    "measure again, furrow remeasure plans it; docs/verification.md \"Verdict\").\n"
    "\n"
    "  --measurements FILE  measured points: .csv, .xyz/.txt, DMIS output\n"
    "                       (.dmo/.dms/.out/.dmi/.dmis/.res), I++ DME response log\n"
    "                       (.log/.ipp, or .res starting with a response line),\n"
    "                       QIF 3.0 Results (.qif);\n"
    "                       repeat it for a re-measure: files are merged by id in\n"
    "                       the order given, a later point replaces an earlier one\n"
    "                       with the same id (each file must carry ids)\n"
    "  --plan FILE          plan.json: ids give the coarse start, its probe the diameter\n"
    "                       (repeated, one per --measurements file in the same order:\n"
    "                       the setups of furrow plan --setups, compared as one part)\n"
    "  --rps FILE           reference point system for --align rps (docs/formats.md\n"
    "                       \"RPS file\"): named points, each fixing the part along\n"
    "                       the axes it declares\n"
    "  --regions FILE       regions.json of PART (furrow partition): each point's\n"
    "                       region is the one holding its foot point; statistics\n"
    "                       per region (default: the plan points' regions)\n"
    "  --tolerance T        profile tolerance zone width in mm (default 0.05)\n"
    "  --outside A          part of the zone on the + side in mm (default T/2 =\n"
    "                       bilateral; T unilateral outside, 0 unilateral inside)\n"
    "  --points K           centre (default for CSV/XYZ) or contact (default for\n"
    "                       DMIS and I++ DME)\n"
    "  --probe-diameter D   ball diameter in mm (default: the plan's probe)\n"
    "  --units U            mm (default) or inch, for CSV and XYZ coordinates\n"
    "  --delimiter D        CSV field delimiter: , ; tab or whitespace (default:\n"
    "                       from the header line)\n"
    "  --decimal-comma      CSV numbers are written 1,5 (default: accepted when\n"
    "                       the delimiter is not ,)\n"
    "  --columns MAP        CSV header names of the fields, e.g.\n"
    "                       \"id=Name,x=X act,y=Y act,z=Z act\" (id x y z i j k and\n"
    "                       nominal nx ny nz; default: recognised by name)\n"
    "  --dialect FILE       a saved CSV dialect (JSON: delimiter, decimal_comma,\n"
    "                       columns, units); the options above override it\n"
    "  --ipp-program FILE   the .prg (any client's) an I++ DME session answers:\n"
    "                       its PtMeas targets become the points' nominals, a\n"
    "                       PtMeas without an answer a point not measured\n"
    "  --scan FILE          a dense scan instead (PLY or PCD, docs/scan.md): spray\n"
    "                       flagged, a voxel subset registered, every point's\n"
    "                       deviation by exact projection; not with --measurements,\n"
    "                       --plan or --qif; a database stores its regions\n"
    "  --deviations FILE    with --scan: every point in the part frame with its\n"
    "                       deviation and status, binary PLY (docs/formats.md)\n"
    "  --out FILE           comparison.json to write\n"
    "  --qif FILE           also write the results as a QIF 3.0 Results document\n"
    "                       (ISO 23952): points, surface profile, per-point\n"
    "                       status, verdict, inputs with SHA-256 (docs/qif.md)\n"
    "  --prediction FILE    prediction.json of PART (furrow predict): predicted vs\n"
    "                       measured and gouge confirmation (docs/verification.md);\n"
    "                       a CONFIRMED gouge fails the part (with --scan too:\n"
    "                       docs/scan.md \"With a prediction\")\n"
    "\n"
    "Comparison options (a job file's \"comparison\" members, docs/options.md); the\n"
    "last eight apply to the verification against a prediction:\n",
    run_compare, compare_options_help};

}  // namespace furrow::cli
