// Fuzz target: the measurement reader, I++ DME sessions of every layout
// (.res, plain and time-stamped logs; docs/testing.md "Fuzz targets"), with
// the format told by content as `furrow compare` tells it.
#include "fuzz_reader.hpp"
#include "io/cmm/measurement_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    furrow::MeasurementReadOptions options;
    options.probe_diameter = 2;  // for answers without ER()
    furrow::measurement_format_from_path("measurements.txt", text);
    furrow::parse_measurements(text, "measurements.log", furrow::MeasurementFormat::ippdme_log, options);
  });
}
