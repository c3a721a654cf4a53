#include "stage/results_options.hpp"

namespace furrow {

namespace {

OptionTable<ResultsStorageOptions> make_table() {
  using O = ResultsStorageOptions;
  OptionTable<O> t;
  OptionSpec<O> db = text_option<O>(
      "db", "PATH",
      "store the comparison in this results database, an SQLite file created when missing, or a "
      "PostgreSQL connection string without a password (docs/results_database.md)",
      [](auto& o) -> auto& { return o.db; });
  db.example = "results.db";
  t.push_back(default_is(db, "$FURROW_DB, else not stored"));
  OptionSpec<O> serial = text_option<O>(
      "serial", "S",
      "the part's serial number, required with a database; the same serial again is a re-measurement, "
      "and SPC reads its latest",
      [](auto& o) -> auto& { return o.serial; });
  serial.example = "SN-0042";
  t.push_back(default_is(serial, "none; furrow run and report: the inspection record's"));
  return t;
}

}  // namespace

const OptionTable<ResultsStorageOptions>& results_storage_option_table() {
  static const OptionTable<ResultsStorageOptions> table = make_table();
  return table;
}

}  // namespace furrow
