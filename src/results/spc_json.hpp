#pragma once
// spc.json: every figure of an SPC computation, the parts it covered and
// the selection that chose them (docs/formats.md "spc.json").
//
// Deterministic: the same result and selection give the same bytes (keys
// sorted, numbers in their shortest round-trip text, characteristics by
// id). Absent figures are null, never a non-finite number.
#include <map>
#include <string>

#include "results/spc_statistics.hpp"

namespace furrow {

// How the parts were chosen, as the command that read them knows it.
struct SpcSelection {
  std::string source;                          // what was read: the database file, or its connection name
  std::map<std::string, std::string> criteria;  // selection option -> value as given (empty: every part)
};

std::string spc_json(const SpcResult& result, const SpcSelection& selection);

}  // namespace furrow
