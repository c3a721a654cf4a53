#pragma once
// Where one part sits in its process, for its QA report (docs/report.md
// "Process"): when the batch is kept in a results database, each region's
// mean deviation over the latest parts with this part last, the region's
// Cpk over the process, and the Nelson rules violated at this part.
//
// The process is the database's SPC selection by region (docs/spc.md,
// results_database.hpp load_spc_input) up to this part:
// - a comparison already stored (its SHA-256 found): the parts up to its
//   serial, in production order (a serial measured again counts with its
//   latest record, as in `furrow spc`);
// - a comparison not stored yet (`furrow run` renders the report before it
//   stores the part): every stored part, then this one last; a serial
//   stored before is a re-measurement and takes this part's values in its
//   place, as SPC would once it is stored.
// So the report and a later `furrow spc --by region --serials ..SERIAL`
// give the same figures for the region.
//
// Units: mm, signed as everywhere (+ material left).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "results/results_database.hpp"

namespace furrow {

// The values a sparkline shows: this part's and the ones before it.
constexpr std::size_t kProcessRecentParts = 25;

struct RegionProcess {
  std::string region;                // region id (decimal text, as the database keys it)
  double lower = 0, upper = 0;       // the profile zone [mm]
  // The latest values up to this part, oldest first (at most
  // kProcessRecentParts), and the serials they belong to.
  std::vector<double> recent;
  std::vector<std::string> serials;
  bool has_part = false;             // the last recent value is this part's
  std::size_t n = 0;                 // values in the whole process
  std::optional<double> mean, cpk;   // over the whole process (docs/spc.md)
  std::vector<int> rules_at_part;    // Nelson rules whose violation reaches this part, ascending
};

struct ProcessContext {
  std::string source;   // the database, as the user named it
  std::string serial;   // this part's
  bool stored = false;  // this comparison was found in the database
  std::size_t parts = 0;  // parts in the process, this one included
  std::size_t position = 0;  // this part's index among them (0-based)
  std::vector<RegionProcess> regions;  // by numeric region id
};

// `part`: the record of this part's comparison (make_comparison_record).
ProcessContext process_context(ResultsDatabase& db, const ComparisonRecord& part);

}  // namespace furrow
