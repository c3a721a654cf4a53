#pragma once
// A short fingerprint of a part's geometry, so that files derived from a part
// (regions.json, plans) can be checked against the part they are used with.
//
// FNV-1a (64 bit) over everything that defines a face: name, orientation,
// degrees, knots, control points, weights and trim loops, in millimetres,
// hashing the exact bits of every double. Any change of geometry changes the
// fingerprint (up to the 2^-64 chance of a collision, irrelevant here); the
// same part read twice, or read from a file Furrow wrote, gives the same one.
// Written as 16 lower-case hex digits.
#include <string>

#include "geometry/part.hpp"

namespace furrow {

std::string face_fingerprint(const Face& face);
// Over the face count and every face's fingerprint, in order.
std::string part_fingerprint(const Part& part);

}  // namespace furrow
