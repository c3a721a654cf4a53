#include "machining/prediction/path_prediction.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

std::function<void(std::size_t, std::size_t)> stage(const StageProgress& progress, const char* name) {
  if (!progress) return {};
  return [progress, name](std::size_t done, std::size_t total) { progress(name, done, total); };
}

SurfaceLocation location(const Part& part, const SurfacePoint& s) {
  SurfaceLocation l;
  if (s.face >= 0) l.face = part.faces[s.face].name();
  l.uv = s.uv;
  l.xyz = s.point;
  return l;
}

ErrorAt error_at(const Part& part, double error, const SurfacePoint& s) {
  ErrorAt e;
  e.found = s.valid;
  e.error = error;
  if (s.valid) e.at = location(part, s);
  return e;
}

}  // namespace

PathPrediction predict_path(const Part& part, const Cutter& cutter, const Toolpath& path,
                            const PathPredictionOptions& options, const StageProgress& progress) {
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    throw InputError("predict: the tolerance must be a positive number of millimetres");
  if (!(options.gouge_threshold >= 0) || !std::isfinite(options.gouge_threshold))
    throw InputError("predict: the gouge threshold must not be negative");
  PathPrediction r;
  r.resolution = options.resolution > 0 ? options.resolution : default_zmap_resolution(cutter, options.tolerance);
  r.gouge_threshold = options.gouge_threshold > 0 ? options.gouge_threshold : 2 * options.tolerance;

  r.geometry = locate_path(part, cutter, path, options.contacts, stage(progress, "locating path"));
  const VerticalProjector projector(part);
  r.steps = predict_steps(projector, cutter, r.geometry, options.step, stage(progress, "per-step errors"));

  // The z-map covers the part and every move's shadow on it.
  r.zmap.emplace(part_xy_extent(part), r.resolution, options.zmap);
  // The moves run between the located tips: for contact-point input these
  // are the cutter locations, not the file's positions.
  std::vector<ZMapMove> moves;
  for (std::size_t p = 0; p < r.geometry.passes.size(); ++p)
    for (std::size_t k = 1; k < r.geometry.passes[p].size(); ++k)
      moves.push_back({r.geometry.passes[p][k - 1].tip, r.geometry.passes[p][k].tip, static_cast<int>(p),
                       static_cast<int>(k - 1)});
  r.zmap->cut(cutter, moves, stage(progress, "z-map"));
  r.map = compute_error_map(part, *r.zmap, options.map, stage(progress, "error map"));
  r.scallops = pass_pair_scallops(projector, *r.zmap, cutter.diameter(), path_contacts(r.geometry), options.scallops);
  r.sites = find_gouge_sites(part, *r.zmap, r.map, {r.gouge_threshold}, options.map);

  std::vector<ContactSite> sites;
  std::vector<std::pair<int, int>> where;
  for (std::size_t p = 0; p < r.geometry.passes.size(); ++p)
    for (std::size_t k = 0; k < r.geometry.passes[p].size(); ++k) {
      const PathPoint& q = r.geometry.passes[p][k];
      if (!q.contact.valid || q.in_air) continue;
      ContactSite s;
      s.face = static_cast<std::size_t>(q.contact.at.face);
      s.uv = q.contact.at.uv;
      s.line = q.line;
      sites.push_back(s);
      where.emplace_back(static_cast<int>(p), static_cast<int>(k));
    }
  const std::vector<GougePoint> checks = scan_gouges(part, cutter, sites, options.local, stage(progress, "local gouges"));
  for (std::size_t k = 0; k < checks.size(); ++k) {
    const GougeStatus s = checks[k].gouge.status;
    if (s == GougeStatus::gouge || s == GougeStatus::concave_crease)
      r.local_gouges.push_back({where[k].first, where[k].second, checks[k]});
  }

  // Rapids against the design surface, sampled as finely as the error map.
  if (progress) progress("rapids", 0, 1);
  RapidCheckOptions rapid;
  rapid.threshold = r.gouge_threshold;
  rapid.sample_spacing = options.map.sample_spacing > 0 ? options.map.sample_spacing : r.resolution;
  rapid.max_samples = options.map.max_samples;
  rapid.normal = options.map.normal;
  rapid.stock = options.stock;
  r.rapids = check_rapids(part, cutter, path.rapids, rapid);
  if (progress) progress("rapids", 1, 1);
  return r;
}

