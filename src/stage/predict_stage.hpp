#pragma once
// The prediction stage (`furrow predict`, and `furrow run`): the machining
// error a tool path leaves on the part, as the record prediction.json holds,
// with errors per region when a partition is given, and its map as a PNG.
// One function for both callers, so a job's prediction.json is the command's.
#include <cstddef>
#include <functional>
#include <string>

#include "machining/prediction/path_prediction.hpp"
#include "machining/prediction/prediction.hpp"
#include "partition/region_map.hpp"

namespace furrow {

// How the prediction names its sources (as seen from where it is written).
struct PredictionSources {
  std::string part;
  std::string toolpath;
  std::string regions;  // used only with a region map
};

struct PredictedPath {
  PathPrediction computed;  // the full-resolution result (z-map, error map)
  Prediction record;        // what prediction.json holds
  std::string json;         // prediction.json's text
};

// `tools`: the cutter of every pass and rapid (machining/cutter/path_tools.hpp).
// `regions` may be null (no per-region errors). `progress` is
// path_prediction.hpp's (step, done, total).
PredictedPath predict_stage(const Part& part, const PathTools& tools, const Toolpath& path,
                            const PathPredictionOptions& options, const PredictionSources& names,
                            const RegionMap* regions, const StageProgress& progress = {});

// The error map as a PNG; `scale` [mm] is where the colours saturate, 0 for
// the default of twice the tolerance. The largest furrow along a pass (F),
// cusp (C) and ridge (R) between passes are marked where they are and
// given in notes under the legend.
std::string prediction_map_png(const Part& part, const PredictedPath& predicted, const PathPredictionOptions& options,
                               double scale);

}  // namespace furrow
