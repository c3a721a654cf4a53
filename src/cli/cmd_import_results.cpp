// furrow import-results --db PATH FOLDER...: store comparisons written
// before (by furrow compare or furrow run) in the results database.
#include <sys/stat.h>

#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/results_storage.hpp"

namespace furrow::cli {

namespace {

namespace fs = std::filesystem;

// A folder's comparison.json, or the file itself.
std::string comparison_in(const std::string& given) {
  const fs::path p(given);
  if (fs::is_directory(p)) {
    const fs::path file = p / "comparison.json";
    if (!fs::is_regular_file(file)) throw InputError(given + ": no comparison.json in this folder");
    return file.string();
  }
  if (!fs::is_regular_file(p)) throw InputError(given + ": no such folder or file");
  return given;
}

// The serial a folder stands for: its name (a file's: its folder's name).
std::string serial_of(const std::string& given, const std::string& comparison) {
  fs::path folder = fs::absolute(comparison).lexically_normal().parent_path();
  const std::string name = folder.filename().string();
  if (name.empty()) throw InputError(given + ": no folder name to take the serial from; give --serial");
  return name;
}

int run_import_results(Args& args) {
  const ResultsStorageOptions storage = read_results_storage(args);
  std::vector<std::string> folders;
  while (const auto f = args.optional_positional()) folders.push_back(*f);
  args.finish();
  if (folders.empty()) args.fail("name at least one FOLDER holding a comparison.json");
  if (storage.db.empty()) args.fail("--db PATH (or FURROW_DB) names the database to store into");
  if (!storage.serial.empty() && folders.size() > 1)
    args.fail("--serial names one part: with several folders each one's name is its serial");
  // Every folder checked before the first part is stored.
  std::vector<std::string> comparisons, serials;
  for (const std::string& f : folders) {
    comparisons.push_back(comparison_in(f));
    serials.push_back(storage.serial.empty() ? serial_of(f, comparisons.back()) : storage.serial);
  }
  const std::unique_ptr<ResultsDatabase> db = open_results_storage(args, storage, true);
  std::size_t stored = 0;
  for (std::size_t k = 0; k < comparisons.size(); ++k) {
    struct stat st {};
    if (::stat(comparisons[k].c_str(), &st) != 0) throw InputError(comparisons[k] + ": cannot be read");
    RecordContext context;
    context.serial = serials[k];
    context.date = utc_iso8601(st.st_mtime);  // when comparison.json was written
    stored += store_comparison_file(*db, comparisons[k], context, std::cout) == StoreResult::stored;
  }
  std::cout << stored << " of " << comparisons.size() << " comparison" << (comparisons.size() == 1 ? "" : "s")
            << " stored in " << db->location() << "\n";
  return kExitOk;
}

}  // namespace

const Command kImportResultsCommand = {
    "import-results", "store comparisons written before in the results database",
    "usage: furrow import-results --db PATH [--serial S] FOLDER...\n"
    "\n"
    "Stores each FOLDER's comparison.json (a folder written by furrow run, or\n"
    "any folder holding one; a comparison.json file may be named instead) in\n"
    "the results database, as furrow compare --db does, with the SHA-256 of\n"
    "every source it names (found as furrow report finds them). The part's\n"
    "serial is the folder's name, or --serial for one folder; its date the\n"
    "file's modification time. Each part is stored whole or not at all; a\n"
    "comparison stored before under the same serial is not stored again, so\n"
    "importing a batch a second time adds nothing (docs/results_database.md).\n"
    "\n"
    "  --db PATH    the results database, an SQLite file created when missing,\n"
    "               or a PostgreSQL connection string (postgresql://...)\n"
    "               without a password (default: the environment's FURROW_DB)\n"
    "  --serial S   the serial number of the one part imported\n"
    "\n"
    "Exit status: 0 every comparison stored or there already, 2 bad input (a\n"
    "folder without comparison.json, a database that is not Furrow's, a\n"
    "comparison stored already under another serial).\n",
    run_import_results};

}  // namespace furrow::cli
