#pragma once
// Where a comparison is stored for statistical process control (`furrow
// compare`, `furrow run`; docs/results_database.md): the results database
// and the part's serial number, described once (base/option_table.hpp) so
// both commands, their help, the man page and docs/options.md say the same.
// Command-line only: a job file names the part, not the batch it joins.
#include <string>

#include "base/option_table.hpp"

namespace furrow {

struct ResultsStorageOptions {
  std::string db;      // the database's location; empty: FURROW_DB, else not stored
  std::string serial;  // the part's serial number; empty: none given
};

const OptionTable<ResultsStorageOptions>& results_storage_option_table();

}  // namespace furrow
