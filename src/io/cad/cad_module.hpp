#pragma once
// The seam between furrow_core and the CAD module furrow_cad.so, which holds
// everything that includes OpenCASCADE (docs/architecture.md "Modules loaded
// on demand"). Not part of Furrow's interface: import_cad() in cad_import.hpp
// is.
//
// The module exports one C function, kImportEntry, of type ImportEntry. It
// never lets an exception out (an exception crossing dlopen'ed code is not
// something to rely on): it fills `result` and returns ModuleOutcome::ok, or
// returns another outcome with the message in `message`, which import_cad()
// turns back into the exception the module caught.
#include <string>

#include "io/cad/cad_import.hpp"

namespace furrow::cad {

enum class ModuleOutcome : int { ok = 0, input_error = 1, out_of_memory = 2, failure = 3 };

using ImportEntry = int (*)(const std::string* path, const CadImportOptions* options, CadImportResult* result,
                            std::string* message);

inline constexpr const char* kModuleName = "furrow_cad";
inline constexpr const char* kModuleOverride = "FURROW_CAD_MODULE";
inline constexpr const char* kImportEntry = "furrow_cad_import";

// The import itself, inside the module: the path's name and signature and the
// options are already checked. Throws InputError as import_cad() documents.
CadImportResult import_with_occt(const std::string& path, const CadImportOptions& options);

}  // namespace furrow::cad
