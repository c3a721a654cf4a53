#pragma once
// A stage's option table (base/option_table.hpp) on the command line: each
// option is `--flag VALUE` (a toggle a bare `--flag`), read into the stage's
// options struct by the table's own read function, so that the command line
// and a job file accept the same values with the same checks.
#include <optional>
#include <string>

#include "base/option_table.hpp"
#include "cli/args.hpp"

namespace furrow::cli {

// The value of one option as given (converted by its kind), or none when
// the option is absent. Malformed numbers fail through args.
std::optional<nlohmann::json> option_value(Args& args, const OptionDoc& doc);

// Reads every option of `table` present in `args` into `options`; absent
// ones keep their values. Errors read "furrow CMD: --flag: ..." (exit 2).
template <class Options>
void read_option_flags(Args& args, const OptionTable<Options>& table, Options& options) {
  const std::vector<OptionDoc> docs = describe(table);
  for (std::size_t k = 0; k < table.size(); ++k)
    if (const std::optional<nlohmann::json> v = option_value(args, docs[k]))
      table[k].read(*v, "furrow " + args.command() + ": " + docs[k].flag, options);
}

}  // namespace furrow::cli
