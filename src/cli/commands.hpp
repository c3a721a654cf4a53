#pragma once
// The furrow subcommands. Each lives in its own cmd_<name>.cpp, defines one
// Command and is listed in main.cpp. A command returns the process exit
// status; bad input is thrown as InputError (status 2), never printed and
// carried on.
#include "cli/args.hpp"
#include "inspection/comparison.hpp"

namespace furrow::cli {

// Exit statuses shared by every command (also documented in README.md).
constexpr int kExitOk = 0;
constexpr int kExitFail = 1;        // the part fails inspection (out of tolerance, gouge)
constexpr int kExitBadInput = 2;    // a file, option or value the user must fix
constexpr int kExitInternal = 3;    // the computation did not succeed (or a bug)
constexpr int kExitInconclusive = 4;  // nothing failed, but not everything was shown to be good

// The exit status of a comparison: 3 when its alignment did not succeed
// (`alignment` is not "ok": the computation did not succeed, whatever else
// was found), else by the verdict: PASS 0, FAIL 1, INCONCLUSIVE 4.
int exit_status(Verdict verdict, const std::string& alignment);

struct Command {
  const char* name;
  const char* summary;  // one line for `furrow help`
  const char* usage;    // help before the stage's options (synopsis, what it does, its own options)
  int (*run)(Args& args);
  // The stage's option lines, written from its option table
  // (base/option_table.hpp), and the help that follows them; none for a
  // command without a stage table.
  std::string (*stage_options)() = nullptr;
  const char* usage_end = "";
};

// The full help of `furrow help NAME` / `furrow NAME --help`: usage, the
// stage's options, usage_end.
std::string usage_text(const Command& command);

extern const Command kInfoCommand;
extern const Command kImportCommand;
extern const Command kPartitionCommand;
extern const Command kGougeCommand;
extern const Command kSelectToolCommand;
extern const Command kToolpathCommand;
extern const Command kPredictCommand;
extern const Command kPlanCommand;
extern const Command kSimulateMeasurementCommand;
extern const Command kCompareCommand;
extern const Command kCompensateCommand;
extern const Command kRemeasureCommand;
extern const Command kReportCommand;
extern const Command kImportResultsCommand;
extern const Command kSpcCommand;
extern const Command kRunCommand;
extern const Command kDemoCommand;

}  // namespace furrow::cli
