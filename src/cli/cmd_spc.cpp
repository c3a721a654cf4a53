// furrow spc --db PATH --out FOLDER: statistical process control over the
// parts stored in a results database (docs/spc.md): control charts,
// capability and the Nelson rules per characteristic, as spc.json,
// spc.html and spc.qif.
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "base/error.hpp"
#include "base/output_set.hpp"
#include "cli/commands.hpp"
#include "results/results_database.hpp"
#include "results/spc_outputs.hpp"
#include "results/spc_summary.hpp"

namespace furrow::cli {

namespace {

int run_spc(Args& args) {
  std::string db_path = args.option_or("db", "");
  const std::string out = args.required_option("out");
  const std::string by_text = args.option_or("by", "point");
  const auto serials = args.option("serials");
  args.finish();
  if (db_path.empty())
    if (const char* env = std::getenv("FURROW_DB")) db_path = env;
  if (db_path.empty()) args.fail("--db PATH (or FURROW_DB) names the results database to read");
  check_results_location(db_path);  // before spc.json or a message names it
  const SpcBy by = parse_spc_by(by_text, "--by");
  SpcSelection selection;
  selection.source = db_path;
  selection.criteria["by"] = to_string(by);
  SerialRange range;
  if (serials) {
    range = parse_serial_range(*serials, "--serials");
    selection.criteria["serials"] = *serials;
  }

  // The output may not replace the database or a folder holding it; checked
  // before the database is read.
  OutputSet outputs;
  outputs.add_input(db_path, "results database");
  outputs.will_write(out);

  const std::unique_ptr<ResultsDatabase> db = open_results_database(db_path, DatabaseAccess::read);
  const SpcInput input = load_spc_input(*db, by, range);
  if (input.parts.empty()) throw InputError(db_path + ": no part stored yet, nothing to chart");
  // Parts but nothing to follow (scans by point, parts without a
  // partition by region): no chart may say no rule was violated.
  if (input.characteristics.empty()) {
    std::fprintf(stderr, "spc: %s: %zu parts but no characteristic %s (%s), nothing charted\n", db_path.c_str(),
                 input.parts.size(), by == SpcBy::point ? "by point" : "by region",
                 by == SpcBy::point ? "no evaluated point with an id; a scan is followed --by region"
                                    : "no comparison had a partition (--regions)");
    return kExitInconclusive;
  }
  const SpcResult result = compute_spc(input);
  stage_spc_outputs(outputs, out, result, selection);
  outputs.publish();
  std::cout << spc_summary(result);
  std::cout << "wrote " << out << " (spc.json, spc.html, spc.qif)\n";
  return violation_in_latest_part(result) ? kExitFail : kExitOk;
}

}  // namespace

const Command kSpcCommand = {
    "spc", "control charts and capability over the parts of a results database",
    "usage: furrow spc --out FOLDER [--db PATH] [--by point|region] [--serials FROM..TO]\n"
    "\n"
    "Follows every characteristic over the parts stored in the results\n"
    "database (furrow compare/run --db, furrow import-results): an individuals\n"
    "and moving-range chart, Cp, Cpk, Pp, Ppk against the profile zone, the\n"
    "trend per part with its 95 % interval, and the Nelson rules 1-8\n"
    "(docs/spc.md). Parts are taken in the order their serial was first\n"
    "stored; a serial measured again counts with its latest comparison.\n"
    "Writes FOLDER with spc.json (every figure, docs/formats.md), spc.html\n"
    "(the charts, worst characteristic first) and spc.qif (QIF 3.0\n"
    "Statistics), published whole, and prints the worst characteristics and\n"
    "what the latest part violates.\n"
    "\n"
    "  --db PATH           the results database to read, an SQLite file or a\n"
    "                      PostgreSQL connection string (default: the\n"
    "                      environment's FURROW_DB); it must exist\n"
    "  --out FOLDER        the output folder, replaced as a whole\n"
    "  --by point|region   characteristics: each plan point's deviation\n"
    "                      (default), or each curvature region's mean deviation\n"
    "  --serials FROM..TO  only the parts from serial FROM to serial TO, in\n"
    "                      production order; either side may be left open\n"
    "                      (\"SN-10..\", \"..SN-40\"); both must be stored serials\n"
    "\n"
    "Exit status: 0 no Nelson rule is violated at the latest part, 1 some\n"
    "characteristic's violation reaches the latest part (a process signal:\n"
    "the summary names it), 2 bad input (no database there, a database that\n"
    "is not Furrow's, an unknown serial, an empty database).\n",
    run_spc};

}  // namespace furrow::cli
