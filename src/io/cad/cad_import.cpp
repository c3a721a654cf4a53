// CAD import (contract in cad_import.hpp): what needs no CAD kernel (option
// and file checks, outward rules) is here; the import itself runs in the
// module furrow_cad.so, loaded on the first import (cad_module.hpp).
#include "io/cad/cad_import.hpp"

#include <new>
#include <stdexcept>
#include <string>

#include "base/error.hpp"
#include "base/number_text.hpp"
#include "base/runtime_module.hpp"
#include "base/text_fields.hpp"
#include "io/cad/cad_file_format.hpp"
#include "io/cad/cad_module.hpp"

namespace furrow {

const char* to_string(CadFaceOrientation basis) {
  switch (basis) {
    case CadFaceOrientation::solid: return "solid";
    case CadFaceOrientation::closed_shell: return "closed_shell";
    case CadFaceOrientation::rule: return "rule";
    case CadFaceOrientation::file: return "undecided";
  }
  return "?";
}

OutwardRule parse_outward_rule(const std::string& text, const std::string& where) {
  OutwardRule rule;
  if (text == "+z" || text == "z") {
    rule.kind = OutwardRule::Kind::plus_z;
  } else if (text == "-z") {
    rule.kind = OutwardRule::Kind::minus_z;
  } else if (text.rfind("point:", 0) == 0) {
    rule.kind = OutwardRule::Kind::away_from_point;
    std::string rest = text.substr(6) + ",";
    int count = 0;
    for (std::size_t comma; (comma = rest.find(',')) != std::string::npos; rest.erase(0, comma + 1)) {
      double value = 0;
      if (count == 3 || !parse_finite(trim(rest.substr(0, comma)), value))
        throw InputError(where + ": " + quote_field(text) + " is not point:x,y,z with three finite numbers (mm)");
      rule.point[count++] = value;
    }
    if (count != 3)
      throw InputError(where + ": " + quote_field(text) + " is not point:x,y,z with three finite numbers (mm)");
  } else {
    throw InputError(where + ": " + quote_field(text) + " is not an outward rule (+z, -z or point:x,y,z)");
  }
  return rule;
}

bool is_cad_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

CadImportResult import_cad(const std::string& path, const CadImportOptions& options) {
  // Above a millimetre sewing would join the edges of neighbouring features
  // (a boss to its hole) and call faces closed that are not.
  if (!(options.sewing_tolerance >= 0 && options.sewing_tolerance <= kMaxSewingTolerance))
    throw InputError(path + ": the sewing tolerance must lie between 0 and 1 mm, got " +
                     general(options.sewing_tolerance, 3) + " mm");
  cad::check_signature(path, cad::format_of(path));
  const auto entry = reinterpret_cast<cad::ImportEntry>(runtime_module_symbol(
      cad::kModuleName, cad::kModuleOverride, "its CAD reader (STEP and IGES through OpenCASCADE)", cad::kImportEntry));
  CadImportResult result;
  std::string message;
  switch (static_cast<cad::ModuleOutcome>(entry(&path, &options, &result, &message))) {
    case cad::ModuleOutcome::ok: return result;
    case cad::ModuleOutcome::input_error: throw InputError(message);
    case cad::ModuleOutcome::out_of_memory: throw std::bad_alloc();
    case cad::ModuleOutcome::failure: break;
  }
  throw std::runtime_error(message.empty() ? path + ": the CAD reader failed" : message);
}

}  // namespace furrow
