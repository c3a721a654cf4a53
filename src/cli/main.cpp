// furrow: command-line entry point. Thin by design: it finds the subcommand,
// maps exceptions to exit statuses and prints errors once, on stderr.
#include <algorithm>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/manual.hpp"
#include "job/job_schema.hpp"
#include "base/error.hpp"

namespace {

using furrow::cli::Command;

const std::vector<const Command*> kCommands = {
    &furrow::cli::kInfoCommand,
    &furrow::cli::kImportCommand,
    &furrow::cli::kPartitionCommand,
    &furrow::cli::kGougeCommand,
    &furrow::cli::kSelectToolCommand,
    &furrow::cli::kToolpathCommand,
    &furrow::cli::kPredictCommand,
    &furrow::cli::kPlanCommand,
    &furrow::cli::kSimulateMeasurementCommand,
    &furrow::cli::kCompareCommand,
    &furrow::cli::kCompensateCommand,
    &furrow::cli::kRemeasureCommand,
    &furrow::cli::kReportCommand,
    &furrow::cli::kImportResultsCommand,
    &furrow::cli::kSpcCommand,
    &furrow::cli::kRunCommand,
    &furrow::cli::kDemoCommand,
};

const Command* find_command(const std::string& name) {
  for (const Command* c : kCommands)
    if (name == c->name) return c;
  return nullptr;
}

void print_overview(std::ostream& out) {
  out << "furrow " << FURROW_VERSION
      << " - inspection planning and machining-error verification of sculptured surfaces\n\n"
         "usage: furrow COMMAND [options]\n\ncommands:\n";
  for (const Command* c : kCommands) {
    std::string name = c->name;
    name.resize(std::max<std::size_t>(18, name.size() + 2), ' ');
    out << "  " << name << c->summary << "\n";
  }
  out << "\n'furrow help COMMAND' shows a command's options; 'furrow help --options' lists every stage\n"
         "option with its job-file member and default, 'furrow help --job-schema' writes the job file's\n"
         "JSON Schema.\n"
         "Exit status: 0 ok/pass, 1 fail, 2 bad input, 3 the computation did not succeed,\n"
         "4 inconclusive (nothing failed, but not everything was shown to be good).\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty() || words[0] == "help" || words[0] == "--help" || words[0] == "-h") {
    if (words.size() == 2 && words[1] == "--man") {
      furrow::cli::write_man_page(std::cout, kCommands);
      return furrow::cli::kExitOk;
    }
    if (words.size() == 2 && words[1] == "--job-schema") {
      std::cout << furrow::job_schema_json();
      return furrow::cli::kExitOk;
    }
    if (words.size() == 2 && words[1] == "--options") {
      furrow::cli::write_options_reference(std::cout);
      return furrow::cli::kExitOk;
    }
    if (words.size() == 2 && words[1] == "--completion") {
      furrow::cli::write_bash_completion(std::cout, kCommands);
      return furrow::cli::kExitOk;
    }
    if (words.size() >= 2) {
      if (const Command* c = find_command(words[1])) {
        std::cout << furrow::cli::usage_text(*c);
        return furrow::cli::kExitOk;
      }
      std::cerr << "furrow: unknown command \"" << words[1] << "\"\n";
      return furrow::cli::kExitBadInput;
    }
    print_overview(words.empty() ? std::cerr : std::cout);
    return words.empty() ? furrow::cli::kExitBadInput : furrow::cli::kExitOk;
  }
  if (words[0] == "--version" || words[0] == "version") {
    std::cout << "furrow " << FURROW_VERSION << "\n";
    return furrow::cli::kExitOk;
  }
  const Command* command = find_command(words[0]);
  if (!command) {
    std::cerr << "furrow: unknown command \"" << words[0] << "\" (see 'furrow help')\n";
    return furrow::cli::kExitBadInput;
  }
  furrow::cli::Args args(words[0], std::vector<std::string>(words.begin() + 1, words.end()));
  if (args.wants_help()) {
    std::cout << furrow::cli::usage_text(*command);
    return furrow::cli::kExitOk;
  }
  try {
    return command->run(args);
  } catch (const furrow::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return furrow::cli::kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "internal error: out of memory\n";
    return furrow::cli::kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return furrow::cli::kExitInternal;
  }
}
