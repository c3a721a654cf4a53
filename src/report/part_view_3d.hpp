#pragma once
// The report's interactive 3D colour map (docs/report.md "3D view"): the
// part's faces tessellated and shaded, every measured point a sphere
// coloured by its deviation on the same scale as the 2D figures
// (colour_scale.hpp, range = max(|tolerance limits|, max |deviation|)), and,
// with a machining prediction, the predicted error field (the z-map error
// map, Prediction::predicted_error_at) as a colour map on the faces that a
// check box switches on. Orbit, zoom, preset views and reset.
//
// The page stays one self-contained file that opens offline: three.js
// (Debian's libjs-three, r111) and its OrbitControls are read from
// FURROW_THREE_DIR at run time and inlined (about 0.9 MB); the data are a
// JSON block. Spheres are instanced (one draw call); beyond 20 000 points
// each is a shaded point sprite (one vertex, still one draw call), so
// 100 000 points stay interactive. Without WebGL (or without script) the section shows static
// views instead: the front view (x, z) drawn here and the top view of the
// Deviations section.
//
// For automated checks the viewer writes data-view3d on its section:
// "drawn:N" (N canvas pixels differing from the background after the first
// frame), "fallback:REASON" without WebGL, "error:MESSAGE" if it failed;
// data-view3d-frame-ms the time of a second frame (how interactive it is).
// Deterministic: the same inputs give the same bytes.
#include <array>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "machining/prediction/prediction.hpp"
#include "render/colour_scale.hpp"
#include "report/report_figures.hpp"

namespace furrow {

// What the viewer draws, computed here (so tests check the numbers, not
// the script). Positions in the part frame [mm].
struct PartView3d {
  struct FaceMesh {
    std::string name;
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;  // indices into vertices; only triangles kept by the trim
    std::vector<Rgb> predicted;                 // per vertex, with a prediction (grey where not reached)
  };
  std::vector<FaceMesh> faces;
  std::vector<Eigen::Vector3d> points;  // foot points, in measurement order
  std::vector<Rgb> colours;             // per point: DeviationScale{range}.colour(deviation); grey if not evaluated
  double range = 0;                     // [mm] of the deviation scale
  double sphere_radius = 0;             // [mm]
  bool has_prediction = false;
  // With gouge confirmation (doc.gouges): every predicted site and every
  // unexplained overcut as a wire sphere coloured by its status (the
  // colours of the gouge-site figure, status_colour), labelled with its id.
  // A site's sphere is centred on its centroid and holds the corners of
  // its (u, v) box on the surface; an unexplained cluster's on its deepest
  // point, 4 sphere radii across (its extent is not in the document).
  struct Marker {
    std::string label, status;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0;  // [mm]
    Rgb colour{0, 0, 0};
  };
  std::vector<Marker> markers;
};

// Tessellation: `grid` x `grid` cells per face's parameter rectangle.
PartView3d part_view_3d(const ComparisonDocument& doc, const Part& part, const Prediction* prediction,
                        int grid = 48);

// The JSON the viewer reads (numbers rounded to 1 µm / 4 digits).
std::string part_view_3d_json(const PartView3d& view);

// The report figure: `html` is the whole section (viewer, data, static
// fallback), `png`/`svg` the static front view. The markers are listed
// under the view and drawn on it; a check box hides them. Throws std::runtime_error
// naming the missing file when three.js is not installed.
// `points_text` says in the caption what the points are (default: "every
// measured point as a sphere at its foot point"; a scan's display sample
// says so), `static_title` titles the static views (deviation_views.hpp).
ReportFigure part_view_3d_figure(const ComparisonDocument& doc, const Part& part, const Prediction* prediction,
                                 const std::string& points_text = "", const std::string& static_title = "");

// Where three.js is read from (FURROW_THREE_DIR, set by CMake).
std::string three_js_directory();

}  // namespace furrow
