#include "report/report_figures.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>

#include "report/figures.hpp"
#include "report/part_outlines.hpp"
#include "report/part_view_3d.hpp"
#include "report/region_map_figure.hpp"
#include "render/drawing_raster.hpp"
#include "render/svg.hpp"

namespace furrow {

namespace {

MapPoint map_point(const ComparisonDocument::Point& p, const Eigen::Vector2d& position) {
  MapPoint m;
  m.position = position;
  m.value = p.evaluated ? p.deviation : std::nan("");
  m.flagged = !p.evaluated || !p.in_tolerance.value_or(true);
  m.label = p.id;
  m.out_of_tolerance = p.evaluated && !p.in_tolerance.value_or(true);
  return m;
}

// Both back ends from the one drawing; the SVG id is the file's stem.
ReportFigure figure(const std::string& file, const std::string& section, const std::string& title,
                    const std::string& caption, const Drawing& drawing, bool vector) {
  ReportFigure f{file, section, title, caption, to_png(drawing), "", ""};
  if (vector) f.svg = to_svg(drawing, title, "fig-" + file.substr(8, file.size() - 12));
  return f;
}

ToleranceLimits limits(const ComparisonDocument& doc) {
  return {doc.options.tolerance.lower(), doc.options.tolerance.upper()};
}

// Each figure is drawn by a job of its own (data, drawing, PNG and SVG), so
// that independent figures can be drawn at once (make_report_figures).
using FigureJobs = std::vector<std::function<ReportFigure()>>;

void add_deviation_maps(const ComparisonDocument& doc, const Part& part, const RegionMap* regions,
                        FigureJobs& out) {
  out.push_back([&doc, &part, regions] {
    std::vector<MapPoint> top;
    for (const auto& p : doc.points) top.push_back(map_point(p, Eigen::Vector2d(p.foot.x(), p.foot.y())));
    std::vector<Outline> outlines = face_outlines_xy(part);
    if (regions)
      for (Outline& o : region_borders_xy(*regions)) outlines.push_back(std::move(o));
    const bool vector = top.size() <= kVectorPointLimit;
    return figure("figures/deviation_top.png", "deviations", "Deviation map, top view",
                  "Signed deviation at every measured point (foot point on the nominal surface, seen from "
                  "above): red = material left, blue = overcut; grey = not evaluated (outlier); a black "
                  "ring marks a point outside the profile zone or not evaluated; points out of tolerance are "
                  "labelled with their id and deviation.",
                  deviation_map_drawing("Deviation [\u00b5m], top view", top, outlines, limits(doc), "x [mm]",
                                        "y [mm]", true),
                  vector);
  });

  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    const bool measured = std::any_of(doc.points.begin(), doc.points.end(),
                                      [f](const auto& p) { return p.face_index == static_cast<int>(f); });
    if (!measured) continue;
    out.push_back([&doc, &part, regions, f] {
      std::vector<MapPoint> pts;
      for (const auto& p : doc.points)
        if (p.face_index == static_cast<int>(f)) pts.push_back(map_point(p, p.uv));
      const Face& face = part.faces[f];
      std::vector<Outline> uv = face_outlines_uv(face);
      if (regions)
        for (Outline& o : region_borders_uv(*regions, static_cast<int>(f))) uv.push_back(std::move(o));
      const bool vector_uv = pts.size() <= kVectorPointLimit;
      return figure("figures/deviation_uv_" + std::to_string(f) + ".png", "deviations",
                    "Deviation map on face \"" + face.name() + "\" (u, v)",
                    "The same deviations on the face's parameter domain, with its boundary" +
                        std::string(regions ? " and the region borders." : "."),
                    deviation_map_drawing("Deviation [\u00b5m] on " + face.name() + " (u, v)", pts, uv, limits(doc),
                                          "u", "v", false),
                    vector_uv);
    });
  }

