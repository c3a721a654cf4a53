#pragma once
// Part files (docs/architecture.md "Files", docs/formats.md "Part JSON").
//
// Geometry is converted to millimetres at this boundary ("units": "inch"
// multiplies coordinates by 25.4; knots and weights are unit-free). Writing
// always produces millimetres, with every double in its shortest exact text,
// so read(write(part)) reproduces the part bit for bit.
//
// Errors are InputError naming the file and the field: "part.json:
// faces[1].knots_v: expected 9 knots (5 control points + degree 3 + 1), got 8".
#include <string>

#include "base/json_fields.hpp"
#include "geometry/part.hpp"

namespace furrow {

// Reads a part from any supported file: .json natively, CAD files (.step,
// .stp, .iges, .igs) through the CAD importer with its default options
// (cad_import.hpp).
Part read_part(const std::string& path);

Part read_part_json(const std::string& path);
// `name` stands for the source in error messages.
Part parse_part_json(const std::string& text, const std::string& name);

std::string part_to_json_text(const Part& part);
void write_part_json(const Part& part, const std::string& path);

// A face's "analytic" member as the part file spells it (docs/formats.md
// "Analytic surfaces"); `furrow info --json` and report.json use the same.
json_fields::json analytic_json(const AnalyticSurface& a);

// Conversion factor from a units name to millimetres ("mm" -> 1, "inch" ->
// 25.4); throws InputError naming `where` for anything else.
double units_to_mm(const std::string& units, const std::string& where);

}  // namespace furrow
