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

#include "results/results_database.hpp"

namespace furrow {

// Key of the transaction-level advisory lock every writer takes: writers
// queue, so the storing order (part_key) is the commit order ("FRRS").
constexpr long long kPostgresWriterLock = 0x46525253;

// True for a location that is a PostgreSQL connection string: a
// postgresql:// or postgres:// URI, or key=value pairs whose first key is
// one of libpq's connection keywords.
bool is_postgres_location(const std::string& location);

// InputError when the connection string holds a password (or an SSL key
// password), naming it with the secret masked and saying where libpq reads
// one from; nothing else is checked.
void check_postgres_location(const std::string& location);

// See open_results_database().
std::unique_ptr<ResultsDatabase> open_postgres_results_database(const std::string& location,
                                                                DatabaseAccess access);

}  // namespace furrow
