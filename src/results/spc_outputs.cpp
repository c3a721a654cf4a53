#include "results/spc_outputs.hpp"

#include "base/atomic_file.hpp"
#include "results/spc_html.hpp"
#include "results/spc_qif.hpp"

namespace furrow {

std::vector<SpcOutputFile> render_spc(const SpcResult& result, const SpcSelection& selection) {
  std::vector<SpcOutputFile> files;
  files.push_back({"spc.html", spc_html(result, selection)});
  files.push_back({"spc.qif", spc_qif(result, selection)});
  files.push_back({"spc.json", spc_json(result, selection)});
  return files;
}

void stage_spc_outputs(OutputSet& outputs, const std::string& out_dir, const SpcResult& result,
                       const SpcSelection& selection) {
  const std::vector<SpcOutputFile> files = render_spc(result, selection);  // before staging: nothing on failure
  const std::string staging = outputs.folder(out_dir);
  for (const SpcOutputFile& f : files) write_file_atomically(staging + "/" + f.name, f.bytes);
}

void write_spc_outputs(const SpcResult& result, const SpcSelection& selection, const std::string& out_dir) {
  OutputSet outputs;
  stage_spc_outputs(outputs, out_dir, result, selection);
  outputs.publish();
}

}  // namespace furrow
