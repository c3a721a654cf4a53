// Fuzz target: the comparison JSON reader (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "inspection/comparison_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_comparison(text, "comparison.json");
  });
}
