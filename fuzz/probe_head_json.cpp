// Fuzz target: the probe-head JSON reader, head.json (docs/testing.md "Fuzz
// targets"): its A/B grids are expanded from min, max and step, so hostile
// steps and ranges must be refused, never looped over.
#include "fuzz_reader.hpp"
#include "io/cmm/probe_head.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_probe_head(text, "head.json");
  });
}
