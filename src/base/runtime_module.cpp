// Finding and loading a module of Furrow (contract in runtime_module.hpp).
#include "base/runtime_module.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <vector>

#ifndef FURROW_VERSION
#error "FURROW_VERSION must be defined by the build"
#endif
// Relative paths from an installed bin/ and lib/ to the module folder
// (CMakeLists.txt, from the install layout).
#ifndef FURROW_MODULE_DIR_FROM_BIN
#define FURROW_MODULE_DIR_FROM_BIN "../lib/furrow"
#endif
#ifndef FURROW_MODULE_DIR_FROM_LIB
#define FURROW_MODULE_DIR_FROM_LIB "furrow"
#endif

namespace furrow {

namespace {

namespace fs = std::filesystem;

// The folder of the program or shared library this function was linked into.
fs::path own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&own_folder), &info) != 0 && info.dli_fname && *info.dli_fname) {
    std::error_code ec;
    const fs::path object = fs::canonical(info.dli_fname, ec);
    if (!ec) return object.parent_path();
  }
  // The main program may be reported by the name it was started with;
  // /proc/self/exe is the file itself.
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

std::vector<std::string> candidates(const std::string& name, const std::string& override_variable) {
  if (const char* forced = std::getenv(override_variable.c_str()); forced && *forced) return {forced};
  const fs::path folder = own_folder();
  const std::string file = name + ".so";
  std::vector<std::string> paths;
  for (const fs::path& p : {folder / file, folder / FURROW_MODULE_DIR_FROM_BIN / file,
                            folder / FURROW_MODULE_DIR_FROM_LIB / file}) {
    const std::string text = p.lexically_normal().string();
    bool seen = false;
    for (const auto& q : paths) seen = seen || q == text;
    if (!seen) paths.push_back(text);
  }
  return paths;
}

void* load(const std::string& name, const std::string& override_variable, const std::string& what) {
  std::string tried;
  for (const std::string& path : candidates(name, override_variable)) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      tried += "\n  " + path + ": no such file";
      continue;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* loader = dlerror();
      // The loader's message starts with the path itself; it is said once.
      std::string why = loader ? loader : "cannot be loaded";
      if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
      tried += "\n  " + path + ": " + why;
      continue;
    }
    using VersionFn = const char* (*)();
    auto version = reinterpret_cast<VersionFn>(dlsym(handle, "furrow_module_version"));
    const std::string found = version ? version() : "";
    if (found != FURROW_VERSION) {
      tried += "\n  " + path + ": " +
               (version ? "built for Furrow " + found + ", this is Furrow " FURROW_VERSION
                        : std::string("not a Furrow module (no furrow_module_version)"));
      dlclose(handle);
      continue;
    }
    return handle;
  }
  throw RuntimeModuleError("furrow could not load " + what + ", module " + name + ".so; looked at:" + tried +
                           "\n(set " + override_variable + " to the module's path if it is installed elsewhere)");
}

}  // namespace

void* runtime_module_symbol(const std::string& name, const std::string& override_variable,
                            const std::string& what, const char* symbol) {
  static std::mutex mutex;
  static std::map<std::string, void*> loaded;
  const std::lock_guard<std::mutex> lock(mutex);
  void*& handle = loaded[name];
  if (!handle) handle = load(name, override_variable, what);
  void* address = dlsym(handle, symbol);
  if (!address)
    throw RuntimeModuleError("furrow's module " + name + ".so has no " + symbol +
                             " (a module of another build?)");
  return address;
}

}  // namespace furrow
