#pragma once
// Everything `furrow predict` computes for a tool path, in one call: the
// path located on the part (path_contacts.hpp), the exact per-step errors
// (path_steps.hpp), the z-map of the whole path (zmap.hpp), the error map
// over every face (error_map.hpp), the scallop of every pass pair
// (pass_scallops.hpp), the gouge sites (gouge_sites.hpp) and the contact
// points where the cutter gouges locally (gouge_scan.hpp, the gouge
// module's check), the rapid moves checked against the part and the stock
// (rapid_check.hpp), then the plain Prediction record (prediction.hpp) that
// prediction.json stores.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "machining/cutter/path_tools.hpp"
#include "machining/gouge/gouge_scan.hpp"
#include "machining/prediction/gouge_sites.hpp"
#include "machining/prediction/path_steps.hpp"
#include "machining/prediction/rapid_check.hpp"
#include "machining/prediction/prediction.hpp"

namespace furrow {

struct PathPredictionOptions {
  double tolerance = 0.01;     // [mm] steps are compared with it
  // Overcut deeper than this is a gouge site [mm]; 0: twice the tolerance (a
  // path planned to the tolerance overcuts up to it by design on convex
  // stretches, and a little more where its passes meet in a saddle).
  double gouge_threshold = 0;
  // Errors exceed the tolerance only by more than this [mm]: a step planned
  // to the tolerance ties with it, and the 4-decimal G-code moves a tip by
  // up to 0.05 um per axis.
  double comparison_margin = 1e-4;
  double resolution = 0;       // [mm] z-map node spacing; 0: default_zmap_resolution()
  PathContactOptions contacts;
  FurrowStepOptions step;
  ZMapOptions zmap;
  ErrorMapOptions map;  // cell_size: stored cells; sample_spacing 0: the z-map's
  PassScallopOptions scallops;
  GougeScanOptions local;
  // Raw stock box in the part frame: rapids below its top are rapid gouges
  // too (rapid_check.hpp); none: rapids are checked against the part only.
  std::optional<Eigen::AlignedBox3d> stock;
};

// `progress(stage, done, total)`; stages "locating path", "per-step errors",
// "z-map", "error map", "local gouges", "rapids".
using StageProgress = std::function<void(const std::string&, std::size_t, std::size_t)>;

struct PathPrediction {
  // The cutters of the path (shared: the z-map's envelopes point into them).
  std::shared_ptr<const PathTools> tools;
  double resolution = 0, gouge_threshold = 0;  // as used [mm]
  PathGeometry geometry;
  std::vector<StepPrediction> steps;
  std::optional<ZMap> zmap;
  ErrorMap map;
  std::vector<PassScallop> scallops;
  std::vector<GougeSite> sites;
  struct Local {
    int pass = 0, point = 0;
    GougePoint check;
  };
  std::vector<Local> local_gouges;  // contact points whose check is not clear
  RapidCheck rapids;  // the path's rapid moves against the part (and the stock)
};

// Throws InputError for invalid options (non-positive tolerance or
// resolution) and for contact-point input that does not fit the part.
//
// A program that changes tools (`tools` with several cutters) is predicted
// tool by tool where the geometry is the cutter's own: locating the path,
// the per-step errors, the local gouge check and the rapids each use the
// cutter of their pass or rapid; the scallop is measured between
// neighbouring passes of the same tool only. The z-map is the one machined
// surface every tool leaves (each move lowers it with its own cutter), so
// the error map and gouge sites are of the finished part. The default
// z-map resolution is the finest any of the cutters asks for.
PathPrediction predict_path(const Part& part, const PathTools& tools, const Toolpath& path,
                            const PathPredictionOptions& options = {}, const StageProgress& progress = {});
// One cutter for every pass and rapid.
PathPrediction predict_path(const Part& part, const Cutter& cutter, const Toolpath& path,
                            const PathPredictionOptions& options = {}, const StageProgress& progress = {});

// The record written to prediction.json; `part_name` and `toolpath_name`
// are stored as given.
Prediction make_prediction(const Part& part, const PathPrediction& result, const PathPredictionOptions& options,
                           const std::string& part_name, const std::string& toolpath_name);

}  // namespace furrow
