#pragma once
// Error types shared by every module.
//
// InputError is thrown for anything the user can fix: a malformed file, an
// invalid option, an inconsistent surface. Its message names the file, the line
// or the field, so the CLI prints it as is and exits with status 2. Numerical
// non-convergence is never an exception: routines report it in their result.
#include <stdexcept>
#include <string>
#include <utility>

namespace furrow {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// Runs `work` and returns what it returns. An InputError raised inside is
// rethrown with "`inputs`: " in front, unless its message already names one
// of them (`inputs` is "PART" or "PART with TOOLPATH"; each name separated by
// " with " is looked for). Why: a limit or an inconsistency found in the
// middle of a computation (a grid too fine, no reachable probe point) comes
// from the files the command read, and the message must name them
// (docs/architecture.md "Conventions", Errors) even though the routine that
// found it never saw a path.
template <class Work>
decltype(auto) naming_inputs(const std::string& inputs, Work&& work) {
  try {
    return std::forward<Work>(work)();
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::string separator = " with ";
    for (std::size_t begin = 0;;) {
      const std::size_t end = inputs.find(separator, begin);
      const std::string name = inputs.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
      if (!name.empty() && message.find(name) != std::string::npos) throw;
      if (end == std::string::npos) break;
      begin = end + separator.size();
    }
    throw InputError(inputs + ": " + message);
  }
}

}  // namespace furrow
