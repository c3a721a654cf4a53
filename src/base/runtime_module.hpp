#pragma once
// Parts of Furrow built as their own shared object and loaded the first time
// they are needed (docs/architecture.md "Modules loaded on demand").
//
// Why: OpenCASCADE is some 25 shared libraries (TBB and X11 among them) whose
// loading and static initialisation take about 45 ms, longer than everything
// else `furrow` starts with together. Only the CAD import needs it, so it
// lives in the module furrow_cad.so and every other command starts without it.
//
// A module named NAME is looked for, first found wins:
//   1. the file the environment variable `override_variable` names, when set
//      and not empty (packagers, and tests that try a missing module);
//   2. NAME.so next to the program or shared library that holds furrow_core
//      (the build tree);
//   3. NAME.so in the module folder of an installed furrow, reached from that
//      same folder (bin/ or lib/), so an installed tree can be moved.
// The module must come from the same Furrow version: it exports
// `furrow_module_version()` and a module of another version is refused,
// because the C++ structures passed through it have no stable binary layout.
// A loaded module stays loaded until the process ends; loading is thread-safe
// and happens once per name.
//
// Failures: RuntimeModuleError (a std::runtime_error: an installation fault,
// not bad input) naming every file tried and why each failed, or the missing
// symbol. Never a null function.
#include <stdexcept>
#include <string>

namespace furrow {

class RuntimeModuleError : public std::runtime_error {
 public:
  explicit RuntimeModuleError(const std::string& message) : std::runtime_error(message) {}
};

// The address of `symbol` in module `name` (e.g. "furrow_cad"), loading the
// module on first use. `what` says what the module is for, in messages
// ("the CAD reader (STEP and IGES)").
void* runtime_module_symbol(const std::string& name, const std::string& override_variable,
                            const std::string& what, const char* symbol);

}  // namespace furrow
