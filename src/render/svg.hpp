#pragma once
// SVG back end of a Drawing (render/drawing.hpp): one <svg> element, ready
// to be written as a file or placed inline in HTML (no XML declaration, no
// external reference, so it is the same text in both places).
//
// Coordinates are written with at most two decimals (1/100 px is below
// anything a screen or printer shows; shorter text for large maps); text is
// XML-escaped, so any id or label is safe. The element has
// viewBox="0 0 W H", width="W" height="H" and a <title>; CSS class and
// data-* attributes of items are kept. Deterministic bytes.
#include <string>

#include "render/drawing.hpp"

namespace furrow {

// `id` (optional) becomes the element's id attribute.
std::string to_svg(const Drawing& drawing, const std::string& title, const std::string& id = "");

}  // namespace furrow
