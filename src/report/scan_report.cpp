// The QA report of a scan (contract in scan_report.hpp).
#include "report/scan_report.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "base/json_fields.hpp"
#include "base/number_text.hpp"
#include "base/numbers.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/comparison_json.hpp"
#include "render/drawing_raster.hpp"
#include "render/svg.hpp"
#include "report/figures.hpp"
#include "report/html.hpp"
#include "report/part_outlines.hpp"
#include "report/part_view_3d.hpp"
#include "report/region_map_figure.hpp"
#include "report/report_figures.hpp"

namespace furrow {

namespace jf = json_fields;
using html::escape;
using nlohmann::json;

namespace {

std::string count(std::size_t n) { return std::to_string(n); }
std::string um(double mm) { return fixed(mm * 1000, 1) + " &micro;m"; }
json num(double v, const char* what) { return jf::finite(v, what); }

ToleranceLimits limits(const ScanComparisonDocument& s) { return {s.tolerance.lower(), s.tolerance.upper()}; }

// The rotation of the registration in degrees (the angle of its rotation
// part), as a metrologist reads "how far was the scan turned".
double rotation_deg(const Eigen::Matrix4d& m) {
  const double c = std::clamp((m.topLeftCorner<3, 3>().trace() - 1) / 2, -1.0, 1.0);
  return degrees(std::acos(c));
}

std::string sample_text(const ScanComparisonDocument& s) {
  const ScanDisplay& d = s.display;
  if (d.voxel == 0)
    return "every evaluated point (" + count(d.points.size()) + ")";
  return count(d.points.size()) + " of " + count(s.summary.evaluated) + " evaluated points, one per occupied " +
         fixed(d.voxel, 3) + " mm voxel: the one with the largest |deviation| (at most " + count(d.cap) + ")";
}

}  // namespace

ComparisonDocument scan_as_comparison(const ScanComparisonDocument& s) {
  ComparisonDocument d;
  d.version = kComparisonFormatVersion;
  d.sources.part = s.sources.part;
  d.sources.measurements = s.sources.scan;
  d.sources.regions = s.sources.regions;
  d.sources.measurement_files.push_back({s.sources.scan, s.points.read, ""});
  d.options = s.fit_options;
  ComparisonDocument::Registration& r = d.registration;
  r.transform = s.registration.transform;
  r.coarse_method = s.registration.coarse;
  r.coarse_median_distance = s.registration.coarse_median;
  r.rms_before = s.registration.rms_before;
  r.rms_after = s.registration.rms_after;
  r.sigma = s.registration.sigma;
  r.outer_iterations = s.registration.outer_iterations;
  r.converged = s.registration.converged;
  r.status = s.registration.status;
  r.outcome = s.registration.converged ? "converged"
              : s.summary.alignment == "too_few_points" ? "too_few_points"
                                                        : "not_converged";
  r.outliers = {{"off_part", s.points.off_part}, {"spray_far", s.points.spray_far}, {"spray_near", s.points.spray_near}};
  d.alignment.method = "bestfit";
  d.summary = s.summary;
  // With a prediction, the verification as the probe-point sections read
  // it: the sites' and clusters' `points` are left empty (a scan records
  // counts) and `deepest` is a cloud index; the sections that name points
  // ask context.scan for both (report_html.cpp, report_json.cpp).
  if (const auto& v = s.verification) {
    d.sources.prediction = s.sources.prediction;
    d.options.prediction = v->options;
    d.options.gouges = v->gouge_options;
    d.prediction = v->compared;
    GougeConfirmation g;
    for (const ScanGougeSite& site : v->sites) g.sites.push_back(site.check);
    for (const ScanOvercutCluster& c : v->unexplained) g.unexplained.push_back(c.cluster);
    d.gouges = std::move(g);
  }
  return d;
}

std::vector<ReportFigure> make_scan_report_figures(const ScanComparisonDocument& s, const Part& part,
                                                   const RegionMap* regions) {
  std::vector<std::function<ReportFigure()>> jobs;
  if (regions)
    jobs.push_back([&part, regions] {
      return ReportFigure{"figures/region_map.png", "regions", "Curvature regions",
                          "The partition the statistics per region use, on the part seen from the top, the front, "
                          "the right and an isometric corner (hidden surfaces removed): convex orange, concave "
                          "blue, saddle green, planar sand; region borders black, face edges grey.",
                          region_map_png("Curvature regions", part, *regions), "", ""};
    });
  jobs.push_back([&s, &part, regions] {
    std::vector<MapPoint> top;
    for (std::size_t k = 0; k < s.display.points.size(); ++k) {
      MapPoint m;
      m.position = s.display.points[k].head<2>();
      m.value = s.display.deviation[k];
      m.out_of_tolerance = m.flagged = !s.tolerance.contains(m.value);
      m.label = "#" + std::to_string(s.display.index[k]);
      top.push_back(std::move(m));
    }
    std::vector<Outline> outlines = face_outlines_xy(part);
    if (regions)
      for (Outline& o : region_borders_xy(*regions)) outlines.push_back(std::move(o));
    const Drawing drawing = deviation_map_drawing("Scan deviation [\u00b5m], top view", top, outlines, limits(s),
                                                  "x [mm]", "y [mm]", true);
    ReportFigure f{"figures/scan_deviation_top.png", "deviations", "Deviation surface of the scan, top view",
                   "The scan's deviation surface seen from above, in the part frame: " + sample_text(s) +
                       ". Red = material left, blue = overcut; a black ring marks a point outside the profile "
                       "zone, labelled with its index in the deviation cloud.",
                   to_png(drawing), "", ""};
    if (top.size() <= kVectorPointLimit) f.svg = to_svg(drawing, f.title, "fig-scan_deviation_top");
    return f;
  });
  jobs.push_back([&s] {
    const Drawing drawing =
        histogram_bins_drawing("Deviations of all " + std::to_string(s.summary.evaluated) + " evaluated points",
                               s.histogram.edges, s.histogram.counts, limits(s));
    return ReportFigure{"figures/scan_histogram.png", "deviations", "Histogram of the scan's deviations",
                        "Every evaluated point of the scan (not only the displayed sample), counted when it was "
                        "compared; the vertical lines are the limits of the profile zone.",
                        to_png(drawing), to_svg(drawing, "Histogram of the scan's deviations", "fig-scan_histogram"),
                        ""};
  });
  if (s.verification)
    jobs.push_back([&s, &part] {
      std::vector<Eigen::Vector2d> background;
      for (const Eigen::Vector3d& p : s.display.points) background.emplace_back(p.x(), p.y());
      return gouge_sites_figure(scan_as_comparison(s), part, background,
                                "grey dots are the scan's displayed points");
    });
  jobs.push_back([&s, &part] {
    ComparisonDocument view = scan_as_comparison(s);
    for (std::size_t k = 0; k < s.display.points.size(); ++k) {
      ComparisonDocument::Point p;
      p.id = "#" + std::to_string(s.display.index[k]);
      p.measured = p.registered = p.contact = p.foot = s.display.points[k];
      p.deviation = s.display.deviation[k];
      p.evaluated = true;
      p.in_tolerance = s.tolerance.contains(p.deviation);
      view.points.push_back(std::move(p));
    }
    return part_view_3d_figure(view, part, nullptr,
                               "the scan's deviation surface: " + sample_text(s) + ", each at its place in the part frame",
                               "Scan deviation surface, " + std::to_string(view.points.size()) + " points shown");
  });
  return draw_figures(jobs);
}

std::vector<FolderFile> make_scan_report(const ScanComparisonDocument& scan, const Part& part,
                                         const RegionMap* regions, const ReportContext& context) {
  ReportContext with_scan = context;
  with_scan.scan = std::make_shared<const ScanComparisonDocument>(scan);
  return render_report(scan_as_comparison(scan), regions, make_scan_report_figures(scan, part, regions), with_scan);
}

std::string scan_section_html(const ScanComparisonDocument* scan, const std::string& figures_html) {
  if (!scan) return "";
  const ScanComparisonDocument& s = *scan;
  const auto& p = s.points;
  const auto& pre = s.preprocessing;
  const auto& r = s.registration;
  std::string out = "<section id=\"scan\"><h2>Scan</h2>\n";
  out += html::key_value_table({
      {"Scan file", "<code>" + escape(s.sources.scan) + "</code> (" + escape(s.sources.scan_units) + ")"},
      {"Deviation cloud", s.sources.deviations.empty() ? std::string("not written")
                                                       : "<code>" + escape(s.sources.deviations) + "</code>"},
      {"Points read", count(p.read) + " (" + count(p.not_finite) + " not finite)"},
      {"Evaluated", count(p.kept)},
      {"Removed: spray far", count(p.spray_far)},
      {"Removed: spray near the surface", count(p.spray_near)},
      {"Removed: off the part", count(p.off_part)},
      {"Removed: seen at grazing incidence", count(p.grazing)},
      {"Spray rules", pre.spray_removal ? "on: " + fixed(pre.spray_near_sigmas, 1) + " robust sigmas off the local "
                                              "quadric of " + std::to_string(pre.normal_neighbours) +
                                              " neighbours (local sigma " + um(pre.local_plane_sigma) +
                                              "); statistical rule fired at " + count(pre.statistical_rule) +
                                              " points"
                                        : std::string("off (no point flagged)")},
      {"Fit subset", count(p.fit) + " points (one per " + fixed(pre.voxel, 3) + " mm voxel), " + count(p.in_fit) +
                         " in the fit; normals " + escape(pre.normals)},
      {"Registration", escape(r.status) + ", coarse start " + escape(r.coarse) + " (median " +
                           um(r.coarse_median) + "), RMS " + um(r.rms_before) + " &rarr; " + um(r.rms_after) +
                           ", sigma " + um(r.sigma) + ", " + std::to_string(r.outer_iterations) + " iterations"},
      {"Scanner frame &rarr; part frame", "turned " + fixed(rotation_deg(r.transform), 3) + "&deg;, moved " +
                                              fixed(r.transform.topRightCorner<3, 1>().norm(), 3) + " mm"},
      {"Shown", sample_text(s)},
  });
  out += "<p>Spray is flagged, never a reason to pass or fail; every point's deviation and flag is in the "
         "deviation cloud. The histogram counts every evaluated point.</p>\n";
  return out + figures_html + "</section>\n";
}

json scan_section_json(const ScanComparisonDocument* scan) {
  if (!scan) return nullptr;
  const ScanComparisonDocument& s = *scan;
  const auto& p = s.points;
  const auto& pre = s.preprocessing;
  const auto& r = s.registration;
  json edges = json::array();
  for (double e : s.histogram.edges) edges.push_back(num(e, "histogram edge"));
  return {{"file", s.sources.scan},
          {"units", s.sources.scan_units},
          {"deviation_cloud", s.sources.deviations.empty() ? json(nullptr) : json(s.sources.deviations)},
          {"points", {{"read", p.read},
                      {"not_finite", p.not_finite},
                      {"evaluated", p.kept},
                      {"removed", {{"spray_far", p.spray_far}, {"spray_near", p.spray_near}, {"off_part", p.off_part},
                                   {"grazing", p.grazing}}},
                      {"fit", p.fit},
                      {"in_fit", p.in_fit}}},
          {"preprocessing", {{"voxel", num(pre.voxel, "voxel")},
                             {"spray_removal", pre.spray_removal},
                             {"spray_neighbours", pre.spray_neighbours},
                             {"spray_far_sigmas", num(pre.spray_far_sigmas, "spray_far_sigmas")},
                             {"spray_near_sigmas", num(pre.spray_near_sigmas, "spray_near_sigmas")},
                             {"normal_neighbours", pre.normal_neighbours},
                             {"local_plane_sigma", num(pre.local_plane_sigma, "local_plane_sigma")},
                             {"statistical_rule", pre.statistical_rule},
                             {"normals", pre.normals}}},
          {"registration", {{"status", r.status},
                            {"converged", r.converged},
                            {"coarse", r.coarse},
                            {"coarse_median", num(r.coarse_median, "coarse_median")},
                            {"rms_before", num(r.rms_before, "rms_before")},
                            {"rms_after", num(r.rms_after, "rms_after")},
                            {"sigma", num(r.sigma, "sigma")},
                            {"outer_iterations", r.outer_iterations},
                            {"rotation_deg", num(rotation_deg(r.transform), "rotation")},
                            {"transform", comparison_json::matrix_json(r.transform, "transform")}}},
          {"histogram", {{"edges", std::move(edges)}, {"counts", s.histogram.counts}}},
          {"display", {{"cap", s.display.cap},
                       {"voxel", num(s.display.voxel, "display voxel")},
                       {"points", s.display.points.size()},
                       {"figure", "figures/scan_deviation_top.png"}}}};
}

}  // namespace furrow
