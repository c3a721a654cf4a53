// Modules loaded on demand (base/runtime_module.hpp): found next to the
// program, refused when they are not Furrow modules, named with every place
// looked at when missing; and OpenCASCADE is in the process only once the CAD
// module is loaded (this test program links no OpenCASCADE itself).
#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "base/runtime_module.hpp"
#include "io/cad/cad_module.hpp"

using namespace furrow;

namespace {

// Whether a shared object whose file name starts with `prefix` is mapped into
// this process, read from the kernel's own list (an oracle outside the loader
// code under test).
bool mapped(const std::string& prefix) {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    const std::size_t slash = line.rfind('/');
    if (slash != std::string::npos && line.compare(slash + 1, prefix.size(), prefix) == 0) return true;
  }
  return false;
}

std::string message_of(const std::string& name, const std::string& variable) {
  try {
    runtime_module_symbol(name, variable, "a test module", "furrow_module_version");
  } catch (const RuntimeModuleError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the CAD module is found next to the program, and OpenCASCADE arrives only with it") {
  ::unsetenv(cad::kModuleOverride);
  CHECK_FALSE(mapped("libTKernel"));
  CHECK_FALSE(mapped("furrow_cad.so"));
  using VersionFn = const char* (*)();
  const auto version = reinterpret_cast<VersionFn>(
      runtime_module_symbol(cad::kModuleName, cad::kModuleOverride, "the CAD reader", "furrow_module_version"));
  REQUIRE(static_cast<bool>(version));
  CHECK(std::string(version()) == FURROW_VERSION);
  CHECK(runtime_module_symbol(cad::kModuleName, cad::kModuleOverride, "the CAD reader", cad::kImportEntry) != nullptr);
  CHECK(mapped("furrow_cad.so"));
  CHECK(mapped("libTKernel"));
  // A symbol the module does not have is an error naming it, not a null pointer.
  CHECK_THROWS_WITH_AS(runtime_module_symbol(cad::kModuleName, cad::kModuleOverride, "the CAD reader", "no_such_entry"),
                       doctest::Contains("no_such_entry"), RuntimeModuleError);
}

TEST_CASE("a missing module is an error naming every place looked at") {
  ::unsetenv("FURROW_TEST_MODULE");
  const std::string message = message_of("furrow_module_that_does_not_exist", "FURROW_TEST_MODULE");
  const std::string next_to_program =
      (std::filesystem::canonical("/proc/self/exe").parent_path() / "furrow_module_that_does_not_exist.so").string();
  CHECK(message.find(next_to_program + ": no such file") != std::string::npos);
  CHECK(message.find("FURROW_TEST_MODULE") != std::string::npos);
  // The override wins over every other place.
  ::setenv("FURROW_TEST_MODULE", "/nonexistent/folder/module.so", 1);
  const std::string forced = message_of("furrow_module_that_does_not_exist_either", "FURROW_TEST_MODULE");
  ::unsetenv("FURROW_TEST_MODULE");
  CHECK(forced.find("/nonexistent/folder/module.so: no such file") != std::string::npos);
  CHECK(forced.find(next_to_program) == std::string::npos);
}

TEST_CASE("a shared object that is not a Furrow module is refused, not called") {
  // The C maths library: a real shared object without furrow_module_version.
  Dl_info info{};
  double (*cosine)(double) = &::cos;
  REQUIRE(dladdr(reinterpret_cast<void*>(cosine), &info) != 0);
  REQUIRE(info.dli_fname != nullptr);
  ::setenv("FURROW_TEST_MODULE", info.dli_fname, 1);
  const std::string message = message_of("furrow_not_a_module", "FURROW_TEST_MODULE");
  ::unsetenv("FURROW_TEST_MODULE");
  CHECK(message.find(std::string(info.dli_fname) + ": not a Furrow module") != std::string::npos);
}

TEST_CASE("a file the loader cannot read is named once with the loader's reason") {
  const std::filesystem::path empty =
      std::filesystem::path(FURROW_BINARY_DIR) / "test-scratch" / ("empty-module." + std::to_string(::getpid()) + ".so");
  std::filesystem::create_directories(empty.parent_path());
  { std::ofstream(empty.string()); }
  ::setenv("FURROW_TEST_MODULE", empty.c_str(), 1);
  const std::string message = message_of("furrow_empty_module", "FURROW_TEST_MODULE");
  ::unsetenv("FURROW_TEST_MODULE");
  std::filesystem::remove(empty);
  const std::size_t first = message.find(empty.string());
  REQUIRE(first != std::string::npos);
  CHECK(message.find(empty.string(), first + 1) == std::string::npos);
  CHECK(message.size() > message.find(empty.string() + ": ") + empty.string().size() + 2);  // a reason follows
}
