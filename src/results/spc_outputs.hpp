#pragma once
// The SPC output folder (`furrow spc --out FOLDER`): spc.json, spc.html and
// spc.qif (docs/spc.md "Output folder"), rendered in memory and published
// as one folder through OutputSet, so a reader never sees half of it.
#include <string>
#include <vector>

#include "base/output_set.hpp"
#include "results/spc_json.hpp"
#include "results/spc_statistics.hpp"

namespace furrow {

struct SpcOutputFile {
  std::string name;   // file name inside the folder
  std::string bytes;  // whole content
};

// Every file of the folder, in publishing order (spc.json last: a reader
// that waits for it finds the others).
std::vector<SpcOutputFile> render_spc(const SpcResult& result, const SpcSelection& selection);

// Stages the folder `out_dir` in `outputs` (whose inputs the caller has
// declared, e.g. the database file); the caller publishes.
void stage_spc_outputs(OutputSet& outputs, const std::string& out_dir, const SpcResult& result,
                       const SpcSelection& selection);

// The same with an OutputSet of its own, published at once. `out_dir`
// replaces an older folder of that name as a whole.
void write_spc_outputs(const SpcResult& result, const SpcSelection& selection, const std::string& out_dir);

}  // namespace furrow
