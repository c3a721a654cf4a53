// Fuzz target: the measurement reader, QIF 3.0 Results (docs/qif.md, docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/cmm/measurement_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::MeasurementReadOptions options;
    furrow::parse_measurements(text, "measurements.qif", furrow::MeasurementFormat::qif, options);
  });
}
