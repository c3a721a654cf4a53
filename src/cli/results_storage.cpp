#include "cli/results_storage.hpp"

#include <cstdlib>
#include <ctime>

#include "base/error.hpp"
#include "base/json_fields.hpp"
#include "cli/option_flags.hpp"
#include "inspection/scan_comparison_document.hpp"
#include "report/report_sources.hpp"

namespace furrow::cli {

ResultsStorageOptions read_results_storage(Args& args) {
  ResultsStorageOptions options;
  read_option_flags(args, results_storage_option_table(), options);
  if (options.db.empty())
    if (const char* env = std::getenv("FURROW_DB")) options.db = env;
  return options;
}

std::unique_ptr<ResultsDatabase> open_results_storage(Args& args, const ResultsStorageOptions& options,
                                                      bool serial_known) {
  if (options.db.empty()) {
    if (!options.serial.empty()) args.fail("--serial names the part in a results database: give --db (or FURROW_DB)");
    return nullptr;
  }
  check_results_location(options.db);  // before a message names it
  if (!serial_known)
    args.fail("storing in the results database " + options.db +
              " needs the part's serial number (--serial S); docs/results_database.md");
  return open_results_database(options.db, DatabaseAccess::write);
}

RecordContext record_context(const std::string& serial, const std::optional<InspectionRecord>& record) {
  RecordContext context;
  context.serial = serial;
  context.date = utc_iso8601(std::time(nullptr));
  if (record) {
    context.operator_name = record->operator_name;
    context.cmm = record->cmm;
  }
  return context;
}

StoreResult store_comparison_file(ResultsDatabase& db, const std::string& path, RecordContext context,
                                  std::ostream& out) {
  const std::string text = json_fields::read_text(path);
  const bool scan = is_scan_comparison_text(text);
  const std::vector<InputDigest> inputs =
      scan ? read_scan_report_sources(path).inputs : read_report_sources(path).inputs;
  // inputs[0] is the comparison itself; the record puts its own digest first.
  for (std::size_t k = 1; k < inputs.size(); ++k)
    context.inputs.push_back({inputs[k].role, inputs[k].path, inputs[k].sha256});
  const ComparisonRecord record = make_comparison_record(text, path, context);
  const StoreResult result = db.store(record);
  if (result == StoreResult::stored && scan)
    out << "stored in " << db.location() << ": part \"" << record.serial << "\", a scan, " << record.regions.size()
        << " regions, " << record.verdict << "\n";
  else if (result == StoreResult::stored)
    out << "stored in " << db.location() << ": part \"" << record.serial << "\", " << record.points.size()
        << " points, " << record.verdict << "\n";
  else
    out << "already in " << db.location() << ": part \"" << record.serial
        << "\" with this comparison (same SHA-256), not stored again\n";
  return result;
}

}  // namespace furrow::cli
