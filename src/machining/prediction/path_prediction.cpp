#include "machining/prediction/path_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
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

// The passes one cutter cuts, as a path of their own, and where each of
// them is in the whole path.
struct ToolGroup {
  int cutter = 0;
  std::vector<int> passes;  // indices into the whole path, in path order
};

std::vector<ToolGroup> tool_groups(const PathTools& tools) {
  std::vector<ToolGroup> groups(tools.cutters.size());
  for (std::size_t c = 0; c < groups.size(); ++c) groups[c].cutter = static_cast<int>(c);
  for (std::size_t p = 0; p < tools.of_pass.size(); ++p)
    groups[static_cast<std::size_t>(tools.of_pass[p])].passes.push_back(static_cast<int>(p));
  return groups;
}

PathGeometry sub_geometry(const PathGeometry& geometry, const ToolGroup& group) {
  PathGeometry sub;
  for (int p : group.passes) sub.passes.push_back(geometry.passes[static_cast<std::size_t>(p)]);
  return sub;
}

void locate(const Part& part, const PathTools& tools, const Toolpath& path, const PathContactOptions& options,
            const StageProgress& progress, PathGeometry& out) {
  out = locate_path(part, tools, path, options, stage(progress, "locating path"));
}

}  // namespace

PathPrediction predict_path(const Part& part, const Cutter& cutter, const Toolpath& path,
                            const PathPredictionOptions& options, const StageProgress& progress) {
  return predict_path(part, single_tool(cutter, path), path, options, progress);
}

PathPrediction predict_path(const Part& part, const PathTools& path_tools, const Toolpath& path,
                            const PathPredictionOptions& options, const StageProgress& progress) {
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance))
    throw InputError("predict: the tolerance must be a positive number of millimetres");
  if (!(options.gouge_threshold >= 0) || !std::isfinite(options.gouge_threshold))
    throw InputError("predict: the gouge threshold must not be negative");
  auto in_range = [&](const std::vector<int>& of) {
    return std::all_of(of.begin(), of.end(),
                       [&](int t) { return t >= 0 && static_cast<std::size_t>(t) < path_tools.cutters.size(); });
  };
  if (path_tools.cutters.empty() || path_tools.of_pass.size() != path.passes.size() ||
      path_tools.of_rapid.size() != path.rapids.size() || !in_range(path_tools.of_pass) ||
      !in_range(path_tools.of_rapid))
    throw std::logic_error("predict_path: the tools do not describe this path");
  PathPrediction r;
  r.tools = std::make_shared<const PathTools>(path_tools);
  const PathTools& tools = *r.tools;
  const std::vector<ToolGroup> groups = tool_groups(tools);
  auto cutter_of = [&](const ToolGroup& g) -> const Cutter& { return tools.cutters[static_cast<std::size_t>(g.cutter)]; };
  if (options.resolution > 0) {
    r.resolution = options.resolution;
  } else {
    r.resolution = std::numeric_limits<double>::infinity();
    for (const Cutter& c : tools.cutters) r.resolution = std::min(r.resolution, default_zmap_resolution(c, options.tolerance));
  }
  r.gouge_threshold = options.gouge_threshold > 0 ? options.gouge_threshold : 2 * options.tolerance;

  locate(part, tools, path, options.contacts, progress, r.geometry);
  const VerticalProjector projector(part);
  for (const ToolGroup& g : groups) {
    if (g.passes.empty()) continue;
    const bool whole = groups.size() == 1;
    std::vector<StepPrediction> steps = predict_steps(projector, cutter_of(g), whole ? r.geometry : sub_geometry(r.geometry, g),
                                                      options.step, stage(progress, "per-step errors"));
    for (StepPrediction& s : steps) {
      if (!whole) s.pass = g.passes[static_cast<std::size_t>(s.pass)];
      r.steps.push_back(std::move(s));
    }
  }
  std::stable_sort(r.steps.begin(), r.steps.end(), [](const StepPrediction& a, const StepPrediction& b) {
    return a.pass != b.pass ? a.pass < b.pass : a.step < b.step;
  });

  // The z-map covers the part and every move's shadow on it. Each tool
  // lowers it with its own cutter, in path order within the tool.
  r.zmap.emplace(part_xy_extent(part), r.resolution, options.zmap);
  // The moves run between the located tips: for contact-point input these
  // are the cutter locations, not the file's positions.
  for (const ToolGroup& g : groups) {
    std::vector<ZMapMove> moves;
    for (int p : g.passes) {
      const std::vector<PathPoint>& pass = r.geometry.passes[static_cast<std::size_t>(p)];
      for (std::size_t k = 1; k < pass.size(); ++k)
        moves.push_back({pass[k - 1].tip, pass[k].tip, p, static_cast<int>(k - 1)});
    }
    if (!moves.empty()) r.zmap->cut(cutter_of(g), moves, stage(progress, "z-map"));
  }
  r.map = compute_error_map(part, *r.zmap, options.map, stage(progress, "error map"));
  for (const ToolGroup& g : groups) {
    if (g.passes.empty()) continue;
    const bool whole = groups.size() == 1;
    std::vector<PassScallop> scallops =
        pass_pair_scallops(projector, *r.zmap, cutter_of(g),
                           path_contacts(whole ? r.geometry : sub_geometry(r.geometry, g)), options.scallops);
    for (PassScallop& sc : scallops) {
      if (!whole) {
        sc.pass_a = g.passes[static_cast<std::size_t>(sc.pass_a)];
        sc.pass_b = g.passes[static_cast<std::size_t>(sc.pass_b)];
      }
      r.scallops.push_back(std::move(sc));
    }
  }
  std::stable_sort(r.scallops.begin(), r.scallops.end(),
                   [](const PassScallop& a, const PassScallop& b) { return a.pass_a < b.pass_a; });
  r.sites = find_gouge_sites(part, *r.zmap, r.map, {r.gouge_threshold}, options.map);

  for (const ToolGroup& g : groups) {
    std::vector<ContactSite> sites;
    std::vector<std::pair<int, int>> where;
    for (int p : g.passes) {
      const std::vector<PathPoint>& pass = r.geometry.passes[static_cast<std::size_t>(p)];
      for (std::size_t k = 0; k < pass.size(); ++k) {
        const PathPoint& q = pass[k];
        if (!q.contact.valid || q.in_air) continue;
        ContactSite s;
        s.face = static_cast<std::size_t>(q.contact.at.face);
        s.uv = q.contact.at.uv;
        s.line = q.line;
        sites.push_back(s);
        where.emplace_back(p, static_cast<int>(k));
      }
    }
    if (sites.empty()) continue;
    const std::vector<GougePoint> checks = scan_gouges(part, cutter_of(g), sites, options.local, stage(progress, "local gouges"));
    for (std::size_t k = 0; k < checks.size(); ++k) {
      const GougeStatus s = checks[k].gouge.status;
      if (s == GougeStatus::gouge || s == GougeStatus::concave_crease)
        r.local_gouges.push_back({where[k].first, where[k].second, checks[k]});
    }
  }
  std::stable_sort(r.local_gouges.begin(), r.local_gouges.end(), [](const PathPrediction::Local& a, const PathPrediction::Local& b) {
    return a.pass != b.pass ? a.pass < b.pass : a.point < b.point;
  });

  // Rapids against the design surface, sampled as finely as the error map,
  // each with the tool in the spindle when it runs.
  if (progress) progress("rapids", 0, 1);
  RapidCheckOptions rapid;
  rapid.threshold = r.gouge_threshold;
  rapid.sample_spacing = options.map.sample_spacing > 0 ? options.map.sample_spacing : r.resolution;
  rapid.max_samples = options.map.max_samples;
  rapid.normal = options.map.normal;
  rapid.stock = options.stock;
  if (groups.size() == 1) {
    r.rapids = check_rapids(part, tools.cutters[0], path.rapids, rapid);
  } else {
    r.rapids.rapids = path.rapids.size();
    r.rapids.stock = options.stock.has_value();
    for (const ToolGroup& g : groups) {
      std::vector<RapidMove> moves;
      std::vector<std::size_t> index;
      for (std::size_t k = 0; k < path.rapids.size(); ++k)
        if (tools.of_rapid[k] == g.cutter) {
          moves.push_back(path.rapids[k]);
          index.push_back(k);
        }
      if (moves.empty()) continue;
      RapidCheck part_check = check_rapids(part, cutter_of(g), moves, rapid);
      r.rapids.checked += part_check.checked;
      r.rapids.unchecked += part_check.unchecked;
      for (RapidGouge& gouge : part_check.gouges) {
        gouge.rapid = index[gouge.rapid];
        r.rapids.gouges.push_back(gouge);
      }
    }
    std::stable_sort(r.rapids.gouges.begin(), r.rapids.gouges.end(),
                     [](const RapidGouge& a, const RapidGouge& b) { return a.rapid < b.rapid; });
  }
  if (progress) progress("rapids", 1, 1);
  return r;
}

