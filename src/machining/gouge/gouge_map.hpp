#pragma once
// PNG map of gouge-prone areas over each face's (u,v) domain (furrow gouge
// --map): one panel per face, u to the right and v up, side by side with the
// face's name and counts, and a legend.
//
// Grid sites fill their cell (nearest node), so the panel reads as an area
// map; sites from a point file are drawn as dots. Colours: clear light green,
// gouge red (darker with larger excess, scaled to the largest), unreachable
// from above grey, degenerate black, concave crease magenta, no site white
// (trimmed away, or not sampled). Returns the encoded PNG bytes; the caller
// writes them atomically. Deterministic for the same inputs.
#include <string>
#include <vector>

#include "machining/gouge/gouge_scan.hpp"

namespace furrow {

// `grid` is the node count per direction for grid sites (0 for point sites).
std::string gouge_map_png(const Part& part, const Cutter& cutter,
                          const std::vector<GougePoint>& points, int grid);

}  // namespace furrow
