// Fuzz target: the G-code tool-path reader (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/machining/toolpath_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_gcode(text, "path.nc");
  });
}
