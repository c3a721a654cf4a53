#pragma once
// XYZ text (docs/formats.md "Measurements"): "x y z" or "x y z i j k" per
// line, separated by blanks, the same count on every line; '#' starts a
// comment line. Points are numbered 1, 2, ... in file order (a scan has no
// ids).
//
// Errors: InputError "FILE:LINE: ..." for a wrong field count or a bad number.
#include <string>
#include <string_view>

#include "io/cmm/measurement_file.hpp"

namespace furrow {

// Fills set.points from `text`, coordinates times `scale` (to mm).
void parse_measurements_xyz(std::string_view text, const std::string& name, double scale, MeasurementSet& set);

}  // namespace furrow
