#pragma once
// What `furrow import` tells the user about a CAD import: per face the
// original surface type, whether the NURBS form is exact or approximated and
// how far it is from the original, the trim loops and their accuracy, and the
// faces that were left out. Text for people, JSON (docs/formats.md "CAD
// import") for scripts; both deterministic.
#include <string>

#include "io/cad/cad_import.hpp"

namespace furrow {

std::string cad_import_report_text(const CadImportResult& result, const std::string& source,
                                   const std::string& output);
std::string cad_import_report_json(const CadImportResult& result, const std::string& source,
                                   const std::string& output);

}  // namespace furrow
