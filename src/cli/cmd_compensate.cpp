// furrow compensate PART --comparison C.json --toolpath PATH.nc --tool TOOL.json --out COMP.nc
#include <cstdio>
#include <iostream>
#include <optional>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "base/output_set.hpp"
#include "base/text_fields.hpp"
#include "cli/commands.hpp"
#include "cli/option_flags.hpp"
#include "inspection/comparison_file.hpp"
#include "io/machining/tool_file.hpp"
#include "io/machining/toolpath_file.hpp"
#include "io/part_file.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "machining/cutter/path_tools.hpp"
#include "stage/compensate_options.hpp"
#include "stage/compensate_stage.hpp"
#include "stage/prediction_options.hpp"

namespace furrow::cli {

namespace {

std::string um(double mm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f um", mm * 1000);
  return buf;
}

// COMP.json beside COMP.nc: the same name with .json.
std::string record_path(const std::string& program) {
  const auto dot = program.find_last_of('.');
  const auto slash = program.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? program.substr(0, dot) : program) + ".json";
}

int run_compensate(Args& args) {
  const std::string comparison_path = args.required_option("comparison");
  const std::string toolpath_path = args.required_option("toolpath");
  const std::optional<std::string> tool_path = args.option("tool");
  const std::optional<std::string> table_path = args.option("tools");
  const std::string out_path = args.required_option("out");
  const std::optional<std::string> prediction_path = args.option("prediction");
  const std::optional<std::string> predict_out = args.option("predict-out");
  CompensateOptions options;
  read_option_flags(args, compensate_option_table(), options);
  // The prediction of the compensated program takes furrow predict's
  // options, with its defaults, so that it is that command's file. Read
  // only with --predict-out: without it one of them is refused, naming it.
  PathPredictionOptions predict_options;
  if (predict_out) {
    read_option_flags(args, prediction_option_table(), predict_options);
  } else {
    for (const OptionDoc& doc : describe(prediction_option_table()))
      if (option_value(args, doc))
        args.fail(doc.flag + " is an option of the prediction of the compensated program: give --predict-out too");
  }
  if (!(predict_options.gouge_threshold > 0)) predict_options.gouge_threshold = 2 * predict_options.tolerance;
  ToolpathReadOptions read;
  read.units = args.option_or("units", "mm");
  const std::string part_path = args.positional("PART (a part file)");
  args.finish();
  if (!tool_path && !table_path)
    args.fail("--tool is required (or --tools, the tool table of a program that changes tools)");
  if (table_path && lower_extension(*table_path) != ".json")
    args.fail("--tools " + *table_path + ": expected a tool table (.json)");
  auto is_apt = [](const std::string& ext) { return ext == ".cl" || ext == ".apt" || ext == ".cls"; };
  const std::string ext = lower_extension(toolpath_path);
  if (ext == ".csv" || ext == ".txt")
    args.fail("--toolpath " + toolpath_path +
              ": compensate writes the program back; give the G-code program or the APT CL file, not a CSV path");
  const ProgramFormat format = is_apt(ext) ? ProgramFormat::apt : ProgramFormat::gcode;
  const std::string out_ext = lower_extension(out_path);
  if (out_ext == ".json")
    args.fail("--out " + out_path + ": expected a program file name (its record is written beside it as .json)");
  if (is_apt(out_ext) != (format == ProgramFormat::apt))
    args.fail("--out " + out_path + ": the compensated program is written in the format it was read in (" +
              (format == ProgramFormat::apt ? "APT CL: .apt, .cl or .cls" : "G-code: not .apt, .cl or .cls") + ")");
  if (lower_extension(comparison_path) != ".json")
    args.fail("--comparison " + comparison_path + ": expected a comparison (.json)");
  const std::string record = record_path(out_path);
  if (predict_out && lower_extension(*predict_out) != ".json")
    args.fail("--predict-out " + *predict_out + ": expected a prediction file name (.json)");
  if (predict_out && (*predict_out == record || *predict_out == out_path))
    args.fail("--predict-out " + *predict_out + ": is the compensated program or its record");
  OutputSet outputs;
  outputs.add_input(part_path, "part");
  outputs.add_input(comparison_path, "comparison");
  outputs.add_input(toolpath_path, "tool path");
  if (tool_path) outputs.add_input(*tool_path, "tool");
  std::optional<std::vector<ToolTableEntry>> table;
  if (table_path) {
    outputs.add_input(*table_path, "tool table");
    table = read_tool_table(*table_path);
    for (const ToolTableEntry& e : *table)
      if (!e.file.empty()) outputs.add_input(e.file, "tool");
  }
  if (prediction_path) outputs.add_input(*prediction_path, "prediction");
  outputs.will_write(out_path);
  outputs.will_write(record);
  if (predict_out) outputs.will_write(*predict_out);

  const Part part = read_part(part_path);
  const ComparisonDocument comparison = read_comparison(comparison_path);
  std::optional<Prediction> prediction;
  if (prediction_path) prediction = read_prediction(*prediction_path);
  const std::string program = json_fields::read_text(toolpath_path);
  const Toolpath path = read_toolpath(toolpath_path, read);
  std::optional<ToolSpec> tool;
  if (tool_path) tool = read_tool_file(*tool_path);
  // Each pass with the tool loaded when it is cut, as furrow predict --tools
  // reads them (machining/cutter/path_tools.hpp).
  const PathTools tools = tools_for_path(path, tool, tool_path.value_or(""), table, table_path.value_or(""));
  const CompensatedProgram done = naming_inputs(part_path + " with " + toolpath_path, [&] {
    return compensate_stage(part, tools, program, format, read, comparison, options,
                            {part_path, comparison_path, toolpath_path, out_path, prediction_path.value_or("")},
                            prediction ? &*prediction : nullptr);
  });
  std::size_t fitted = 0;
  for (const auto& face : done.field.field.faces) fitted += face && face->fitted();
  std::cout << "error field: " << done.field.samples << " points"
            << (done.field.prediction_given     ? " (the prediction given removed)"
                : done.field.prediction_removed ? " (prediction removed)"
                                                : " (no prediction: deviations fitted as they are)")
            << ", " << fitted << " of " << part.faces.size() << " faces fitted\n";
  std::cout << "moved " << done.offset.moved << " tips, largest offset " << um(done.offset.largest_offset) << "; "
            << done.offset.clipped.size() << " clipped at " << um(options.max_offset) << ", "
            << done.offset.gouge_clipped.size() << " cut back to avoid a local gouge\n";
  if (done.clip_back_rounds > 0)
    std::cout << "z-map check: " << done.clip_back.size() << " tips clipped back in " << done.clip_back_rounds
              << " round" << (done.clip_back_rounds == 1 ? "" : "s") << " (of at most " << options.clip_back << ")\n";
  std::cout << "program: " << done.program.lines_moved << " lines moved (" << done.program.words_rewritten
            << " words rewritten, " << done.program.words_added << " added, " << done.program.arcs_split
            << " arcs split into lines)\n";
  if (done.expected.overall.count > 0) {
    const ExpectedStatistics& e = done.expected.overall;
    std::cout << "expected at the " << e.count << " measured points: RMS " << um(e.rms_before) << " measured, "
              << um(e.rms_after) << " after compensation (worst " << e.worst_after_id << ", " << um(e.worst_after)
              << ")\n";
  }
  const CompensationGougeCheck& check = done.check;
  if (!check.safe()) {
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "furrow compensate: nothing written: after %d clip-back round%s the compensated program would "
                  "still cut %.4f mm deeper than its offset allows at (%.3f, %.3f, %.3f), line %d (%zu z-map nodes "
                  "at %.3f mm)\n",
                  done.clip_back_rounds, done.clip_back_rounds == 1 ? "" : "s", check.worst_excess, check.worst.x(),
                  check.worst.y(), check.worst.z(), check.worst_line, check.deeper, check.resolution);
    std::cerr << buf;
    return kExitInternal;
  }
  if (done.rework) {
    const ReworkProgram& r = *done.rework;
    const ReworkSelection& sel = r.selection;
    if (r.text.empty()) {
      // Nothing to re-cut: a programmer expects no program rather than an
      // empty one to load, and the exit status of success.
      std::cout << "no rework needed: the error field's largest material left, " << um(sel.largest_field)
                << ", is within the threshold " << um(r.threshold) << "; nothing written\n";
      return kExitOk;
    }
    const ReworkCheck& rc = r.check;
    if (!rc.safe()) {
      char buf[320];
      if (rc.deeper > 0)
        std::snprintf(buf, sizeof buf,
                      "furrow compensate: nothing written: the rework program would cut %.4f mm deeper than the "
                      "compensated program at (%.3f, %.3f, %.3f) (%zu z-map nodes at %.3f mm)\n",
                      rc.worst_excess, rc.worst.x(), rc.worst.y(), rc.worst.z(), rc.deeper, rc.resolution);
      else
        std::snprintf(buf, sizeof buf,
                      "furrow compensate: nothing written: a rapid of the rework program (line %d) would cut %.4f mm "
                      "into the part at (%.3f, %.3f, %.3f) (%zu z-map nodes at %.3f mm)\n",
                      rc.worst_rapid_line, rc.worst_rapid_depth, rc.worst_rapid.x(), rc.worst_rapid.y(),
                      rc.worst_rapid.z(), rc.rapid_nodes_cut, rc.resolution);
      std::cerr << buf;
      return kExitInternal;
    }
    std::cout << "rework: " << sel.stretches.size() << " stretch" << (sel.stretches.size() == 1 ? "" : "es") << " in "
              << sel.regions.size() << " region" << (sel.regions.size() == 1 ? "" : "s") << ", " << sel.moves_kept
              << " of " << sel.moves << " moves re-cut where material left exceeds " << um(r.threshold)
              << "; rapids at the clearance height " << sel.clearance << " mm\n";
  }
  const std::string& written = done.rework ? done.rework->text : done.program.text;
  if (predict_out) {
    const PredictedPath predicted = naming_inputs(part_path + " with " + out_path, [&] {
      return predict_compensated(part, tool, tool_path.value_or(""), table, table_path.value_or(""), written, format,
                                 read, predict_options, {part_path, out_path, ""});
    });
    const PredictionSummary& s = predicted.record.summary;
    std::cout << "predicted (" << *predict_out << "): max undercut " << um(s.max_undercut.error) << ", max overcut "
              << um(s.max_overcut.error) << ", scallop " << um(s.max_scallop) << ", " << s.gouge_sites
              << " gouge sites, " << predicted.record.rapids.gouges.size() << " rapid gouges\n";
    outputs.file(*predict_out, predicted.json);
  }
  outputs.file(record, done.json);
  outputs.file(out_path, written);
  outputs.publish(out_path);
  std::cout << "wrote " << out_path << " and " << record << "\n";
  return kExitOk;
}

