#pragma once
// Raster back end of a Drawing (render/drawing.hpp): the same items painted
// with OpenCV (anti-aliased) on white and encoded as PNG (render/png.hpp).
// For figures too large to be vector graphics in a page (maps of many
// thousand points) and for the figure files of a report folder.
//
// Text uses OpenCV's Hershey font, ASCII only: "µ" is written "u", any other
// non-ASCII byte "?". One SVG pixel is one image pixel. Deterministic bytes.
#include <vector>

#include "render/drawing.hpp"

namespace furrow {

std::vector<unsigned char> to_png(const Drawing& drawing);

}  // namespace furrow
