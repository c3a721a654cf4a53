#pragma once
// The few lines `furrow spc` prints on standard output (docs/spc.md
// "Summary"): the counts, the worst characteristics, and what is violated
// at the latest part — the reason for the exit status, said in words.
#include <cstddef>
#include <string>

#include "results/spc_statistics.hpp"

namespace furrow {

// At most `worst` characteristics are listed, worst first. Ends with a newline.
std::string spc_summary(const SpcResult& result, std::size_t worst = 5);

}  // namespace furrow
