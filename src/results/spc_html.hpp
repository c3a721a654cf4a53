#pragma once
// spc.html: the SPC of a batch on one self-contained page (inline CSS and
// SVG, no script, no external reference), docs/spc.md "spc.html":
// the selection, the capability table and the I-MR charts worst first
// (lowest cpk, then most violations, then id; worst_first in
// spc_statistics.hpp), and the parts with their verdicts.
//
// The page is well-formed XML (every element closed, text escaped), so
// tools and tests can read it with an XML parser. Deterministic bytes.
#include <string>

#include "results/spc_json.hpp"
#include "results/spc_statistics.hpp"

namespace furrow {

std::string spc_html(const SpcResult& result, const SpcSelection& selection);

}  // namespace furrow
