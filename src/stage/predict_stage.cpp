#include "stage/predict_stage.hpp"

#include <cmath>

#include "base/number_text.hpp"
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

namespace {

std::string um(double mm) { return fixed(mm * 1000, 1) + " um"; }

}  // namespace

std::string prediction_map_png(const Part& part, const PredictedPath& predicted, const PathPredictionOptions& options,
                               double scale) {
  ErrorImageOptions image;
  image.scale = scale > 0 ? scale : 2 * options.tolerance;
  image.max_side = 900;
  // The three errors between contact points, each marked where it is
  // largest (docs/architecture.md "Scallop between passes").
  const Prediction& p = predicted.record;
  auto mark = [&](const SurfaceLocation& at, const std::string& label) {
    if (const auto face = part.find_face(at.face)) image.markers.push_back({*face, at.uv, label});
  };
  const StepRecord* furrow = nullptr;
  double furrow_size = 0;
  for (const StepRecord& s : p.steps) {
    if (s.status != "evaluated") continue;
    const double size = std::max(s.undercut.error, -s.overcut.error);
    if (!furrow || size > furrow_size) furrow = &s, furrow_size = size;
  }
  const ScallopRecord *cusp = nullptr, *ridge = nullptr;
  for (const ScallopRecord& s : p.scallops) {
    if (s.has_cusp && (!cusp || s.cusp > cusp->cusp)) cusp = &s;
    if (!ridge || s.height > ridge->height) ridge = &s;
  }
  std::string along = "along the passes (per step): ", between = "between passes: ";
  if (furrow) {
    const bool under = furrow->undercut.error >= -furrow->overcut.error;
    mark(under ? furrow->undercut.at : furrow->overcut.at, "F");
    along += "largest furrow " + um(furrow_size) + " (F)";
  } else {
    along += "no step evaluated";
  }
  if (cusp) {
    mark(cusp->cusp_at, "C");
    between += "cusp " + um(cusp->cusp) + " (C)";
  }
  if (ridge) {
    mark(ridge->at, "R");
    between += std::string(cusp ? ", " : "") + "ridge with the furrows " + um(ridge->height) + " (R)";
  }
  if (!cusp && !ridge) between += "no adjacent passes";
  image.notes = {along, between};
  return error_map_png(part, predicted.computed.map, image);
}

}  // namespace furrow
