#pragma once
// Error types shared by every module.
//
// InputError is thrown for anything the user can fix: a malformed file, an
// invalid option, an inconsistent surface. Its message names the file, the line
// or the field, so the CLI prints it as is and exits with status 2. Numerical
// non-convergence is never an exception: routines report it in their result.
#include <stdexcept>
#include <string>

namespace furrow {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace furrow