  out.push_back([&doc] {
    std::vector<double> evaluated;
    for (const auto& p : doc.points)
      if (p.evaluated) evaluated.push_back(p.deviation);
    return figure("figures/histogram.png", "deviations", "Histogram of deviations",
                  "Evaluated points only; the vertical lines are the limits of the profile zone.",
                  histogram_drawing("Deviations of " + std::to_string(evaluated.size()) + " evaluated points",
                                    evaluated, limits(doc)),
                  true);
  });
}

void add_prediction_figures(const ComparisonDocument& doc, const Part& part, FigureJobs& out) {
  out.push_back([&doc] {
    std::vector<double> predicted, measured, sigma;
    for (const auto& p : doc.points)
      if (p.prediction && p.prediction->compared) {
        predicted.push_back(p.prediction->predicted);
        measured.push_back(p.prediction->measured);
        sigma.push_back(p.prediction->sigma);
      }
    return figure("figures/predicted_vs_measured.png", "prediction", "Predicted vs measured",
                  "Each compared point's predicted machining error (x) against its measured deviation after "
                  "the prediction alignment (y), with 1-sigma bars of the combined uncertainty; a perfect "
                  "prediction lies on the diagonal.",
                  scatter_drawing("Predicted vs measured error [\u00b5m]", predicted, measured, sigma),
                  predicted.size() <= kVectorPointLimit);
  });

  if (!doc.gouges) return;
  out.push_back([&doc, &part] {
    std::vector<Eigen::Vector2d> background;
    for (const auto& p : doc.points) background.emplace_back(p.foot.x(), p.foot.y());
    return gouge_sites_figure(doc, part, background, "grey dots are the measured points");
  });
}

// The measured deviations and the residual the compensated program is
// expected to leave at the same points (docs/compensation.md "Predicted
// before it is cut"), drawn as the top-view deviation map on one colour
// scale: the largest |value| of either map and the zone's limits, so a
// colour means the same micrometres in both.
void add_compensation_maps(const ComparisonDocument& doc, const Part& part, const RegionMap* regions,
                           const CompensationRecord& record, FigureJobs& out) {
  const ToleranceLimits zone = limits(doc);
  double range = std::max(std::fabs(zone.lower), std::fabs(zone.upper));
  for (const ExpectedPoint& p : record.expected.points)
    range = std::max({range, std::fabs(p.measured), std::fabs(p.residual)});
  if (!(range > 0)) range = 1e-3;
  auto map = [&doc, &part, regions, &record, zone, range](bool after) {
    std::vector<MapPoint> points;
    for (const ExpectedPoint& p : record.expected.points) {
      const ComparisonDocument::Point& c = doc.points.at(p.index);
      MapPoint m;
      m.position = Eigen::Vector2d(c.foot.x(), c.foot.y());
      m.value = after ? p.residual : p.measured;
      m.out_of_tolerance = m.value < zone.lower || m.value > zone.upper;
      m.flagged = m.out_of_tolerance;
      m.label = p.id;
      points.push_back(std::move(m));
    }
    std::vector<Outline> outlines = face_outlines_xy(part);
    if (regions)
      for (Outline& o : region_borders_xy(*regions)) outlines.push_back(std::move(o));
    const bool vector = points.size() <= kVectorPointLimit;
    if (!after)
      return figure("figures/compensation_before.png", "compensation", "Before compensation: measured deviation",
                    "The measured deviation at every point the compensation took (foot point, seen from above): "
                    "red = material left, blue = overcut; a black ring marks a point outside the profile zone. "
                    "The same colour scale as the map after compensation.",
                    deviation_map_drawing("Measured deviation [\u00b5m], top view", points, outlines, zone, "x [mm]",
                                          "y [mm]", true, range),
                    vector);
    return figure("figures/compensation_after.png", "compensation", "After compensation: expected residual",
                  "The deviation the compensated program is expected to leave at the same points: the measured "
                  "deviation plus the correction the program writes at its nearest contact (0 where it does not "
                  "cut the point). The same colour scale as the map before.",
                  deviation_map_drawing("Expected residual [\u00b5m], top view", points, outlines, zone, "x [mm]",
                                        "y [mm]", true, range),
                  vector);
  };
  out.push_back([map] { return map(false); });
  out.push_back([map] { return map(true); });
}

}  // namespace

ReportFigure gouge_sites_figure(const ComparisonDocument& doc, const Part& part,
                                const std::vector<Eigen::Vector2d>& background, const std::string& background_text) {
  std::vector<StatusItem> items;
  if (doc.gouges) {
    for (const GougeSiteCheck& site : doc.gouges->sites) {
      StatusItem it;
      it.position = site.centroid.head<2>();
      if (site.face_index >= 0 && static_cast<std::size_t>(site.face_index) < part.faces.size())
        it.outline = uv_box_outline_xy(part.faces[static_cast<std::size_t>(site.face_index)], site.uv_box);
      it.label = site.id;
      it.status = to_string(site.status);
      items.push_back(std::move(it));
    }
    for (const OvercutCluster& c : doc.gouges->unexplained) {
      StatusItem it;
      it.position = c.xyz.head<2>();
      it.label = c.id;
      it.status = "UNEXPLAINED";
      items.push_back(std::move(it));
    }
  }
  return figure("figures/gouge_sites.png", "gouges", "Gouge sites",
                "Predicted gouge sites (their extent on the surface, from above) coloured by status, "
                "unexplained overcuts (measured, not predicted) in purple; " + background_text + ".",
                status_map_drawing("Gouge sites and unexplained overcuts, top view", items, face_outlines_xy(part),
                                   background, "x [mm]", "y [mm]"),
                background.size() <= kVectorPointLimit);
}

std::vector<ReportFigure> make_report_figures(const ComparisonDocument& doc, const Part& part,
                                              const RegionMap* regions, const Prediction* prediction,
                                              const CompensationRecord* compensation, bool interactive) {
  FigureJobs jobs;
  if (regions)
    jobs.push_back([&part, regions] {
      return ReportFigure{"figures/region_map.png", "regions", "Curvature regions",
                          "The partition the plan and the statistics per region use, on the part seen from the "
                          "top, the front, the right and an isometric corner (hidden surfaces removed): convex "
                          "orange, concave blue, saddle green, planar sand; region borders black, face edges grey.",
                          region_map_png("Curvature regions", part, *regions), "", ""};
    });
  add_deviation_maps(doc, part, regions, jobs);
  if (interactive) jobs.push_back([&] { return part_view_3d_figure(doc, part, prediction); });
  if (doc.prediction) add_prediction_figures(doc, part, jobs);
  if (compensation) add_compensation_maps(doc, part, regions, *compensation, jobs);
  return draw_figures(jobs);
}

std::vector<ReportFigure> draw_figures(const std::vector<std::function<ReportFigure()>>& jobs) {
  std::vector<ReportFigure> out(jobs.size());
  std::vector<std::exception_ptr> failed(jobs.size());
  const int n = static_cast<int>(jobs.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < n; ++k) {
    try {
      out[static_cast<std::size_t>(k)] = jobs[static_cast<std::size_t>(k)]();
    } catch (...) {
      failed[static_cast<std::size_t>(k)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace furrow
