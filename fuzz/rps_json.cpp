// Fuzz target: the reference point system reader, the RPS file of
// furrow compare --align rps (docs/testing.md "Fuzz targets"): ids, axes
// strings and weights are checked field by field, hostile numbers refused.
#include "fuzz_reader.hpp"
#include "inspection/reference_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_reference_points(text, "rps.json");
  });
}
