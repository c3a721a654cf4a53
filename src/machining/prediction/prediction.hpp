#pragma once
// A machining-error prediction as later stages see it (probe planning,
// simulated measurements, gouge confirmation, the QA report): plain data,
// read from prediction.json by prediction_file.hpp, with one query,
// predicted_error_at(face, u, v). Nothing here depends on how the prediction
// was computed (path_prediction.hpp builds it from the z-map and the
// per-step predictor).
//
// The error field is stored per face as a grid of cells over the face's
// parameter rectangle (about 1 mm on the surface by default): cell
// (ci, cj) covers [u0 + ci du, u0 + (ci + 1) du] x [v0 + cj dv, ...] and
// holds, over the error-map samples inside it that the tool reached, the
// mean error and the band [max_overcut, max_undercut]. A cell that no
// reached sample falls in has a status saying why (not reached by the tool,
// trimmed away, not machinable) and no numbers.
// Sign convention (docs/architecture.md): positive = material left, negative = overcut.
// Lengths in millimetres.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "geometry/nurbs_surface.hpp"
#include "geometry/part.hpp"
#include "io/machining/tool_file.hpp"
#include "machining/prediction/error_map.hpp"

namespace furrow {

struct SurfaceLocation {
  std::string face;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
};

struct ErrorAt {
  bool found = false;  // false: nothing was evaluated (e.g. no reached sample)
  double error = 0;    // [mm]
  SurfaceLocation at;
};

struct StepRecord {
  int pass = 0, step = 0;
  std::string status;  // path_steps.hpp StepStatus names; the numbers below only when "evaluated"
  double length = 0;   // [mm] between the contact points
  ErrorAt undercut;    // largest error of the step (>= 0)
  ErrorAt overcut;     // smallest error of the step (<= 0)
  double chord_deviation = 0;  // [mm] chord estimate, for comparison
  // Whether every search of an evaluated step (roots, refinements, the
  // strip beside the curve) settled within its tolerance before its
  // iteration cap: only then are its errors the exact ones (false: the best
  // found, an extreme can be larger). Empty: not recorded (a file from
  // before it was written), which says nothing either way.
  std::optional<bool> converged;
};

// Between two adjacent passes (pass_scallops.hpp): the ridge the z-map
// keeps, and the cusp of the two passes' cutters alone.
struct ScallopRecord {
  int pass_a = 0, pass_b = 0;
  double height = 0;  // [mm] the ridge
  SurfaceLocation at;
  bool has_cusp = false;  // false: no cross-section had one, or a file from before cusps were written
  double cusp = 0;        // [mm]
  SurfaceLocation cusp_at;
};

struct GougeSiteRecord {
  int id = 0;
  std::string face;
  double depth = 0;  // [mm], positive
  SurfaceLocation deepest;
  double area = 0;  // [mm^2]
  int samples = 0;
  SurfaceLocation centroid;
  Eigen::AlignedBox3d box;
  Eigen::AlignedBox2d uv_box;
};

struct LocalGougeRecord {
  int pass = 0, point = 0, line = 0;  // path point (index in its pass) and source line
  SurfaceLocation at;
  std::string status;     // local_gouge.hpp GougeStatus name ("gouge", "concave_crease")
  double max_excess = 0;  // [1/mm] largest part-minus-cutter curvature
  std::vector<Eigen::Vector2d> directions_deg;  // (start, width) arcs from the cutter's meridian
};

// A rapid move whose cutter touches the part or enters the stock
// (rapid_check.hpp): `kind` "part" (at: the deepest point on the design
// surface, with its face and uv) or "stock" (at.xyz: the lowest tip inside
// the stock; no face).
struct RapidGougeRecord {
  int line = 0;       // source line of the rapid
  std::string kind;   // "part" or "stock"
  double depth = 0;   // [mm], positive
  SurfaceLocation at;
};

// The rapid check of the path. `written` says whether prediction.json holds
// it: only with a stock box or a rapid gouge, so that other predictions keep
// their bytes; a file without it had no rapid gouge (or was written before
// rapids were checked).
struct RapidsRecord {
  bool written = false;
  std::size_t checked = 0, unchecked = 0;
  bool has_stock = false;
  Eigen::AlignedBox3d stock;
  std::vector<RapidGougeRecord> gouges;
};

// Error summary of one region of a partition (regions.json), when given.
struct RegionErrorRecord {
  int region = 0;               // region id of the partition
  std::string face;             // its face
  std::string curvature_class;  // planar, convex, concave, saddle
  int samples = 0, reached = 0; // error-map samples in the region, and reached
  double mean = 0;              // [mm] over the reached samples
  ErrorAt max_undercut, max_overcut;  // best samples
};

struct FaceGridRecord {
  std::string name;
  ParameterDomain domain;
  int cells_u = 0, cells_v = 0;
  std::vector<ErrorCellStatus> status;  // [cj * cells_u + ci]
  std::vector<double> mean, max_undercut, max_overcut;  // same index; 0 unless reached
  // Same index: the cell's samples within one z-map cell of a swept region's
  // boundary, whose errors depend on the grid and the path's chords
  // (error_map.hpp "Boundary samples"); all 0 when the file has none.
  std::vector<int> boundary;
  // Error-map samples of the face per status (docs/formats.md
  // "prediction.json"): `not_reached` are the uncut ones, which the tool
  // never came near and which carry no number. Optional when reading (files
  // written before they were counted): has_samples is false then.
  bool has_samples = false;
  std::size_t samples_reached = 0, samples_not_reached = 0, samples_not_machinable = 0, samples_outside = 0;
};

struct ZMapRecord {
  double resolution = 0;  // [mm]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  int nx = 0, ny = 0;
  std::size_t moves = 0, cut_nodes = 0;
};

struct PredictionSummary {
  ErrorAt max_undercut, max_overcut;  // over the error map (refined)
  std::size_t steps = 0, steps_evaluated = 0, steps_over_tolerance = 0;
  double max_step_error = 0;  // [mm] largest |error| of an evaluated step, converged or not
  // Evaluated steps whose search did not converge (StepRecord::converged);
  // empty when the file does not record it.
  std::optional<std::size_t> steps_not_converged;
  // Between passes [mm], over the pass pairs: the ridge the z-map keeps
  // there (cusp plus the furrows along the passes where they meet it), and
  // the cusp alone (0 in files from before cusps were written).
  double max_scallop = 0, max_cusp = 0;
  std::size_t gouge_sites = 0, local_gouge_points = 0;
  std::size_t path_points = 0, points_without_contact = 0, points_in_air = 0, points_below_surface = 0;
  double lowest_gap = 0;  // [mm]
  std::size_t samples_reached = 0, samples_not_reached = 0, samples_not_machinable = 0;
  std::size_t samples_boundary = 0;  // error-map samples flagged boundary
};

// The per-step line of a prediction's summary ("largest error 10.0 um, 0
// steps over the tolerance"), saying how many steps did not converge and
// that their errors are not exact, or that the file does not record it.
std::string describe_step_errors(const PredictionSummary& summary);

struct PredictedError {
  ErrorCellStatus status = ErrorCellStatus::outside;  // of the cell containing (u, v)
  double value = 0;         // [mm] cell means interpolated bilinearly over reached cells
  double max_undercut = 0;  // [mm] the containing cell's band
  double max_overcut = 0;
  int cell_u = -1, cell_v = -1;
  bool reached() const { return status == ErrorCellStatus::reached; }
};

// One tool of a program that changes tools (machining/cutter/path_tools.hpp).
struct ToolUseRecord {
  int number = 0;  // the program's tool number (T n)
  ToolSpec tool;
};

struct Prediction {
  std::string part, toolpath;  // source files, as given
  ToolSpec tool;  // the tool of the first pass (the only one unless `tools` is filled)
  // A program that changes tools: its tools in order of first use, and per
  // pass the index of its tool in `tools`. Both empty for a one-tool path.
  std::vector<ToolUseRecord> tools;
  std::vector<int> pass_tools;
  double tolerance = 0, gouge_threshold = 0;  // [mm]
  ZMapRecord zmap;
  PredictionSummary summary;
  std::vector<StepRecord> steps;
  std::vector<ScallopRecord> scallops;
  std::vector<GougeSiteRecord> gouge_sites;
  std::vector<LocalGougeRecord> local_gouges;
  RapidsRecord rapids;
  bool has_regions = false;  // a regions file was given
  std::string regions_file;
  std::vector<RegionErrorRecord> regions;
  std::vector<FaceGridRecord> faces;

  // The predicted error at (u, v) of a face. Throws InputError for a face
  // the prediction does not have; (u, v) outside the face's parameter
  // rectangle gives status `outside`.
  PredictedError predicted_error_at(const std::string& face, double u, double v) const;
  // Ids of the gouge sites whose uv box contains (u, v) on that face.
  std::vector<int> gouge_sites_at(const std::string& face, double u, double v) const;
  const FaceGridRecord* find_face(const std::string& face) const;
};

// Throws InputError (naming both files) unless every face the prediction
// names is a face of the part with the same parameter domain and every
// gouge site and local gouge lies on a face of the part: a prediction of
// another part. Every stage that reads a prediction with a part calls it
// before trusting a face name.
void check_prediction_against_part(const Prediction& prediction, const Part& part,
                                   const std::string& prediction_name, const std::string& part_name);

}  // namespace furrow
