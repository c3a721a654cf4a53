#pragma once
// The measured points on the part in four views (top, front, right side,
// isometric; render/part_views.hpp): the faces shaded grey with hidden
// surfaces removed, every point a dot at its foot coloured by its deviation
// on the report's scale (colour_scale.hpp, blue overcut, red material left;
// grey when not evaluated), ringed in black when out of tolerance or set
// aside, and a grey ring where the view does not see the point. A colour
// bar in micrometres with the zone's limits is the key.
//
// The 3D view's static figure (part_view_3d.hpp): what a printed report or
// a browser without WebGL shows of the part in 3D. Deterministic PNG bytes.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"

namespace furrow {

// `range` [mm] of the colour scale (> 0). `title` names the points (default:
// "Measured points, N at their foot points").
std::vector<unsigned char> deviation_views_png(const ComparisonDocument& doc, const Part& part, double range,
                                               const std::string& title = "");

}  // namespace furrow
