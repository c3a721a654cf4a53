#pragma once
// A figure of a partition for people: the part in four views (top, front,
// right side, isometric; render/part_views.hpp), every visible surface
// point coloured by its region's class (convex orange, concave blue, saddle
// green, planar sand; a cell the partition left out light grey, a
// degenerate cell dark grey), shaded, region borders in black, face edges in grey and every
// region's id ("R3") where its interior point is seen; a legend names the
// colours. One picture whatever the number of faces.
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
