#pragma once
// The options of the machining prediction (`furrow predict`, a job's
// "prediction" section), described once (base/option_table.hpp).
//
// The colour range of the error map is not among them: it only draws a
// figure, and `furrow predict --map-scale` takes it in µm where a job's
// "map_scale" is in mm (docs/options.md says so).
#include "base/option_table.hpp"
#include "machining/prediction/path_prediction.hpp"

namespace furrow {

const OptionTable<PathPredictionOptions>& prediction_option_table();

}  // namespace furrow
