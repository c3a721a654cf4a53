// furrow run job.json: partition -> predict -> plan -> compare -> report in
// one go, from a job file (docs/formats.md "Job file").
#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/job_output.hpp"
#include "cli/results_storage.hpp"
#include "job/pipeline.hpp"

namespace furrow::cli {

namespace {

int run_run(Args& args) {
  const auto out = args.option("out");
  const auto record = args.option("record");
  ResultsStorageOptions storage = read_results_storage(args);
  const std::string job_path = args.positional("JOB (a job.json file)");
  args.finish();
  Job job = read_job(job_path);
  if (out) job.output = *out;
  if (record) {  // replaces the job's own record (relative to the current directory)
    job.record_file = *record;
    job.record = read_inspection_record(*record);
  }
  // The record's serial names the part only when there is a database to store
  // it in; --serial without --db is still refused.
  const std::string serial = storage.serial.empty() && job.record ? job.record->serial : storage.serial;
  // Before any work: a database that is not Furrow's stops the job here.
  const std::unique_ptr<ResultsDatabase> db = open_results_storage(args, storage, !serial.empty());
  RecordContext context = record_context(serial, job.record);
  // The report shows the part after the stored ones; it is stored once the
  // folder is written.
  ProcessLookup process;
  if (db)
    process = [&](const std::string& comparison_text) {
      return std::optional<ProcessContext>(
          process_context(*db, make_comparison_record(comparison_text, "comparison.json", context)));
    };
  // A stage's option or input came from the job: the message names it.
  const int status = naming_inputs(job_path, [&] { return run_and_report(job, std::cout, process); });
  const std::string comparison = (std::filesystem::path(job.output) / "comparison.json").string();
  if (db && std::filesystem::exists(comparison)) {
    context.date = utc_iso8601(std::time(nullptr));  // stored now
    store_comparison_file(*db, comparison, context, std::cout);
  } else if (db) {
    std::cout << "nothing stored in " << db->location() << ": the job measured nothing\n";
  }
  return status;
}

std::string run_options_help() {
  return "\nResults database (docs/results_database.md, docs/options.md), after the output\n"
         "folder is written:\n" +
         option_help_lines(describe(results_storage_option_table()));
}

}  // namespace

const Command kRunCommand = {
    "run", "a whole inspection job from a job file: partition to QA report",
    "usage: furrow run JOB.json [--out FOLDER] [--record RECORD.json]\n"
    "\n"
    "Runs the job file's stages with the options it gives (docs/formats.md\n"
    "\"Job file\"; paths in it are relative to the job file): partition, tool\n"
    "path (a file, or generated), machining prediction, probe plan, then -\n"
    "when the job names measurements (a file, or a simulation) - registration,\n"
    "comparison with the prediction, gouge confirmation and the QA report,\n"
    "and with a \"compensate\" member the program moved by the measured error\n"
    "(furrow compensate on the job's comparison, docs/compensation.md).\n"
    "Without measurements it stops after the plan. Everything is written into\n"
    "the job's output folder, replaced as a whole (docs/report.md).\n"
    "\n"
    "  --out FOLDER   output folder instead of the job's (relative to the\n"
    "                 current directory)\n"
    "  --record FILE  inspection record (part number, serial, operator, CMM,\n"
    "                 sign-off; docs/formats.md \"Inspection record\") instead\n"
    "                 of the job's \"record\"\n",
    run_run, run_options_help,
    "\n"
    "Exit status: 0 pass (or plan only), 1 fail (out of tolerance or a\n"
    "confirmed gouge), 2 bad input, 3 the computation did not succeed,\n"
    "4 inconclusive (see furrow compare). A compensated program the z-map check\n"
    "still refuses: 3, nothing written.\n"};

}  // namespace furrow::cli