Prediction make_prediction(const Part& part, const PathPrediction& r, const PathPredictionOptions& options,
                           const std::string& part_name, const std::string& toolpath_name) {
  Prediction p;
  p.part = part_name;
  p.toolpath = toolpath_name;
  const PathTools& tools = *r.tools;
  p.tool = tools.cutters[tools.of_pass.empty() ? 0 : static_cast<std::size_t>(tools.of_pass.front())].spec();
  if (tools.changes_tools()) {
    for (std::size_t c = 0; c < tools.cutters.size(); ++c) p.tools.push_back({tools.numbers[c], tools.cutters[c].spec()});
    p.pass_tools = tools.of_pass;
  }
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
  s.steps_not_converged = 0;
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
      rec.converged = st.error.converged;
      if (!st.error.converged) ++*s.steps_not_converged;
      const double magnitude = st.error.magnitude();
      s.max_step_error = std::max(s.max_step_error, magnitude);
      if (magnitude > options.tolerance + options.comparison_margin) ++s.steps_over_tolerance;
    }
    p.steps.push_back(rec);
  }
  for (const PassScallop& sc : r.scallops) {
    if (!sc.ridge.found) continue;
    ScallopRecord rec;
    rec.pass_a = sc.pass_a;
    rec.pass_b = sc.pass_b;
    rec.height = sc.ridge.height;
    rec.at = location(part, sc.ridge.at);
    s.max_scallop = std::max(s.max_scallop, sc.ridge.height);
    if (sc.cusp.found) {
      rec.has_cusp = true;
      rec.cusp = sc.cusp.height;
      rec.cusp_at = location(part, sc.cusp.at);
      s.max_cusp = std::max(s.max_cusp, sc.cusp.height);
    }
    p.scallops.push_back(rec);
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