Prediction make_prediction(const Part& part, const Cutter& cutter, const PathPrediction& r,
                           const PathPredictionOptions& options, const std::string& part_name,
                           const std::string& toolpath_name) {
  Prediction p;
  p.part = part_name;
  p.toolpath = toolpath_name;
  p.tool = cutter.spec();
  p.tolerance = options.tolerance;
  p.gouge_threshold = r.gouge_threshold;
  const ZMap& z = *r.zmap;
  p.zmap = {z.cell(), {z.x(0), z.y(0)}, z.nx(), z.ny(), z.moves().size(), z.cut_node_count()};

  PredictionSummary& s = p.summary;
  s.max_undercut = error_at(part, r.map.max_undercut.error, r.map.max_undercut.at);
  s.max_undercut.found = s.max_undercut.found && r.map.max_undercut.found;
  s.max_overcut = error_at(part, r.map.max_overcut.error, r.map.max_overcut.at);
  s.max_overcut.found = s.max_overcut.found && r.map.max_overcut.found;
  s.steps = r.steps.size();
  for (const StepPrediction& st : r.steps) {
    StepRecord rec;
    rec.pass = st.pass;
    rec.step = st.step;
    rec.status = to_string(st.status);
    if (st.status == StepStatus::evaluated) {
      ++s.steps_evaluated;
      rec.length = st.length;
      rec.undercut = error_at(part, st.error.undercut.error, st.error.undercut.at);
      rec.overcut = error_at(part, st.error.overcut.error, st.error.overcut.at);
      rec.chord_deviation = st.chord.deviation;
      const double magnitude = st.error.magnitude();
      s.max_step_error = std::max(s.max_step_error, magnitude);
      if (magnitude > options.tolerance + options.comparison_margin) ++s.steps_over_tolerance;
    }
    p.steps.push_back(rec);
  }
  for (const PassScallop& sc : r.scallops) {
    if (!sc.found) continue;
    p.scallops.push_back({sc.pass_a, sc.pass_b, sc.height, location(part, sc.at)});
    s.max_scallop = std::max(s.max_scallop, sc.height);
  }
  for (const GougeSite& g : r.sites) {
    GougeSiteRecord rec;
    rec.id = g.id;
    rec.face = part.faces[g.face].name();
    rec.depth = g.depth;
    rec.deepest = location(part, g.deepest);
    rec.area = g.area;
    rec.samples = g.samples;
    rec.centroid.face = rec.face;
    rec.centroid.uv = g.centroid_uv;
    rec.centroid.xyz = g.centroid;
    rec.box = g.box;
    rec.uv_box = g.uv_box;
    p.gouge_sites.push_back(rec);
  }
  for (const PathPrediction::Local& l : r.local_gouges) {
    LocalGougeRecord rec;
    rec.pass = l.pass;
    rec.point = l.point;
    rec.line = l.check.site.line;
    rec.at.face = part.faces[l.check.site.face].name();
    rec.at.uv = l.check.site.uv;
    rec.at.xyz = l.check.point;
    rec.status = to_string(l.check.gouge.status);
    rec.max_excess = l.check.gouge.max_excess;
    for (const AngularRange& a : l.check.gouge.ranges)
      rec.directions_deg.emplace_back(degrees(a.start), degrees(a.width));
    p.local_gouges.push_back(rec);
  }
  // Written only when there is something to say (docs/formats.md
  // "prediction.json"): a prediction without rapid gouges or stock box keeps
  // the bytes it always had.
  p.rapids.checked = r.rapids.checked;
  p.rapids.unchecked = r.rapids.unchecked;
  p.rapids.has_stock = options.stock.has_value();
  if (options.stock) p.rapids.stock = *options.stock;
  for (const RapidGouge& g : r.rapids.gouges) {
    RapidGougeRecord rec;
    rec.line = g.line;
    rec.kind = to_string(g.kind);
    rec.depth = g.depth;
    rec.at.xyz = g.at;
    if (g.face >= 0) {
      rec.at.face = part.faces[static_cast<std::size_t>(g.face)].name();
      rec.at.uv = g.uv;
    }
    p.rapids.gouges.push_back(rec);
  }
  p.rapids.written = p.rapids.has_stock || !p.rapids.gouges.empty();
  s.gouge_sites = p.gouge_sites.size();
  s.local_gouge_points = p.local_gouges.size();
  s.path_points = r.geometry.points;
  s.points_without_contact = r.geometry.without_contact;
  s.points_in_air = r.geometry.in_air;
  s.points_below_surface = r.geometry.below_surface;
  s.lowest_gap = r.geometry.lowest_gap;
  s.samples_reached = r.map.reached;
  s.samples_not_reached = r.map.not_reached;
  s.samples_not_machinable = r.map.not_machinable;
  s.samples_boundary = r.map.boundary;
  for (const FaceErrorMap& m : r.map.faces) {
    FaceGridRecord f;
    f.name = part.faces[m.face].name();
    f.domain = m.domain;
    f.cells_u = m.cells_u;
    f.cells_v = m.cells_v;
    for (const ErrorCell& c : m.cells) {
      f.status.push_back(c.status);
      f.mean.push_back(c.mean);
      f.max_undercut.push_back(c.max_undercut);
      f.max_overcut.push_back(c.max_overcut);
      f.boundary.push_back(c.boundary);
    }
    f.has_samples = true;
    for (const ErrorCellStatus st : m.status) {
      switch (st) {
        case ErrorCellStatus::reached: ++f.samples_reached; break;
        case ErrorCellStatus::not_reached: ++f.samples_not_reached; break;
        case ErrorCellStatus::not_machinable: ++f.samples_not_machinable; break;
        case ErrorCellStatus::outside: ++f.samples_outside; break;
      }
    }
    p.faces.push_back(f);
  }
  return p;
}

}  // namespace furrow
