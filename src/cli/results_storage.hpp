#pragma once
// Storing comparisons in the results database from the command line
// (`furrow compare`, `furrow run`, `furrow import-results`;
// docs/results_database.md): the database is opened before any work, so a
// location that is not Furrow's database stops the command (exit 2) before
// it writes anything; the comparison is stored after comparison.json is
// written, from the file's own bytes.
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "cli/args.hpp"
#include "report/inspection_record.hpp"
#include "results/results_database.hpp"
#include "stage/results_options.hpp"

namespace furrow::cli {

// --db and --serial (results_storage_option_table), --db defaulting to the
// environment's FURROW_DB.
ResultsStorageOptions read_results_storage(Args& args);

// The database to store into, or null without one. `serial_known`: a serial
// is given or will come from elsewhere (a job's inspection record);
// otherwise a database without --serial is refused, as is --serial without
// a database.
std::unique_ptr<ResultsDatabase> open_results_storage(Args& args, const ResultsStorageOptions& options,
                                                      bool serial_known);

// What a stored record says beyond the comparison: the serial, the time
// now, and the operator and CMM of the inspection record when there is one.
RecordContext record_context(const std::string& serial, const std::optional<InspectionRecord>& record);
// Stores the comparison.json at `path` (its sources' digests found as the
// QA report finds them, report/report_sources.hpp) and says so on `out`.
// Returns what the database did. InputError for a bad file or serial, or
// a digest stored already under another serial.
StoreResult store_comparison_file(ResultsDatabase& db, const std::string& path, RecordContext context,
                                  std::ostream& out);

}  // namespace furrow::cli
