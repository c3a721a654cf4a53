#pragma once
// PostgreSQL results-database locations (docs/results_database.md
// "PostgreSQL", "Passwords"): telling a connection string from a file path,
// and refusing one that holds a password before any message can print it.
// Reads the string with libpq's own parser, so every form libpq accepts
// (URI, key=value pairs, percent-encoding) is judged as libpq would.
#include <string>

namespace furrow {

// True for a location that is a PostgreSQL connection string: a
// postgresql:// or postgres:// URI, or key=value pairs whose first key is
// one of libpq's connection keywords.
bool is_postgres_location(const std::string& location);

// InputError when the connection string holds a password (or an SSL key
// password), naming it with the secret masked and saying where libpq reads
// one from; InputError for a string libpq cannot parse. Nothing else is
// checked.
void check_postgres_location(const std::string& location);

// Where a password goes instead of the connection string, for messages.
extern const char* const kPostgresPasswordHelp;

// A libpq message (newline-terminated, possibly several lines) as one line.
std::string postgres_one_line(std::string text);

}  // namespace furrow
