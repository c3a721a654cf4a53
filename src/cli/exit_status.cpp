#include "cli/commands.hpp"

namespace furrow::cli {

int exit_status(Verdict verdict, const std::string& alignment) {
  if (alignment != "ok") return kExitInternal;
  switch (verdict) {
    case Verdict::pass:
      return kExitOk;
    case Verdict::inconclusive:
      return kExitInconclusive;
    case Verdict::fail:
      break;
  }
  return kExitFail;
}

}  // namespace furrow::cli
