// Fuzz target: the measurement reader, xyz format (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/cmm/measurement_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::MeasurementReadOptions options;
    options.probe_diameter = 2;  // required for probe centres, the default kind of CSV and XYZ
    furrow::parse_measurements(text, "measurements.xyz", furrow::MeasurementFormat::xyz, options);
  });
}
