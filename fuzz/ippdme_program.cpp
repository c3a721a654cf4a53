// Fuzz target: the strict reader of Furrow's I++ DME programs (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/cmm/ippdme_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_ippdme_program(text, "program.prg");
  });
}
