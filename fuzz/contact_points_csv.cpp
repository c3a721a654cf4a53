// Fuzz target: the contact-point CSV reader (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/machining/contact_point_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::parse_contact_points_csv(text, "points.csv");
  });
}