std::string compensate_options_help() {
  return option_help_lines(describe(compensate_option_table())) +
         "\nPrediction options, for --predict-out (as furrow predict's, docs/options.md):\n" +
         option_help_lines(describe(prediction_option_table()));
}

}  // namespace

const Command kCompensateCommand = {
    "compensate", "a G-code or APT CL program moved by the measured error field of the part it cut",
    "usage: furrow compensate PART --comparison COMPARISON.json --toolpath PATH.nc|PATH.apt\n"
    "                         --tool TOOL.json|--tools TABLE.json --out COMP.nc|COMP.apt\n"
    "                         [--gain G] [--max-offset MM]\n"
    "                         [--smoothing MM|auto] [--clip-back N] [--prediction P.json]\n"
    "                         [--rework [--rework-threshold MM]]\n"
    "                         [--predict-out PRED.json [prediction options]]\n"
    "                         [--units mm|inch]\n"
    "\n"
    "Fits the systematic error of a measured part (the comparison's residuals\n"
    "against its prediction, or its deviations without one) as a smooth field per\n"
    "face, moves every tool tip of the program that cut it (G-code, or APT CL\n"
    "data: .apt, .cl, .cls) by -gain x the field along the surface normal, and\n"
    "writes the program again in its own format: only the coordinates of moved\n"
    "lines change; comments, feeds, spindle, tool changes, rapids, work offsets\n"
    "and line numbers are kept, and a moved arc becomes straight segments\n"
    "(docs/compensation.md \"Writing the program\"). COMP.json, written beside\n"
    "it, holds the field per face, the clipped moves, the z-map check and\n"
    "the residual expected at each measured point and region once the\n"
    "program is cut (docs/compensation.md \"Predicted before it is cut\").\n"
    "The written program is checked with a z-map against the original; moves\n"
    "that cut deeper than their offsets allow have their offsets halved and\n"
    "the check runs again (--clip-back rounds); if it still fails, nothing is\n"
    "written and the exit status is 3.\n"
    "With --rework, the program written re-cuts the same part: only the\n"
    "compensated moves where the field says material is left beyond the\n"
    "threshold, joined by rapids at the program's clearance height, checked\n"
    "against the full compensated program; when no move needs it, nothing is\n"
    "written (exit 0, docs/compensation.md \"Rework\").\n"
    "\n"
    "  --comparison FILE     comparison.json of furrow compare for PART (required)\n"
    "  --toolpath FILE       the G-code program or APT CL file the part was cut\n"
    "                        with (required)\n"
    "  --tool FILE           its tool JSON (required unless --tools is given)\n"
    "  --tools FILE          tool table of a program that changes tools (T n M6),\n"
    "                        as furrow predict reads it: each pass is located,\n"
    "                        moved and checked with the tool loaded when it is\n"
    "                        cut (--tool: the one in the spindle before the first\n"
    "                        change); not with --rework\n"
    "  --out FILE            compensated program to write (required); its record\n"
    "                        goes beside it with the extension .json\n"
    "  --prediction FILE     prediction.json of furrow predict for this program:\n"
    "                        its error at each measured point (the path's own\n"
    "                        furrows and cusps) is taken off the deviation\n"
    "                        before the fit, instead of the comparison's own\n"
    "                        prediction (if it has one)\n"
    "  --predict-out FILE    also predict the program written (as furrow predict\n"
    "                        would read it, with the same tool) and write that\n"
    "                        prediction.json; the prediction options of furrow\n"
    "                        predict (--tolerance, --resolution, --cell, ...)\n"
    "                        apply to it\n"
    "  --units U             units of G-code before G20/G21, of APT before UNITS/\n"
    "                        (default mm)\n"
    "\n"
    "Compensation options (docs/options.md):\n",
    run_compensate, compensate_options_help};

}  // namespace furrow::cli
