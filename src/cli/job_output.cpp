#include "cli/job_output.hpp"

#include <cstdio>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/terminal_progress.hpp"
#include "job/pipeline.hpp"

namespace furrow::cli {

int run_and_report(const Job& job, std::ostream& out, const ProcessLookup& process) {
  TerminalProgress progress;
  const PipelineResult result = run_job(job, [&](const std::string& stage, std::size_t done, std::size_t total) {
    progress.update(stage, done, total);
  }, process);
  progress.finish();
  if (result.compensation_refused) {  // nothing written, like furrow compensate (docs/compensation.md "Safety")
    std::cerr << "furrow run: " << result.compensation_message << "\n";
    return kExitInternal;
  }
  write_job_output(job, result);
  for (const std::string& line : result.summary) out << line << "\n";
  out << "stage times:";
  char buf[64];
  for (const StageTime& t : result.stages) {
    std::snprintf(buf, sizeof buf, " %s %.2f s;", t.stage.c_str(), t.seconds);
    out << buf;
  }
  std::snprintf(buf, sizeof buf, " total %.2f s\n", result.total_seconds);
  out << buf;
  if (result.measured)
    out << "report: " << job.output << "/report.html\n";
  else
    out << "plan: " << job.output << "/plan/ (no measurements, no report)\n";
  // Without measurements the job's outcome is the plan's: a region left
  // uncovered fails it like `furrow plan` (docs/cmm.md "Coverage"); with
  // them the verdict already counts such regions as not inspected.
  const int status = result.measured ? exit_status(result.verdict, result.alignment)
                                     : (result.plan_complete || job.plan_allow_uncovered ? kExitOk : kExitFail);
  // A rapid into the part or the stock fails the job as it fails `furrow
  // predict`, whatever the measurement says; a failed computation (3) stays.
  if (result.rapid_gouges > 0 && (status == kExitOk || status == kExitInconclusive)) return kExitFail;
  return status;
}

}  // namespace furrow::cli
