#include "cli/option_flags.hpp"

#include <cmath>

namespace furrow::cli {

namespace {

// The option as given under `name` (without "--"), converted by its kind.
std::optional<nlohmann::json> value_under(Args& args, const std::string& name, const OptionDoc& doc) {
  switch (doc.kind) {
    case OptionKind::number:
      if (const auto x = args.number(name)) return nlohmann::json(*x);
      return std::nullopt;
    case OptionKind::integer:
      // Read as a number and checked whole by the table, as a job file's
      // value is; a whole one travels as an integer so messages print "0".
      if (const auto x = args.number(name)) {
        if (*x == std::floor(*x) && std::fabs(*x) < 9e15) return nlohmann::json(static_cast<long>(*x));
        return nlohmann::json(*x);
      }
      return std::nullopt;
    case OptionKind::text:
      if (const auto t = args.option(name)) return nlohmann::json(*t);
      return std::nullopt;
    case OptionKind::toggle:
      // "--no-KEY" turns off an option on by default; "--KEY" turns one on.
      if (args.flag(name)) return nlohmann::json(name.rfind("no-", 0) != 0);
      return std::nullopt;
    case OptionKind::numbers:
      if (const auto t = args.option(name)) return nlohmann::json(parse_number_list(*t, doc.count, name));
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<nlohmann::json> option_value(Args& args, const OptionDoc& doc) {
  std::optional<nlohmann::json> value = value_under(args, doc.flag.substr(2), doc);
  if (doc.former_flag.empty()) return value;
  std::optional<nlohmann::json> former = value_under(args, doc.former_flag.substr(2), doc);
  if (value && former) args.fail(doc.flag + " and " + doc.former_flag + " are the same option, given twice");
  return value ? value : former;
}

}  // namespace furrow::cli
