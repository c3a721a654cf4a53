#pragma once
// Command-line arguments of one subcommand, validated up front.
//
// Options are `--name value` or `--name=value`; flags are `--name`. Every
// accessor consumes what it reads; finish() then rejects anything left over
// (an unknown option, a stray value), so a typo never runs silently with
// defaults. All errors are InputError("furrow CMD: ...") => exit status 2.
//
// Contract for commands: read every option and flag first, then the
// positionals. A word is only known to be an option's value once the option
// has been read, so positionals taken earlier could swallow it.
#include <optional>
#include <string>
#include <vector>

namespace furrow::cli {

class Args {
 public:
  Args(std::string command, std::vector<std::string> words);

  const std::string& command() const { return command_; }
  bool wants_help() const;

  // Next positional argument; `what` names it in the error when missing.
  std::string positional(const std::string& what);
  std::optional<std::string> optional_positional();

  std::optional<std::string> option(const std::string& name);
  std::string option_or(const std::string& name, const std::string& fallback);
  std::string required_option(const std::string& name);
  bool flag(const std::string& name);
  // Every value of an option that may be given several times, in order.
  std::vector<std::string> repeated_option(const std::string& name);

  // Numeric options: finite, with optional bounds checked here.
  std::optional<double> number(const std::string& name);
  double number_or(const std::string& name, double fallback);
  double positive_or(const std::string& name, double fallback);
  double non_negative_or(const std::string& name, double fallback);
  std::optional<long> integer(const std::string& name);
  long integer_or(const std::string& name, long fallback, long min_value);

  // Throws when an argument was not consumed.
  void finish() const;

  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::string command_;
  std::vector<std::string> words_;
  std::vector<bool> used_;
};

// Parses a comma-separated list of numbers of the given count.
std::vector<double> parse_number_list(const std::string& text, std::size_t count,
                                      const std::string& option);

}  // namespace furrow::cli
