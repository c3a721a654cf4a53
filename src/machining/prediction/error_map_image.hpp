#pragma once
// The error map as a picture (furrow predict --map errors.png): each face's
// (u, v) domain as an image (u to the right, v up), faces side by side, the
// error coloured on a diverging scale — blue for overcut, white for zero,
// red for material left — saturating at +-scale, with a colour bar labelled
// in micrometres. Samples the tool did not reach are light grey, samples
// that cannot be machined from above dark grey, trimmed-away areas white
// with a thin frame around each face. Markers (a ring with a label) show
// where named extremes lie, and notes under the picture give figures the
// colours cannot (furrow predict: the largest furrow along the passes, cusp
// and ridge between them, each marked where it is).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "machining/prediction/error_map.hpp"

namespace furrow {

struct MapMarker {
  std::size_t face = 0;  // index in the part
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  std::string label;     // short: drawn beside the ring
};

struct ErrorImageOptions {
  double scale = 0.02;  // [mm] colour saturation (+-)
  int max_side = 900;   // pixels along the longer side of each face's picture
  std::vector<MapMarker> markers;  // on faces the map does not have: not drawn
  std::vector<std::string> notes;  // one line each, under the legend line
};

// PNG bytes (OpenCV). Deterministic for the same map and options.
std::string error_map_png(const Part& part, const ErrorMap& map, const ErrorImageOptions& options = {});

}  // namespace furrow
