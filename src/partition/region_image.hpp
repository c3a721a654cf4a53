#pragma once
// A figure of a partition for people: one panel per face showing its (u,v)
// domain, u to the right and v up, each cell coloured by its region's class
// (convex orange, concave blue, saddle green, planar sand; trimmed light
// grey, degenerate dark grey), region borders in black and every region's id
// at its interior point; a legend names the colours. Panels are drawn with
// the face's aspect on the surface (face_extent), not the raw parameter
// square, so the picture looks like the part seen along its normal.
//
// PNG bytes come from render/png.hpp; writing goes through
// write_file_atomically, so a failed run leaves no partial image.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "partition/partition.hpp"

namespace furrow {

// Precondition: `result` was computed for `part`.
std::vector<unsigned char> region_image_png(const Part& part, const PartitionResult& result);

}  // namespace furrow
