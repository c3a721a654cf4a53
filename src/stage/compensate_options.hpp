#pragma once
// The options of compensation (`furrow compensate`), described once
// (base/option_table.hpp). docs/compensation.md says what each one does.
#include <optional>

#include "base/option_table.hpp"

namespace furrow {

struct CompensateOptions {
  double gain = 1;          // share of the measured error taken off, in (0, 2]
  double max_offset = 0.2;  // [mm] largest offset applied, > 0
  std::optional<double> smoothing;  // [mm] fixed smoothing length; unset: GCV
  // Rounds of the clip-back (docs/compensation.md "Safety"): each halves
  // the offsets of the moves the z-map check blames; after this many the
  // program is refused (exit 3). 0: refused at the first failed check.
  int clip_back = 8;
  // Write a rework program instead of the full one (docs/compensation.md
  // "Rework"): only where the field says material is left beyond
  // rework_threshold, unset: the upper limit of the comparison's tolerance.
  bool rework = false;
  std::optional<double> rework_threshold;  // [mm], >= 0; only with rework
};

const OptionTable<CompensateOptions>& compensate_option_table();

}  // namespace furrow
