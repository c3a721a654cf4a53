#pragma once
// Point clouds written as PLY (docs/formats.md "Point clouds (PLY)"): one
// element `vertex` whose properties are the given columns, in order, binary
// little-endian whatever the host - the layout scanner software and
// CloudCompare read and write. Coordinates stay doubles (float64) where the
// caller asks: a float's step is 7.6 um at 100 mm from the origin.
//
// Values are converted to the column's type as written (a uchar column
// takes 0..255 whole numbers). A column of another length than the first,
// a non-finite value or one out of its type's range is a programming error
// (std::invalid_argument): nothing here comes from a user.
#include <string>
#include <vector>

namespace furrow {

enum class PlyScalar { uchar, float32, float64 };

struct PlyColumn {
  std::string name;  // the property's name: "x", "nx", "intensity", ...
  PlyScalar type = PlyScalar::float64;
  std::vector<double> values;
};

// The whole file: header (format binary_little_endian 1.0, the comments,
// element vertex N, one property per column) and the records.
std::string ply_vertex_text(const std::vector<PlyColumn>& columns, const std::vector<std::string>& comments = {});

}  // namespace furrow
