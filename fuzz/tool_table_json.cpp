// Fuzz target: the tool-table JSON reader (docs/testing.md "Fuzz targets").
// Tool files the table names are looked for in a folder that does not
// exist, so every such name is refused without reading anything.
#include "fuzz_reader.hpp"
#include "io/machining/tool_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_tool_table_json(text, "table.json", "/nonexistent-furrow-fuzz-folder");
  });
}
