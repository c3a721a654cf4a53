// Fuzz target: the strict reader of Furrow's DMIS programs (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/cmm/dmis_program_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_dmis_program(text, "program.dmi");
  });
}
