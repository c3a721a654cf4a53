#pragma once
// The standards' own artifacts that the tests check Furrow's files against:
// the official QIF 3.0 XSD set, NIST's I++ DME test files and NIST's I++ DME
// context checker. They are not part of the project; they sit in `shared/`
// beside the checkout (CI lays it there too). A test that needs one must fail,
// not skip, when it is missing: standards_path() throws then, naming the path.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace furrow::test {

// `relative` below shared/, e.g. "standards/qif-3.0/QIFDocument.xsd" or
// "tools/nist-ippdme-checker/check". Throws std::runtime_error when it does
// not exist (the test then fails with that message).
inline std::string standards_path(const std::string& relative) {
  const auto path = std::filesystem::path(FURROW_SOURCE_DIR).parent_path() / "shared" / relative;
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + " is missing: the standards' artifacts must lie in shared/ beside "
                             "the checkout (docs/testing.md \"Standards' artifacts\")");
  return path.string();
}

}  // namespace furrow::test
