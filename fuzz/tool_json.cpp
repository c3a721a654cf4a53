// Fuzz target: the single-tool JSON reader (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/machining/tool_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_tool_json(text, "tool.json");
  });
}
