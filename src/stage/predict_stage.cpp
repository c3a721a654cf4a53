#include "stage/predict_stage.hpp"

#include "machining/prediction/error_map_image.hpp"
#include "machining/prediction/prediction_file.hpp"
#include "machining/prediction/region_errors.hpp"

namespace furrow {

PredictedPath predict_stage(const Part& part, const PathTools& tools, const Toolpath& path,
                            const PathPredictionOptions& options, const PredictionSources& names,
                            const RegionMap* regions, const StageProgress& progress) {
  PredictedPath out;
  out.computed = predict_path(part, tools, path, options, progress);
  out.record = make_prediction(part, out.computed, options, names.part, names.toolpath);
  if (regions) {
    out.record.has_regions = true;
    out.record.regions_file = names.regions;
    out.record.regions = errors_by_region(part, out.computed.map, regions->regions.size(),
                                          [&](int face, double u, double v) { return regions->region_at(face, u, v); });
    for (RegionErrorRecord& r : out.record.regions)
      r.curvature_class = to_string(regions->regions[static_cast<std::size_t>(r.region)].curvature_class);
  }
  out.json = prediction_to_json_text(out.record);
  return out;
}

std::string prediction_map_png(const Part& part, const PredictedPath& predicted, const PathPredictionOptions& options,
                               double scale) {
  return error_map_png(part, predicted.computed.map, {scale > 0 ? scale : 2 * options.tolerance, 900});
}

}  // namespace furrow
