#include "report/report_html.hpp"

#include <cmath>
#include <cstdio>

#include "report/compensation_section.hpp"
#include "report/face_summary.hpp"
#include "report/merged_surfaces.hpp"
#include "report/html.hpp"
#include "report/inspection_record_html.hpp"
#include "report/point_table_html.hpp"
#include "report/process_html.hpp"
#include "report/print_style.hpp"
#include "report/scan_report.hpp"
#include "base/number_text.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

using html::escape;
using html::TableRow;

// Micrometres with one decimal and a sign, e.g. "-118.4".
std::string um(double mm) { return signed_fixed(mm * 1000, 1); }
std::string um_or_dash(const std::optional<double>& mm) { return mm ? um(*mm) : "&ndash;"; }
std::string count(std::size_t n) { return std::to_string(n); }

const char* kStyle = R"(
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;color:#222;margin:0 auto;max-width:1120px;padding:16px 24px;line-height:1.4}
h1{font-size:1.6em;margin:0.2em 0}h2{font-size:1.25em;border-bottom:2px solid #ccc;padding-bottom:3px;margin-top:1.6em}
h3{font-size:1.05em;margin-bottom:0.3em}.meta{color:#555;margin:0}
.verdict{display:flex;gap:24px;align-items:center;border-radius:8px;padding:18px 24px;margin:16px 0;color:#fff}
.verdict.pass{background:#28963c}.verdict.fail{background:#c81e1e}.verdict.inconclusive{background:#b86e00}
.verdict .result{flex:none;font-size:3.2em;font-weight:bold;letter-spacing:0.05em;min-width:3.6em;text-align:center}.verdict.inconclusive .result{font-size:2.2em}
.verdict .facts p{margin:0.25em 0;font-size:1.05em}.verdict ul{margin:0.4em 0 0 1.2em;padding:0}
nav{font-size:0.95em;color:#555}nav a{margin-right:1em}
table{border-collapse:collapse;margin:0.6em 0;font-size:0.9em}
th,td{border:1px solid #ccc;padding:3px 8px;text-align:right;vertical-align:top}
th{background:#f0f0f0}td:first-child,th:first-child{text-align:left}
table.kv th{text-align:left;font-weight:normal;color:#444}table.kv td{text-align:left}
table.points{font-size:0.8em}table.points td{white-space:nowrap}table.files td{text-align:left}
tr.out td{background:#fde2e2}tr.outlier td{color:#888;font-style:italic}
.status{font-weight:bold;padding:1px 6px;border-radius:3px;color:#fff;white-space:nowrap}
.CONFIRMED{background:#c81e1e}.NOT_CONFIRMED{background:#28963c}.NOT_MEASURED{background:#8c8c8c}.UNEXPLAINED{background:#8232aa}
figure{margin:0.8em 0;display:inline-block;max-width:100%}figure img,figure svg{max-width:100%;height:auto;border:1px solid #ddd}
figcaption{font-size:0.85em;color:#555;max-width:900px}
code,pre{font-family:"DejaVu Sans Mono",monospace;font-size:0.85em}pre{background:#f6f6f6;padding:8px;overflow-x:auto}
.hash{font-family:"DejaVu Sans Mono",monospace;font-size:0.8em;word-break:break-all}
@media print{.verdict{-webkit-print-color-adjust:exact;print-color-adjust:exact}nav{display:none}}
)";

// Marks <body data-images-loaded="n/m"> once the page has loaded, for
// automated checks; nothing on the page depends on it.
const char* kImageCheck =
    "<script>window.addEventListener('load',function(){var im=document.images,ok=0;"
    "for(var i=0;i<im.length;i++){if(im[i].complete&&im[i].naturalWidth>0)ok++;}"
    "document.body.setAttribute('data-images-loaded',ok+'/'+im.length);});</script>\n";

std::string status_badge(const std::string& status) {
  std::string cls = status;
  for (char& c : cls)
    if (c == ' ') c = '_';
  return "<span class=\"status " + escape(cls) + "\">" + escape(status) + "</span>";
}

std::string figures_of(const std::vector<ReportFigure>& figures, const std::string& section) {
  std::string out;
  for (const ReportFigure& f : figures) {
    if (f.section != section) continue;
    if (!f.html.empty()) {  // an interactive section with its own static fallback (the 3D view)
      out += f.html;
      continue;
    }
    // Vector figures inline (crisp, text selectable); raster-only ones as PNG.
    const std::string body = f.svg.empty() ? html::embedded_png(f.png, f.title) : f.svg;
    out += "<figure>" + body + "<figcaption><b>" + escape(f.title) + ".</b> " + escape(f.caption) + " (<code>" +
           escape(f.svg.empty() ? f.file : f.svg_file()) + "</code>)</figcaption></figure>\n";
  }
  return out;
}

std::string verdict_section(const ReportVerdict& v) {
  std::string out = std::string("<section id=\"verdict\" class=\"verdict ") + (v.pass ? "pass" : v.verdict == Verdict::inconclusive ? "inconclusive" : "fail") + "\">\n";
  out += std::string("<div class=\"result\" id=\"verdict-result\">") + v.result() + "</div>\n<div class=\"facts\">\n";
  out += "<p>Profile <b>" + fixed(v.profile * 1000, 1) + " &micro;m</b> against a tolerance zone of <b>" +
         fixed(v.zone.width * 1000, 1) + " &micro;m</b> [" + um(v.zone.lower()) + ", " + um(v.zone.upper()) +
         " &micro;m] (" + escape(v.zone.disposition()) + ")</p>\n";
  out += "<p>" + count(v.out_of_tolerance) + " of " + count(v.evaluated) +
         " evaluated points out of tolerance; registration " +
         (v.registration_converged ? "converged" : "<b>not converged</b>") + "</p>\n";
  if (v.has_prediction) {
    out += "<p>Gouges: <b>" + count(v.confirmed) + " of " + count(v.sites) + "</b> predicted sites confirmed, " +
           count(v.not_confirmed) + " not confirmed, " + count(v.not_measured) + " not measured; " +
           count(v.unexplained) + " unexplained overcuts</p>\n";
    if (v.prediction_verdict) out += "<p>Machining prediction: " + escape(*v.prediction_verdict) + "</p>\n";
  } else {
    out += "<p>No machining prediction: gouges were not checked</p>\n";
  }
  if (!v.reasons.empty()) {
    out += "<ul class=\"reasons\">";
    for (const std::string& r : v.reasons) out += "<li>" + escape(r) + "</li>";
    out += "</ul>\n";
  }
  return out + "</div>\n</section>\n";
}

std::string alignment_section(const ComparisonDocument& doc) {
  const ComparisonDocument::Registration& r = doc.registration;
  std::string out = "<section id=\"alignment\"><h2>Alignment</h2>\n";
  std::vector<TableRow> rows;
  for (int i = 0; i < 4; ++i) {
    TableRow row;
    for (int j = 0; j < 4; ++j) row.cells.push_back(fixed(r.transform(i, j), j < 3 && i < 3 ? 8 : 4));
    rows.push_back(row);
  }
  out += "<h3>Transform CMM &rarr; part (row-major, mm)</h3>\n" + html::table({}, rows, "matrix");
  std::string outliers;
  for (const auto& [reason, n] : r.outliers)
    if (n > 0) outliers += (outliers.empty() ? "" : ", ") + count(n) + " " + escape(reason);
  std::vector<std::pair<std::string, std::string>> kv = {
      {"Part on the CMM (x_cmm = Rz Ry Rx x_part + t)",
       "rotation " + fixed(r.placement_rotation_deg.x(), 4) + ", " + fixed(r.placement_rotation_deg.y(), 4) + ", " +
           fixed(r.placement_rotation_deg.z(), 4) + " &deg;; translation " + fixed(r.placement_translation.x(), 4) +
           ", " + fixed(r.placement_translation.y(), 4) + ", " + fixed(r.placement_translation.z(), 4) + " mm"},
      {"Coarse start", escape(r.coarse_method) + " (" + count(static_cast<std::size_t>(r.coarse_matched_ids)) +
                           " ids matched" + (r.coarse_ambiguous ? ", ambiguous: another orientation fits as well" : "") +
                           ")"},
      {"RMS before / after", fixed(r.rms_before * 1000, 2) + " / " + fixed(r.rms_after * 1000, 2) + " &micro;m"},
      {"Residual sigma", fixed(r.sigma * 1000, 2) + " &micro;m"},
      {"Iterations", count(static_cast<std::size_t>(r.outer_iterations)) + " outer, " +
                         count(static_cast<std::size_t>(r.solver_iterations)) + " solver, " +
                         count(static_cast<std::size_t>(r.outlier_passes)) + " outlier passes"},
      {"Status", escape(r.status) + (r.converged ? "" : " <b>(not converged)</b>")},
      {"Degrees of freedom fitted", count(static_cast<std::size_t>(r.fitted_dof))},
      {"Points", count(doc.summary.points) + " measured, " + count(doc.summary.in_fit) + " in the fit, " +
                     count(doc.summary.evaluated) + " evaluated"},
      {"Outliers", outliers.empty() ? "none" : outliers},
  };
  // Only a frame other than the best fit is named: the best fit is what the rest describes.
  if (doc.alignment.method != "bestfit")
    kv.insert(kv.begin(), std::make_pair(std::string("Method"), escape(doc.alignment.method) +
                                         (doc.alignment.note.empty() ? "" : ": " + escape(doc.alignment.note))));
  for (const auto& d : doc.alignment.datums) {
    if (d.kind == "rps") {  // a reference point: its residual along the axes it fixes
      kv.push_back({"RPS point " + escape(d.label) + " (fixes " + escape(d.directions) + ")",
                    "largest residual " + fixed(d.form_error * 1000, 1) + " &micro;m"});
      continue;
    }
    kv.push_back({"Datum " + escape(d.label) + " (" + escape(d.kind) + ", " + count(d.points.size()) + " points)",
                  d.kind == "plane"  ? "flatness " + fixed(d.form_error * 1000, 1) + " &micro;m"
                  : d.kind == "line" ? "straightness " + fixed(d.form_error * 1000, 1) + " &micro;m"
                  : d.kind == "cylinder" ? "roundness " + fixed(d.form_error * 1000, 1) + " &micro;m"
                                     : "sets the last origin"});
  }
  if (r.covariance) {
    const auto& c = *r.covariance;
    const double deg = 180 / kPi;
    kv.push_back({"Transform 1-sigma",
                  "rx " + fixed(std::sqrt(c(0, 0)) * deg * 3600, 2) + "&Prime;, ry " +
                      fixed(std::sqrt(c(1, 1)) * deg * 3600, 2) + "&Prime;, rz " +
                      fixed(std::sqrt(c(2, 2)) * deg * 3600, 2) + "&Prime;; tx " + fixed(std::sqrt(c(3, 3)) * 1000, 2) +
                      ", ty " + fixed(std::sqrt(c(4, 4)) * 1000, 2) + ", tz " + fixed(std::sqrt(c(5, 5)) * 1000, 2) +
                      " &micro;m"});
    double worst = 0;
    for (const auto& p : doc.points) worst = std::max(worst, p.uncertainty.value_or(0));
    kv.push_back({"Largest deviation uncertainty from the alignment", fixed(worst * 1000, 2) + " &micro;m (1 sigma)"});
  } else {
    kv.push_back({"Covariance", escape(r.covariance_status)});
  }
  for (const auto& w : r.weak) {
    std::string text = escape(w.text) + (w.held ? ": held at the coarse start, not fitted" : ": fitted");
    text += w.sigma ? ", 1 sigma " + fixed(*w.sigma * 1000, 2) + " &micro;m of displacement at the points"
                    : ", not constrained at all by the measured surface";
    if (w.from_points) text += " <b>(the measured faces would fix it: measure more of them, or add a datum)</b>";
    kv.push_back({"Weakly constrained", text});
  }
  return out + html::key_value_table(kv) + "</section>\n";
}

// With the CMM's or the datum frame, the frame's profile (form + location)
// beside the best fit's (form alone): they answer different questions
// (docs/registration.md "Alignments").
std::string profile_text(const ComparisonDocument& doc) {
  const std::string frame = fixed(doc.summary.profile * 1000, 1) + " &micro;m";
  const auto& a = doc.alignment;
  if (a.method == "bestfit" || !a.bestfit_profile) return frame;
  const std::string name = a.method == "datums" ? "datum frame" : a.method == "rps" ? "RPS frame" : "CMM frame";
  return frame + " in the " + name +
         " (form + location); " + fixed(*a.bestfit_profile * 1000, 1) + " &micro;m best fit (form)";
}

std::string deviations_section(const ComparisonDocument& doc, const std::vector<ReportFigure>& figures) {
  const ComparisonSummary& s = doc.summary;
  std::string out = "<section id=\"deviations\"><h2>Deviations</h2>\n";
  out += html::key_value_table({
      {"Evaluated points", count(s.evaluated) + " (" + count(s.in_tolerance) + " in, " + count(s.out_of_tolerance) +
                               " out of tolerance)"},
      {"Mean / sigma", um(s.deviations.mean) + " / " + fixed(s.deviations.sigma * 1000, 1) + " &micro;m"},
      {"Min / max", um(s.deviations.min) + " / " + um(s.deviations.max) + " &micro;m"},
      {"Profile (2 max |d|)", profile_text(doc)},
  });
  return out + figures_of(figures, "deviations") + "</section>\n";
}

std::string regions_section(const ComparisonDocument& doc, const RegionMap* regions,
                            const std::vector<ReportFigure>& figures) {
  std::string out = "<section id=\"regions\"><h2>Regions</h2>\n";
  if (doc.summary.regions.empty()) return out + "<p>The points carry no region ids.</p></section>\n";
  std::vector<TableRow> rows;
  for (const RegionStatistics& r : doc.summary.regions) {
    const Region* known = regions && r.region >= 0 && static_cast<std::size_t>(r.region) < regions->regions.size()
                              ? &regions->regions[static_cast<std::size_t>(r.region)]
                              : nullptr;
    TableRow row;
    row.cells = {"R" + std::to_string(r.region),
                 known ? escape(regions->faces[static_cast<std::size_t>(known->face)].name) : "&ndash;",
                 known ? to_string(known->curvature_class) : "&ndash;",
                 known ? fixed(known->area, 1) : "&ndash;",
                 count(r.deviations.count),
                 um(r.deviations.mean),
                 fixed(r.deviations.sigma * 1000, 1),
                 um(r.deviations.min),
                 um(r.deviations.max),
                 count(r.out_of_tolerance)};
    std::string residual = "&ndash;", verdict = "&ndash;";
    if (doc.prediction)
      for (const RegionResidualStatistics& p : doc.prediction->regions)
        if (p.region == r.region) {
          residual = fixed(p.statistics.rms * 1000, 1);
          verdict = escape(to_string(p.statistics.verdict));
        }
    row.cells.push_back(residual);
    row.cells.push_back(verdict);
    if (r.out_of_tolerance > 0) row.css_class = "out";
    rows.push_back(row);
  }
  out += html::table({"Region", "Face", "Class", "Area [mm2]", "Points", "Mean [um]", "Sigma [um]", "Min [um]",
                      "Max [um]", "Out", "Residual RMS [um]", "Prediction"},
                     rows);
  const std::vector<MergedSurface> merged = merged_surfaces(doc, regions);
  if (!merged.empty()) {
    out += "<h3>Surfaces across faces</h3>\n<p>Regions of one class on faces that meet tangentially (a fillet "
           "chain, a blend split into patches) are one surface; their points together:</p>\n";
    std::vector<TableRow> surfaces;
    for (const MergedSurface& m : merged) {
      std::string ids, faces;
      for (int id : m.group->regions) ids += (ids.empty() ? "R" : ", R") + std::to_string(id);
      for (int f : m.group->faces)
        faces += (faces.empty() ? "" : ", ") + escape(regions->faces[static_cast<std::size_t>(f)].name);
      TableRow row;
      row.cells = {"S" + std::to_string(m.group->id), to_string(m.group->curvature_class), ids, faces,
                   fixed(m.group->area, 1), count(m.deviations.count),
                   m.deviations.count ? um(m.deviations.mean) : "&ndash;",
                   m.deviations.count ? fixed(m.deviations.sigma * 1000, 1) : "&ndash;",
                   m.deviations.count ? um(m.deviations.min) : "&ndash;",
                   m.deviations.count ? um(m.deviations.max) : "&ndash;", count(m.out_of_tolerance)};
      if (m.out_of_tolerance > 0) row.css_class = "out";
      surfaces.push_back(std::move(row));
    }
    out += html::table({"Surface", "Class", "Regions", "Faces", "Area [mm2]", "Points", "Mean [um]", "Sigma [um]",
                        "Min [um]", "Max [um]", "Out"},
                       surfaces);
  }
  return out + figures_of(figures, "regions") + "</section>\n";
}

std::string prediction_section(const ComparisonDocument& doc, const std::vector<ReportFigure>& figures) {
  std::string out = "<section id=\"prediction\"><h2>Predicted vs measured</h2>\n";
  if (!doc.prediction) return out + "<p>No machining prediction was given.</p></section>\n";
  const PredictionComparison& p = *doc.prediction;
  const ResidualStatistics& o = p.overall;
  const UncomparedCounts& u = p.uncompared;
  out += html::key_value_table({
      {"Verdict", "<b>" + escape(to_string(o.verdict)) + "</b>"},
      {"Compared points", count(o.count) + " (not compared: " + count(u.not_reached) + " not reached, " +
                              count(u.outside) + " outside, " + count(u.not_machinable) + " not machinable, " +
                              count(u.face_not_predicted) + " on faces without prediction)"},
      {"Mean predicted / measured", um(o.mean_predicted) + " / " + um(o.mean_measured) + " &micro;m"},
      {"Residual mean / sigma / RMS / max |r|", um(o.mean) + " / " + fixed(o.sigma * 1000, 1) + " / " +
                                                   fixed(o.rms * 1000, 1) + " / " + fixed(o.max_abs * 1000, 1) +
                                                   " &micro;m"},
      {"Correlation", o.correlation ? fixed(*o.correlation, 3) : "&ndash;"},
      {"Normalised RMS, share within", fixed(o.normalised_rms, 2) + ", " + fixed(100 * o.within_share, 1) + " %"},
      {"Alignment to the predicted surface", escape(p.alignment.status) + " (" + count(p.alignment.points) +
                                                 " points, RMS " + fixed(p.alignment.rms_before * 1000, 2) +
                                                 " &rarr; " + fixed(p.alignment.rms_after * 1000, 2) + " &micro;m)"},
  });
  return out + figures_of(figures, "prediction") + "</section>\n";
}

// A scan (`scan` set) records per site and cluster a count of points and
// the cloud index of the point its deepest local mean is centred on, not
// point ids (scan_verification.hpp); its tables add how the depth was read.
std::string gouges_section(const ComparisonDocument& doc, const std::vector<ReportFigure>& figures,
                           const ScanComparisonDocument* scan) {
  std::string out = "<section id=\"gouges\"><h2>Gouges</h2>\n";
  if (!doc.gouges) return out + "<p>No machining prediction was given: no gouge sites to check.</p></section>\n";
  const GougeConfirmation& g = *doc.gouges;
  const ScanVerification* v = scan && scan->verification ? &*scan->verification : nullptr;
  if (v)
    out += "<p>A scan point is as noisy as the scanner (" + fixed(v->noise * 1000, 1) + " &micro;m" +
           "), so each site and cluster is read through local means: the mean deviation of the points within " +
           fixed(v->read_radius, 2) + " mm of a point (at least " + count(kScanReadPoints) +
           "); the deepest is the measured depth, its 1-sigma the noise over the square root of its points. "
           "<i>Deepest</i> is the index of its centre point in the deviation cloud.</p>\n";
  if (g.sites.empty()) {
    out += "<p>The prediction has no gouge sites.</p>\n";
  } else {
    std::vector<TableRow> rows;
    for (std::size_t k = 0; k < g.sites.size(); ++k) {
      const GougeSiteCheck& s = g.sites[k];
      const ScanGougeSite* read = v ? &v->sites.at(k) : nullptr;
      TableRow row{{escape(s.id), escape(to_string(s.source)), escape(s.face), status_badge(to_string(s.status)),
                    um_or_dash(s.predicted_depth ? std::optional<double>(-*s.predicted_depth) : std::nullopt),
                    um_or_dash(s.measured_depth ? std::optional<double>(-*s.measured_depth) : std::nullopt),
                    s.uncertainty ? fixed(*s.uncertainty * 1000, 1) : "&ndash;",
                    s.threshold ? fixed(*s.threshold * 1000, 1) : "&ndash;",
                    count(read ? read->on_site : s.points.size()),
                    !s.deepest ? "&ndash;" : read ? "#" + count(*s.deepest) : escape(doc.points.at(*s.deepest).id),
                    s.depth_consistent ? (*s.depth_consistent ? "yes" : "no") : "&ndash;"},
                   ""};
      if (read) {
        row.cells.push_back(s.deepest ? count(read->read_points) : "&ndash;");
        row.cells.push_back(count(read->anchors_seen) + " of " + count(s.anchors.size()));
      }
      rows.push_back(std::move(row));
    }
    std::vector<std::string> head = {"Site", "Source", "Face", "Status", "Predicted error [um]",
                                     "Measured deviation [um]", "1-sigma [um]", "Threshold [um]", "Points", "Deepest",
                                     "Depth consistent"};
    if (v) {
      head.push_back("Read over [points]");
      head.push_back("Predicted spots seen");
    }
    out += html::table(head, rows);
  }
  if (g.unexplained.empty()) {
    out += "<p>No unexplained overcuts.</p>\n";
  } else {
    std::vector<TableRow> rows;
    for (std::size_t k = 0; k < g.unexplained.size(); ++k) {
      const OvercutCluster& c = g.unexplained[k];
      const ScanOvercutCluster* read = v ? &v->unexplained.at(k) : nullptr;
      TableRow row{{escape(c.id), status_badge("UNEXPLAINED"), escape(c.face),
                    fixed(c.xyz.x(), 2) + ", " + fixed(c.xyz.y(), 2) + ", " + fixed(c.xyz.z(), 2), um(-c.depth),
                    fixed(c.uncertainty * 1000, 1), fixed(c.threshold * 1000, 1),
                    count(read ? read->points : c.points.size()),
                    read ? "#" + count(c.deepest) : escape(doc.points.at(c.deepest).id)},
                   ""};
      if (read) {
        row.cells.push_back(count(read->read_points));
        row.cells.push_back(fixed(c.centroid.x(), 2) + ", " + fixed(c.centroid.y(), 2) + ", " +
                            fixed(c.centroid.z(), 2));
        const Eigen::Vector3d size = read->extent_max - read->extent_min;
        row.cells.push_back(fixed(size.x(), 2) + ", " + fixed(size.y(), 2) + ", " + fixed(size.z(), 2));
      }
      rows.push_back(std::move(row));
    }
    std::vector<std::string> head = {"Cluster", "Status", "Face", "Deepest at x, y, z [mm]", "Deviation [um]",
                                     "1-sigma [um]", "Threshold [um]", "Points", "Deepest"};
    if (v) {
      head.push_back("Read over [points]");
      head.push_back("Centre x, y, z [mm]");
      head.push_back("Extent along x, y, z [mm]");
    }
    out += "<h3>Unexplained overcuts (measured, not predicted)</h3>\n" + html::table(head, rows);
  }
  return out + figures_of(figures, "gouges") + "</section>\n";
}

std::string options_rows(const ComparisonDocument::Options& o) {
  const auto num = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return std::string(buf);
  };
  return html::key_value_table({
      {"Tolerance zone", num(o.tolerance.width) + " mm, + side " + num(o.tolerance.outside) + " mm (" +
                             escape(o.disposition) + ")"},
      {"Measurements", escape(o.points) + " points, probe diameter " + num(o.probe_diameter) + " mm, units " +
                           escape(o.units)},
      {"Registration", "dof " + escape(o.dof) + ", loss " + escape(o.loss) + " (scale " + num(o.loss_scale) +
                           " mm), max " + std::to_string(o.max_outer_iterations) + " outer / " +
                           std::to_string(o.max_solver_iterations) + " solver iterations, motion tolerance " +
                           num(o.motion_tolerance) + " mm"},
      {"Outliers", std::string(o.outlier_rejection ? "rejected" : "kept") + ": " + num(o.outlier_sigma) +
                       " robust sigmas, floor " + num(o.outlier_floor) + " mm, edge " + num(o.edge_tolerance) +
                       " mm, " + std::to_string(o.confirm_neighbours) + " neighbours within " +
                       num(o.neighbour_radius) + " mm, max " + std::to_string(o.max_outlier_passes) + " passes"},
      {"Prediction comparison", "probe sigma " + num(o.prediction.probe_sigma) + " mm, alignment " +
                                    (o.prediction.align ? "on" : "off") + ", explained when RMS(z) &le; " +
                                    num(o.prediction.max_normalised_rms) + " and " +
                                    num(100 * o.prediction.required_share) + " % within " +
                                    num(o.prediction.within_sigmas) + " sigma (min " +
                                    std::to_string(o.prediction.min_points) + " points)"},
      {"Gouge confirmation", "overcut beyond max(" + num(o.gouges.overcut_sigmas) + " sigma, " +
                                 num(o.gouges.tolerance_fraction) + " |lower limit|), site margin " +
                                 num(o.gouges.site_margin) + " mm, contact cluster " +
                                 num(o.gouges.contact_cluster_distance) + " mm, overcut cluster " +
                                 num(o.gouges.overcut_cluster_distance) + " mm"},
  });
}

std::string traceability_section(const ComparisonDocument& doc, const ReportContext& context) {
  std::string out = "<section id=\"traceability\"><h2>Traceability</h2>\n";
  out += html::key_value_table({{"Furrow version", escape(FURROW_VERSION)},
                                {"Generated", escape(context.generated)},
                                {"Comparison format", std::to_string(doc.version)}});
  std::vector<TableRow> rows;
  for (const InputDigest& in : context.inputs)
    rows.push_back({{escape(in.role), "<code>" + escape(in.path) + "</code>", count(in.bytes),
                     in.generated ? "this run" : "input", "<span class=\"hash\">" + escape(in.sha256) + "</span>"},
                    ""});
  out += "<h3>Files (SHA-256)</h3>\n" + html::table({"Role", "Path", "Bytes", "Origin", "SHA-256"}, rows, "files");
  if (!context.stages.empty()) {
    std::vector<TableRow> times;
    for (const StageTime& t : context.stages) times.push_back({{escape(t.stage), fixed(t.seconds, 2)}, ""});
    times.push_back({{"<b>total</b>", "<b>" + fixed(context.total_seconds, 2) + "</b>"}, ""});
    out += "<h3>Stage times (wall clock, s)</h3>\n" + html::table({"Stage", "Seconds"}, times);
  }
  out += "<h3>Comparison options</h3>\n" + options_rows(doc.options);
  if (!context.job_options_json.empty())
    out += "<h3>Job options (every stage, defaults resolved)</h3>\n<pre class=\"options\">" +
           escape(context.job_options_json) + "</pre>\n";
  return out + "</section>\n";
}

}  // namespace

std::string report_html(const ComparisonDocument& doc, const ReportVerdict& verdict, const RegionMap* regions,
                        const ReportContext& context, const std::vector<ReportFigure>& figures) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                    "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
                    escape("QA report " + context.title + ": " + verdict.result()) + "</title>\n<style>" + kStyle +
                    inspection_record_css() + point_table_css() + "</style>\n";
  // File names as the user gave them where the context knows them (a job's
  // inputs), else as the comparison names them.
  auto named = [&](const std::string& role, const std::string& fallback) {
    for (const InputDigest& in : context.inputs)
      if (in.role == role) return in.path;
    return fallback;
  };
  // The printed page header: the part number and serial when the record
  // has them (what a filed report is looked up by), else the part file.
  std::string print_part = named("part", doc.sources.part), print_title = context.title;
  if (context.record) {
    const InspectionRecord& r = *context.record;
    if (!r.part_number.empty()) print_part = r.part_number + (r.revision.empty() ? "" : " rev " + r.revision);
    if (!r.serial.empty()) print_title += ", serial " + r.serial;
    else if (!r.lot.empty()) print_title += ", lot " + r.lot;
  }
  out += print_style(print_part, print_title) + "</head>\n<body>\n";  // print_style.hpp
  out += "<header><h1>QA report: " + escape(context.title) + "</h1>\n<p class=\"meta\">Part <code>" +
         escape(named("part", doc.sources.part)) + "</code>, measurements <code>" +
         escape(named("measurements", doc.sources.measurements)) +
         "</code> &middot; Furrow " + escape(FURROW_VERSION) + " &middot; " + escape(context.generated) +
         "</p>\n" + record_header_html(context.record) +
         (context.description.empty() ? "" : "<p>" + escape(context.description) + "</p>\n") +
         "</header>\n";
  out += verdict_section(verdict);
  out += "<nav>" + std::string(context.scan ? "<a href=\"#scan\">Scan</a>" : "") + "<a href=\"#alignment\">Alignment</a><a href=\"#regions\">Regions</a>" +
         std::string(context.process ? "<a href=\"#process\">Process</a>" : "") + "<a href=\"#deviations\">"
         "Deviations</a><a href=\"#view3d\">3D view</a><a href=\"#prediction\">Predicted vs measured</a><a "
         "href=\"#gouges\">Gouges</a>" +
         std::string(context.compensation ? "<a href=\"#compensation\">Compensation</a>" : "") +
         "<a href=\"#faces\">Faces</a><a href=\"#points\">Points</a><a "
         "href=\"#traceability\">Traceability</a></nav>\n";
  out += scan_section_html(context.scan.get(), figures_of(figures, "scan"));
  out += alignment_section(doc);
  out += regions_section(doc, regions, figures);
  out += process_section_html(context.process);
  out += deviations_section(doc, figures);
  out += figures_of(figures, "view3d");  // part_view_3d.hpp: a whole section, when present
  out += prediction_section(doc, figures);
  out += gouges_section(doc, figures, context.scan.get());
  out += compensation_section_html(context.compensation, context.compensation_file,
                                   figures_of(figures, "compensation"));
  if (context.scan)  // a scan's points are in its deviation cloud, not listed here
    out += "<section id=\"points\"><h2>Points</h2>\n<p>The deviation of every point of the scan, and its flag, is in "
           "the comparison's deviation cloud" +
           (context.scan->sources.deviations.empty()
                ? std::string(" (not written: compare with --deviations FILE)")
                : " <code>" + escape(context.scan->sources.deviations) + "</code>") +
           "; the sections above count and draw them.</p></section>\n";
  else
    out += face_summary_html(doc, context.face_surfaces) + point_table_html(doc);
  out += traceability_section(doc, context) + sign_off_html(context.record);
  return out + kImageCheck + "</body>\n</html>\n";
}

}  // namespace furrow
