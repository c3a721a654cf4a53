// furrow import CAD_FILE --out PART.json: STEP/IGES to Furrow's part JSON.
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "cli/commands.hpp"
#include "base/output_set.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cad/cad_import_report.hpp"
#include "io/part_file.hpp"

namespace furrow::cli {

namespace {

int run_import(Args& args) {
  const std::string out_path = args.required_option("out");
  const bool as_json = args.flag("json");
  CadImportOptions options;
  options.skip_bad_faces = args.flag("skip-bad-faces");
  options.trim_chord_tolerance = args.positive_or("trim-tolerance", options.trim_chord_tolerance);
  options.approximation_tolerance =
      args.positive_or("approximation-tolerance", options.approximation_tolerance);
  options.sewing_tolerance = args.non_negative_or("sewing-tolerance", options.sewing_tolerance);
  if (options.sewing_tolerance > kMaxSewingTolerance)
    args.fail("--sewing-tolerance must be at most 1 mm (sewing would join neighbouring features)");
  if (const auto rule = args.option("outward")) options.outward = parse_outward_rule(*rule, "furrow import: --outward");
  const std::string path = args.positional("CAD_FILE (a .step, .stp, .iges or .igs file)");
  args.finish();
  if (!is_cad_file(path)) args.fail(path + " is not a STEP or IGES file name (.step .stp .iges .igs)");
  OutputSet outputs;
  outputs.add_input(path, "CAD");
  outputs.will_write(out_path);

  if (isatty(STDERR_FILENO)) {
    options.progress = [](std::size_t done, std::size_t total) {
      std::fprintf(stderr, "\rimporting faces %zu/%zu", done, total);
      if (done == total) std::fprintf(stderr, "\n");
    };
  }
  const CadImportResult result = import_cad(path, options);
  // One warning line per face left out (docs/formats.md "CAD import").
  for (const CadSkippedFace& s : result.skipped)
    std::cerr << "warning: " << path << ": " << (s.entity.rfind("entity ", 0) == 0 ? "" : "face ")
              << (s.name.empty() ? "" : "\"" + s.name + "\" ") << s.entity << " left out: " << s.reason << "\n";
  outputs.file(out_path, part_to_json_text(result.part));
  outputs.publish();
  std::cout << (as_json ? cad_import_report_json(result, path, out_path)
                        : cad_import_report_text(result, path, out_path));
  return kExitOk;
}

}  // namespace

const Command kImportCommand = {
    "import", "convert a STEP or IGES part to Furrow's part JSON",
    "usage: furrow import CAD_FILE --out PART.json [--json] [--skip-bad-faces]\n"
    "                     [--trim-tolerance MM] [--approximation-tolerance MM]\n"
    "                     [--sewing-tolerance MM] [--outward +z|-z|point:x,y,z]\n"
    "\n"
    "Reads a STEP (AP203/AP214/AP242) or IGES part through OpenCASCADE and writes\n"
    "every face as a NURBS patch with its trim loops, normals out of the material,\n"
    "in millimetres (docs/formats.md \"CAD import\"). Prints per face the original\n"
    "surface type, whether the NURBS is exact or approximated and how far it is from\n"
    "the original, and the trim loops. Any command taking a PART also reads .step,\n"
    ".stp, .iges and .igs directly with the default tolerances.\n"
    "\n"
    "  --out FILE                   part JSON to write (required)\n"
    "  --json                       print the import report as JSON\n"
    "  --skip-bad-faces             leave out (and list) faces that cannot be read or converted,\n"
    "                               one warning line each (default: any is an error)\n"
    "                               instead of failing\n"
    "  --trim-tolerance MM          3-D distance between trim polygon and true\n"
    "                               boundary (default 1e-5)\n"
    "  --approximation-tolerance MM for surfaces with no exact NURBS form (default 1e-5)\n"
    "  --sewing-tolerance MM        faces that bound no solid are sewn into shells where\n"
    "                               their edges meet within this distance (default 1e-3;\n"
    "                               0: no sewing); closed shells are oriented by volume\n"
    "  --outward RULE               side of the material for open shells: +z (normals\n"
    "                               up), -z, or point:x,y,z (normals away from a point\n"
    "                               inside the material); without it such faces keep the\n"
    "                               file's sense and are reported undecided\n",
    run_import};

}  // namespace furrow::cli
