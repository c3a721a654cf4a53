// comparison.json of a scan read back (contract in scan_comparison_document.hpp).
#include "inspection/scan_comparison_document.hpp"

#include "base/error.hpp"
#include "base/json_cursor.hpp"
#include "inspection/comparison_json.hpp"
#include "inspection/scan_display_json.hpp"
#include "inspection/scan_fit_options_json.hpp"
#include "inspection/scan_verification_json.hpp"

namespace furrow {

namespace jf = json_fields;
using nlohmann::json;
using comparison_json::read_statistics;

namespace {

}  // namespace

bool is_scan_comparison_text(const std::string& text) {
  const json doc = json::parse(text, nullptr, false);
  return doc.is_object() && doc.contains("kind") && doc["kind"] == "scan";
}

ScanComparisonDocument parse_scan_comparison(const std::string& text, const std::string& name) {
  const json root = jf::parse_text(text, name);
  const JsonCursor c(root, name + ":");
  ScanComparisonDocument d;
  if (c.string("kind") != "scan") throw InputError(c.path("kind") + ": expected \"scan\"");
  d.furrow_version = c.string("furrow_version");

  const JsonCursor s = c.at("sources");
  d.sources.part = s.string("part");
  d.sources.scan = s.string("scan");
  d.sources.regions = s.string("regions");
  d.sources.deviations = s.string("deviations");
  d.sources.scan_units = s.string("scan_units");
  if (s.has("prediction")) d.sources.prediction = s.string("prediction");

  const JsonCursor p = c.at("preprocessing");
  auto& pre = d.preprocessing;
  pre.voxel = p.positive("voxel");
  pre.spray_neighbours = p.integer("spray_neighbours", 0);
  pre.spray_far_sigmas = p.number("spray_far_sigmas");
  pre.spray_near_sigmas = p.number("spray_near_sigmas");
  pre.spray_removal = p.boolean("spray_removal");
  pre.normal_neighbours = p.integer("normal_neighbours", 0);
  pre.local_origin = p.vector3("local_origin");
  pre.local_plane_sigma = p.non_negative("local_plane_sigma");
  pre.statistical_rule = p.count("statistical_rule");
  pre.normals = p.string("normals");

  const JsonCursor n = c.at("points");
  auto& pts = d.points;
  pts.read = n.count("read");
  pts.not_finite = n.count("not_finite");
  pts.kept = n.count("kept");
  const JsonCursor removed = n.at("removed");
  pts.spray_far = removed.count("spray_far");
  pts.spray_near = removed.count("spray_near");
  pts.off_part = removed.count("off_part");
  if (removed.find("grazing")) pts.grazing = removed.count("grazing");
  pts.fit = n.count("fit");
  pts.in_fit = n.count("in_fit");

  const JsonCursor r = c.at("registration");
  auto& reg = d.registration;
  reg.status = r.string("status");
  reg.converged = r.boolean("converged");
  reg.coarse = r.string("coarse");
  reg.coarse_median = r.non_negative("coarse_median");
  reg.rms_before = r.non_negative("rms_before");
  reg.rms_after = r.non_negative("rms_after");
  reg.sigma = r.non_negative("sigma");
  reg.outer_iterations = r.integer("outer_iterations", 0);
  const json& rows = r.array("transform");
  if (rows.size() != 4) throw InputError(r.path("transform") + ": expected a 4 x 4 matrix");
  for (int i = 0; i < 4; ++i) {
    const std::vector<double> row = jf::numbers(rows[static_cast<std::size_t>(i)], jf::child(r.path("transform"), i));
    if (row.size() != 4) throw InputError(jf::child(r.path("transform"), i) + ": expected 4 numbers");
    for (int j = 0; j < 4; ++j) reg.transform(i, j) = row[static_cast<std::size_t>(j)];
  }

  const JsonCursor t = c.at("tolerance");
  d.tolerance = ToleranceZone::make(t.number("width"), t.number("outside"), t.path("width"));

  d.fit_options.tolerance = d.tolerance;
  d.fit_options.disposition = d.tolerance.disposition();
  d.fit_options.points = "contact";
  d.fit_options.probe_diameter = 0;
  d.fit_options.units = d.sources.scan_units;
  if (!c.has("fit_options"))
    throw InputError(name + ": a scan comparison without its fit options (written by an older Furrow): compare "
                            "the scan again");
  read_scan_fit_options(c.at("fit_options"), d.fit_options);

  const JsonCursor m = c.at("summary");
  ComparisonSummary& sum = d.summary;
  sum.evaluated = m.count("evaluated");
  sum.in_tolerance = m.count("in_tolerance");
  sum.out_of_tolerance = m.count("out_of_tolerance");
  sum.deviations = read_statistics(m.at("deviations"));
  sum.profile = m.non_negative("profile");
  const json& regions = m.array("regions");
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const JsonCursor g(regions[k], jf::child(m.path("regions"), k));
    sum.regions.push_back({g.integer("region"), read_statistics(g.at("deviations")), g.count("out_of_tolerance")});
  }
  sum.alignment = m.string("alignment");
  sum.verdict = parse_verdict(m.string("verdict"), m.path("verdict"));
  sum.pass = sum.verdict == Verdict::pass;
  const json& open = m.array("inconclusive");
  for (std::size_t k = 0; k < open.size(); ++k) {
    const JsonCursor w(open[k], jf::child(m.path("inconclusive"), k));
    sum.inconclusive.push_back({w.string("kind"), "", w.string("text")});
  }
  sum.points = d.points.kept + d.points.off_part;
  sum.outliers = d.points.off_part;
  sum.in_fit = d.points.in_fit;

  if (!c.has("histogram") || !c.has("display"))
    throw InputError(name + ": a scan comparison without the display sample and histogram the report shows "
                            "(written by an older Furrow): compare the scan again");
  d.histogram = read_scan_histogram(c.at("histogram"));
  d.display = read_scan_display(c.at("display"));
  if (!d.sources.prediction.empty()) {
    d.verification = scan_verification_json::read_scan_verification(c);
    d.summary.confirmed_gouges = d.verification->confirmed();
    d.summary.unexplained_overcuts = d.verification->unexplained.size();
  }
  std::size_t counted = 0;
  for (std::size_t k : d.histogram.counts) counted += k;
  if (counted != sum.evaluated)
    throw InputError(c.path("histogram") + ": counts " + std::to_string(counted) + " points, summary.evaluated " +
                     std::to_string(sum.evaluated));
  return d;
}

ScanComparisonDocument read_scan_comparison(const std::string& path) {
  return parse_scan_comparison(jf::read_text(path), path);
}

}  // namespace furrow
