#pragma once
// The results database in PostgreSQL (docs/results_database.md
// "PostgreSQL"): one database for a shop with several CMMs writing at once.
// The location is a libpq connection string, a URI (postgresql://...,
// postgres://...) or key=value pairs (host=... dbname=...). A connection
// string holding a password is refused: libpq takes it from ~/.pgpass
// (PGPASSFILE), PGPASSWORD or a service file. The only file that includes
// <libpq-fe.h> (scripts/check-layers.py).
#include <memory>
#include <string>

#include "results/postgres_location.hpp"
#include "results/results_database.hpp"

namespace furrow {

// Key of the transaction-level advisory lock every writer takes: writers
// queue, so the storing order (part_key) is the commit order ("FRRS").
constexpr long long kPostgresWriterLock = 0x46525253;

// See open_results_database().
std::unique_ptr<ResultsDatabase> open_postgres_results_database(const std::string& location,
                                                                DatabaseAccess access);

}  // namespace furrow
