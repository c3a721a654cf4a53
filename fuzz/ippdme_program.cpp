// Fuzz target: the I++ DME program readers, the strict one of Furrow's own
// files and the one of any client's (docs/testing.md "Fuzz targets").
#include "fuzz_reader.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/cmm/ippdme_session.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return furrow_fuzz::run_reader(data, size, [](const std::string& text) {
    try {
      furrow::parse_ippdme_program(text, "program.prg");
    } catch (const furrow::InputError&) {
      // refused by the strict reader; the reader of any client's programs still runs
    }
    furrow::parse_ippdme_session(text, "program.prg");
  });
}
