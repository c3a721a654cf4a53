#pragma once
// The shared body of every fuzz target (docs/testing.md "Fuzz targets").
//
// A reader must answer any input either with a value or with an InputError
// (docs/architecture.md "Conventions", Errors): that is the one expected
// rejection. Any other exception is a bug, so it is reported and the process
// aborts, which libFuzzer records as a crash with the input that caused it;
// crashes, sanitizer reports and hangs (-timeout) are caught by libFuzzer
// itself.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include "base/error.hpp"

namespace furrow_fuzz {

template <class Reader>
int run_reader(const std::uint8_t* data, std::size_t size, Reader&& read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const furrow::InputError&) {
    // Rejected with a message for the user: the expected outcome of bad input.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: the reader threw an exception other than InputError: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: the reader threw a non-standard exception\n");
    std::abort();
  }
  return 0;
}

}  // namespace furrow_fuzz
