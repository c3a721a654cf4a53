#pragma once
// The results database in one SQLite file (docs/results_database.md
// "SQLite"): nothing to start, several writers at once through WAL and a
// busy timeout. The only file that includes <sqlite3.h>
// (scripts/check-layers.py).
#include <memory>
#include <string>

#include "results/results_database.hpp"

namespace furrow {

// SQLite's header field that tells a Furrow results file from any other
// SQLite file ("FRRS").
constexpr int kSqliteApplicationId = 0x46525253;
// How long a writer waits for another one's transaction [ms].
constexpr int kSqliteBusyTimeoutMs = 60000;

// See open_results_database().
std::unique_ptr<ResultsDatabase> open_sqlite_results_database(const std::string& path, DatabaseAccess access);

}  // namespace furrow
