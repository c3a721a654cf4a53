#include "cli/manual.hpp"

#include <algorithm>
#include <regex>
#include <sstream>

#include "base/option_table.hpp"
#include "io/cad/cad_module.hpp"
#include "stage/compare_options.hpp"
#include "stage/scan_options.hpp"
#include "stage/compensate_options.hpp"
#include "stage/partition_options.hpp"
#include "stage/plan_options.hpp"
#include "stage/prediction_options.hpp"
#include "stage/results_options.hpp"
#include "stage/scan_simulation_options.hpp"
#include "stage/simulation_options.hpp"
#include "stage/toolpath_options.hpp"

namespace furrow::cli {

namespace {

// troff treats a leading '.' or '\'' as a request and '\' as an escape.
std::string troff_line(const std::string& line) {
  std::string out;
  for (char c : line) {
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out.insert(0, "\\&");
  return out;
}

}  // namespace

std::string usage_text(const Command& command) {
  std::string text = command.usage;
  if (command.stage_options) text += command.stage_options();
  return text + command.usage_end;
}

std::vector<std::string> options_in_usage(const std::string& usage) {
  std::vector<std::string> out;
  static const std::regex option("--[a-z][a-z0-9-]*");
  for (auto it = std::sregex_iterator(usage.begin(), usage.end(), option); it != std::sregex_iterator(); ++it)
    if (std::find(out.begin(), out.end(), it->str()) == out.end()) out.push_back(it->str());
  return out;
}

void write_man_page(std::ostream& out, const std::vector<const Command*>& commands) {
  out << ".TH FURROW 1 \"\" \"furrow " << FURROW_VERSION << "\" \"User Commands\"\n"
      << ".SH NAME\nfurrow \\- inspection planning and machining\\-error verification of "
         "sculptured surfaces\n"
      << ".SH SYNOPSIS\n.B furrow\n.I COMMAND\n[options]\n"
      << ".SH DESCRIPTION\nFurrow partitions free\\-form faces by curvature, predicts the "
         "errors a 3\\-axis finishing path leaves, plans CMM probe points and programs, "
         "registers measured points to the CAD surface and writes a QA report.\n"
      << ".SH COMMANDS\n";
  for (const Command* c : commands) {
    out << ".SS " << c->name << "\n" << troff_line(c->summary) << "\n.PP\n.nf\n";
    std::istringstream usage(usage_text(*c));
    for (std::string line; std::getline(usage, line);) out << troff_line(line) << "\n";
    out << ".fi\n";
  }
  out << ".SH EXIT STATUS\n.TP\n0\nok, or the part passes\n.TP\n1\nthe part fails (out of "
         "tolerance, gouge, uncovered)\n.TP\n2\nbad input: a file, option or value to fix; "
         "nothing is written\n.TP\n3\nthe computation did not succeed\n.TP\n4\ninconclusive: nothing failed, but "
         "something was not shown to be good (a suspected blunder outside the zone, an unmeasured predicted gouge, "
         "a region below its minimum, an undetermined alignment)\n"
      << ".SH ENVIRONMENT\n.TP\n.B " << cad::kModuleOverride
      << "\nThe CAD module to load for STEP and IGES files instead of looking for " << cad::kModuleName
      << ".so next to the program and in the installed module folder (lib/furrow). Without a module that "
         "can be loaded, a CAD import stops with exit status 3 and names every place looked at.\n"
      << ".SH SEE ALSO\n"
         "\\fBfurrow help \\-\\-options\\fR writes the reference of every stage option (flag, job\\-file "
         "member, default); \\fBfurrow help \\-\\-job\\-schema\\fR the JSON Schema of a job file. Both are "
         "installed with the documentation as options.md and job.schema.json, next to report.schema.json.\n";
}

void write_options_reference(std::ostream& out) {
  out << "# Options of the stages\n\n"
         "<!-- Written by `furrow help --options`; a test compares this file with its output. -->\n\n"
         "Each stage option is described once in the code (src/stage/*_options.cpp) and\n"
         "taken the same way on the command line (`--flag VALUE`; a true/false option is a\n"
         "bare flag that sets the other value) and in a job file (the member, in the\n"
         "stage's section; see formats.md \"Job file\"). A value is checked the same way\n"
         "from both: a number must be finite and within its bounds, a word one of its\n"
         "choices.\n";
  const auto section = [&](const char* title, const char* where, const std::vector<OptionDoc>& docs) {
    out << "\n## " << title << "\n\n" << where << "\n\n" << option_markdown_table(docs);
  };
  section("Partition", "`furrow partition`; the job file's `partition` section.", describe(partition_option_table()));
  section("Tool path", "`furrow toolpath`; the job file's `toolpath` as `{\"generate\": {...}}`.",
          describe(toolpath_option_table()));
  section("Prediction",
          "`furrow predict`; the job file's `prediction` section. The colour range of the error map is "
          "`--map-scale` in µm on the command line and `map_scale` in mm in a job file.",
          describe(prediction_option_table()));
  section("Plan",
          "`furrow plan`; the job file's `plan` section (`furrow remeasure` takes the stylus, move and "
          "program options).",
          describe(plan_option_table()));
  section("Simulated measurement",
          "`furrow simulate-measurement`; the job file's `measurements` as `{\"simulate\": {...}}`. Planted "
          "bumps are `--bump X,Y,Z,R,H` (repeated) on the command line and `bumps` `[[x, y, z, r, h], ...]` in a "
          "job file.",
          describe(simulation_option_table()));
  section("Simulated scan",
          "`furrow simulate-measurement --scan`, on the command line only (a job's measurements are probe points); "
          "the part's placement (`--misalign`), `--seed` and `--bump` are the simulated measurement's. See "
          "scan_simulation.md.",
          describe(scan_simulation_option_table()));
  section("Comparison", "`furrow compare`; the job file's `comparison` section.", describe(compare_option_table()));
  section("Scan pre-processing",
          "`furrow compare --scan`, on the command line (no job-file stage yet); see scan.md.",
          describe(scan_option_table()));
  section("Compensation", "`furrow compensate`, on the command line (no job-file stage yet).",
          describe(compensate_option_table()));
  section("Results database",
          "`furrow compare`, `furrow run` and `furrow report`, on the command line only (a job file names a part, not the batch "
          "it joins); see results_database.md.",
          describe(results_storage_option_table()));
}

void write_bash_completion(std::ostream& out, const std::vector<const Command*>& commands) {
  out << "# bash completion for furrow " << FURROW_VERSION << " (written by `furrow help --completion`)\n"
      << "_furrow() {\n"
      << "  local cur=${COMP_WORDS[COMP_CWORD]}\n"
      << "  if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
      << "    COMPREPLY=($(compgen -W \"help --version";
  for (const Command* c : commands) out << " " << c->name;
  out << "\" -- \"$cur\"))\n    return\n  fi\n"
      << "  case \"$cur\" in\n    -*)\n      case \"${COMP_WORDS[1]}\" in\n";  out << "        help) COMPREPLY=($(compgen -W \"--man --completion --options --job-schema\" -- \"$cur\")) ;;\n";

  for (const Command* c : commands) {
    out << "        " << c->name << ") COMPREPLY=($(compgen -W \"";
    const std::vector<std::string> options = options_in_usage(usage_text(*c));
    for (std::size_t k = 0; k < options.size(); ++k) out << (k ? " " : "") << options[k];
    out << "\" -- \"$cur\")) ;;\n";
  }
  out << "      esac ;;\n    *) COMPREPLY=($(compgen -f -- \"$cur\")) ;;\n  esac\n}\n"
      << "complete -o filenames -F _furrow furrow\n";
}

}  // namespace furrow::cli
