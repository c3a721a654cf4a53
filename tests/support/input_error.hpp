#pragma once
// The message of the InputError a reader throws, for tests that check the
// wording of a refusal: empty when the call accepted its input. Any other
// exception propagates and fails the test as what it is.
#include <string>

#include "base/error.hpp"

namespace furrow::test {

template <class F>
std::string input_error_of(F&& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace furrow::test
