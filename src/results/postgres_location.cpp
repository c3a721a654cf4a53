#include "results/postgres_location.hpp"

#include <libpq-fe.h>

#include <algorithm>
#include <memory>
#include <regex>

#include "base/error.hpp"

namespace furrow {

const char* const kPostgresPasswordHelp =
    "put the password in ~/.pgpass (or the file PGPASSFILE names), in PGPASSWORD, or in a service file "
    "(service=NAME, PGSERVICEFILE) and give the location without it (docs/results_database.md \"Passwords\")";

// libpq's messages end in a newline and may hold several lines.
std::string postgres_one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] == '\n' || text[k] == '\t') {
      if (!out.empty() && out.back() != ' ') out += ' ';
      continue;
    }
    out += text[k];
  }
  return out;
}

namespace {

// The location with any password replaced by ****, for the one message
// that has to name a location holding one.
std::string masked(const std::string& location) {
  std::string out = location;
  const std::size_t scheme = out.find("://");
  if (scheme != std::string::npos) {
    const std::size_t start = scheme + 3;
    const std::size_t end = std::min(out.find_first_of("/?", start), out.size());
    const std::size_t at = out.rfind('@', end == 0 ? 0 : end - 1);
    if (at != std::string::npos && at >= start) {
      const std::size_t colon = out.find(':', start);
      if (colon < at) out.replace(colon + 1, at - colon - 1, "****");
    }
  }
  // key=value pairs, and a URI's query parameters.
  static const std::regex pair(R"(((?:^|[\s?&])(?:ssl)?password\s*=\s*)('(?:[^'\\]|\\.)*'|[^\s&]*))");
  return std::regex_replace(out, pair, "$1****");
}

struct ConninfoFree {
  void operator()(PQconninfoOption* o) const { PQconninfoFree(o); }
};
using Conninfo = std::unique_ptr<PQconninfoOption, ConninfoFree>;

}  // namespace

bool is_postgres_location(const std::string& location) {
  if (location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0) return true;
  // key=value pairs: the first key must be one of libpq's.
  std::size_t k = location.find_first_not_of(" \t");
  if (k == std::string::npos) return false;
  const std::size_t key_end = location.find_first_of(" \t=", k);
  if (key_end == std::string::npos) return false;
  const std::size_t eq = location.find_first_not_of(" \t", key_end);
  if (eq == std::string::npos || location[eq] != '=') return false;
  const std::string key = location.substr(k, key_end - k);
  const Conninfo defaults(PQconndefaults());
  if (!defaults) return false;
  for (const PQconninfoOption* o = defaults.get(); o->keyword; ++o)
    if (key == o->keyword) return true;
  return false;
}

void check_postgres_location(const std::string& location) {
  char* error = nullptr;
  const Conninfo options(PQconninfoParse(location.c_str(), &error));
  if (!options) {
    const std::string shown = masked(location);
    // libpq's message may quote a piece of the string: only when no
    // password could be in it.
    std::string message = shown + ": not a valid PostgreSQL connection string";
    if (error && shown == location) message += " (" + postgres_one_line(error) + ")";
    PQfreemem(error);
    throw InputError(message);
  }
  for (const PQconninfoOption* o = options.get(); o->keyword; ++o) {
    const std::string keyword = o->keyword;
    if ((keyword == "password" || keyword == "sslpassword") && o->val && *o->val) {
      std::string shown = masked(location);
      // A form the masking does not know (percent-encoded, say): not named at all.
      if (shown.find(o->val) != std::string::npos) shown = "--db";
      throw InputError(shown + ": the connection string holds a " +
                       (keyword == "password" ? "password" : "key password") +
                       ", which would show wherever the location is printed; " + kPostgresPasswordHelp);
    }
  }
}

}  // namespace furrow
