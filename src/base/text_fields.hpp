#pragma once
// Small text helpers shared by every reader of plain-text inputs (CSV,
// G-code, command-line values), so that a number or a file extension means
// the same thing everywhere.
#include <string>

namespace furrow {

// True when the whole of `text` is one finite number (strtod syntax, no
// leading or trailing characters, no overflow); the value goes to `out`.
bool parse_finite(const std::string& text, double& out);

// `text` without leading and trailing blanks (space, tab, CR, LF).
std::string trim(const std::string& text);

// ASCII lower case.
std::string to_lower(std::string text);

// A path's extension in lower case, with the dot (".json"; "" when none).
std::string lower_extension(const std::string& path);

}  // namespace furrow
