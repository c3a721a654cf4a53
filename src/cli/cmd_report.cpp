// furrow report comparison.json --out reports/NAME: the QA report folder
// (report.html, report.json, points.csv, figures) of a comparison.
#include <cstdio>
#include <filesystem>

#include <ctime>
#include <iostream>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "cli/commands.hpp"
#include "cli/results_storage.hpp"
#include "base/atomic_file.hpp"
#include "report/pdf_print.hpp"
#include "report/print_style.hpp"
#include "report/process_context.hpp"
#include "report/report_sources.hpp"
#include "report/scan_report.hpp"
#include "report/verdict.hpp"

namespace furrow::cli {

namespace {

// The part's place in its batch: found in the database by its digest, or
// stored there first under --serial (else the record's serial), as
// furrow compare --db would have (docs/results_database.md).
ProcessContext report_process(Args& args, const ResultsStorageOptions& storage, const std::string& comparison_path,
                              const std::vector<InputDigest>& inputs, const ReportContext& report) {
  std::string serial = storage.serial.empty() && report.record ? report.record->serial : storage.serial;
  const std::string& digest = inputs.front().sha256;  // the comparison's own
  const std::unique_ptr<ResultsDatabase> db =
      open_results_database(storage.db, serial.empty() ? DatabaseAccess::read : DatabaseAccess::write);
  bool stored = false;
  for (const StoredPart& p : db->parts())
    if (p.comparison_sha256 == digest) stored = true, serial = p.serial;
  const RecordContext context = record_context(serial, report.record);
  if (!stored) {
    if (serial.empty())
      args.fail(comparison_path + " is not stored in " + storage.db +
                ": give --serial S to store it there (docs/results_database.md)");
    store_comparison_file(*db, comparison_path, context, std::cout);
  }
  return process_context(*db, make_comparison_record(json_fields::read_text(comparison_path), comparison_path, context));
}

int run_report(Args& args) {
  const std::string out = args.required_option("out");
  const auto title = args.option("title");
  const auto record = args.option("record");
  const auto compensation = args.option("compensation");
  const bool pdf = args.flag("pdf");
  const std::string paper = args.option("paper").value_or("a4");
  const ResultsStorageOptions storage = read_results_storage(args);
  const std::string comparison_path = args.positional("COMPARISON (a comparison.json of furrow compare)");
  args.finish();
  paper_size_css(paper, "--paper");  // a4 or letter, before any work

  if (is_scan_comparison_text(json_fields::read_text(comparison_path))) {
    if (compensation) args.fail("--compensation: a compensation record is made from probe points, not from a scan");
    ScanReportSources sources = read_scan_report_sources(comparison_path);
    ReportContext context;
    if (record) {
      context.record = read_inspection_record(*record);
      sources.inputs.push_back(digest_file("record", *record));
    }
    check_inputs_outside(out, sources.inputs);
    // A scan is stored by its regions (docs/results_database.md "Scans"):
    // its place in the batch is found as a probe comparison's is.
    if (!storage.db.empty()) context.process = report_process(args, storage, comparison_path, sources.inputs, context);
    else if (!storage.serial.empty()) args.fail("--serial names the part in a results database: give --db (or FURROW_DB)");
    context.title = title.value_or(std::filesystem::path(out).lexically_normal().filename().string());
    if (context.title.empty() || context.title == ".") context.title = "comparison";
    context.generated = utc_timestamp();
    context.inputs = sources.inputs;
    const std::vector<FolderFile> files =
        make_scan_report(sources.doc, sources.part, sources.regions ? &*sources.regions : nullptr, context);
    write_folder_atomically(out, [&](const std::string& staging) {
      write_folder_files(staging, files);
      if (pdf) print_pdf(staging + "/report.html", staging + "/report.pdf", PdfOptions{paper});
    });
    const ReportVerdict v = report_verdict(scan_as_comparison(sources.doc));
    std::printf("verdict: %s (scan: profile %.1f um, zone %.1f um, %zu of %zu points out of tolerance)\n"
                "wrote %s/report.html (and report.json, points.csv, %zu figure files%s)\n",
                v.result(), v.profile * 1000, v.zone.width * 1000, v.out_of_tolerance, v.evaluated, out.c_str(),
                files.size() - 3, pdf ? ", report.pdf" : "");
    return exit_status(v.verdict, v.alignment);
  }
  ReportSources sources = read_report_sources(comparison_path);
  ReportContext context;
  if (record) {  // checked before any work; its digest goes with the other inputs
    context.record = read_inspection_record(*record);
    sources.inputs.push_back(digest_file("record", *record));
  }
  if (compensation) {  // the record of a compensated program: of this comparison, or refused before any work
    context.compensation = read_compensation_record(*compensation);
    check_record_against(*context.compensation, sources.doc, *compensation);
    context.compensation_file = *compensation;
    sources.inputs.push_back(digest_file("compensation", *compensation));
  }
  check_inputs_outside(out, sources.inputs);
  if (!storage.db.empty()) context.process = report_process(args, storage, comparison_path, sources.inputs, context);
  else if (!storage.serial.empty()) args.fail("--serial names the part in a results database: give --db (or FURROW_DB)");
  context.title = title.value_or(std::filesystem::path(out).lexically_normal().filename().string());
  if (context.title.empty() || context.title == ".") context.title = "comparison";
  context.generated = utc_timestamp();
  context.inputs = sources.inputs;
  const std::vector<FolderFile> files =
      make_report(sources.doc, sources.part, sources.regions ? &*sources.regions : nullptr, context,
                  sources.prediction ? &*sources.prediction : nullptr);
  write_folder_atomically(out, [&](const std::string& staging) {
    write_folder_files(staging, files);
    if (pdf) print_pdf(staging + "/report.html", staging + "/report.pdf", PdfOptions{paper});  // no PDF: no folder
  });

  const ReportVerdict v = report_verdict(sources.doc);
  std::printf("verdict: %s (profile %.1f um, zone %.1f um, %zu of %zu points out of tolerance", v.result(),
              v.profile * 1000, v.zone.width * 1000, v.out_of_tolerance, v.evaluated);
  if (v.has_prediction) std::printf(", %zu of %zu predicted gouges confirmed", v.confirmed, v.sites);
  std::printf(")\nwrote %s/report.html (and report.json, points.csv, results.qif, %zu figure files%s)\n", out.c_str(),
              files.size() - 4, pdf ? ", report.pdf" : "");
  return exit_status(v.verdict, v.alignment);
}

std::string report_options_help() {
  return "\nResults database (docs/results_database.md, docs/options.md): with --db the\n"
         "report gets a Process section, each region's mean deviation over the last\n"
         "parts of the batch with this one last and its Cpk (docs/report.md\n"
         "\"Process\"). A comparison not stored yet is stored first, under --serial\n"
         "or the record's serial; without either it is refused:\n" +
         option_help_lines(describe(results_storage_option_table()));
}

}  // namespace

const Command kReportCommand = {
    "report", "QA report of a comparison: self-contained HTML, JSON, CSV, figures",
    "usage: furrow report COMPARISON.json --out FOLDER [--title TEXT] [--record RECORD.json]\n"
    "                     [--compensation COMP.json] [--pdf [--paper a4|letter]] [--db PATH [--serial S]]\n"
    "\n"
    "Writes the QA report of a comparison (furrow compare) into FOLDER, replaced\n"
    "as a whole: report.html (self-contained, opens offline), report.json (every\n"
    "number; docs/report.schema.json), points.csv (one row per measured point),\n"
    "results.qif (QIF 3.0 Results, docs/qif.md) and the figures as SVG and PNG\n"
    "files (region map, deviation maps, histogram, predicted vs measured, gouge\n"
    "sites, the 3D view's front view). The page has an interactive 3D view\n"
    "(three.js from Debian's libjs-three, inlined). The report opens with the\n"
    "verdict and names every input file with its SHA-256 (docs/report.md).\n"
    "With --pdf also report.pdf, the page printed by headless Chromium\n"
    "(/usr/bin/chromium; A4 or Letter, header and page number on every page).\n"
    "The part, plan, regions and prediction the comparison names are looked up\n"
    "relative to the current directory, then next to COMPARISON.\n"    "A comparison of a scan (furrow compare --scan) gets a Scan section, the\n"
    "histogram of every evaluated point and its deviation surface (the sample\n"
    "the comparison recorded) in the maps and the 3D view; the raw scan is not\n"
    "needed, and there is no results.qif (docs/report.md \"A scan\").\n"
    "Exit status 0 when the comparison passed, 1 when it failed, 4 when it was\n"
    "inconclusive.\n"
    "\n"
    "  --out FOLDER   report folder to write (required)\n"
    "  --title TEXT   heading (default: the folder's name)\n"
    "  --record FILE  inspection record: part number, revision, serial, lot,\n"
    "                 customer, operator, CMM, probe, qualification date,\n"
    "                 temperature, program, notes, sign-off (docs/formats.md\n"
    "                 \"Inspection record\"); shown in the header, written to\n"
    "                 report.json and results.qif\n"
    "  --compensation COMP.json\n"
    "                 the record furrow compensate wrote beside a program\n"
    "                 compensated from this comparison: adds a Compensation\n"
    "                 section (measured deviation and expected residual per\n"
    "                 region and overall, maps before and after on one colour\n"
    "                 scale; docs/report.md \"Compensation\"). A record of another\n"
    "                 comparison is refused (exit 2)\n"
    "  --pdf          also print report.pdf (needs Chromium)\n"
    "  --paper SIZE   a4 (default) or letter\n",
    run_report, report_options_help};

}  // namespace furrow::cli
