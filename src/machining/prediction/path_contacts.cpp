#include "machining/prediction/path_contacts.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <sstream>

#include "base/number_text.hpp"
#include "base/error.hpp"

namespace furrow {

namespace {

std::string at_line(const Toolpath& path, const ToolpathPoint& p) {
  return path.source + ":" + std::to_string(p.line);
}

std::string mm(double x) { return general(x); }

// A contact point of a CSV: its place on the part, validated.
PathPoint locate_contact(const Part& part, const Cutter& cutter, const Toolpath& path, const ToolpathPoint& p,
                         const ClosestPointFinder& projector, const PathContactOptions& options) {
  PathPoint result;
  result.line = p.line;
  const CutterLocation loc = cutter_location(cutter, p.position, p.normal, options.location);
  if (!loc.reachable)
    throw InputError(at_line(path, p) + ": the normal points down (n_z < 0): a 3-axis cutter "
                                        "cannot reach this contact point from above");
  result.tip = loc.tip;
  SurfacePoint s;
  if (p.has_uv) {
    int face = 0;
    if (!p.face.empty()) {
      const auto f = part.find_face(p.face);
      if (!f) throw InputError(at_line(path, p) + ": the part has no face \"" + p.face + "\"");
      face = static_cast<int>(*f);
    } else if (part.faces.size() != 1) {
      throw InputError(at_line(path, p) + ": u and v without a face column, but the part has " +
                       std::to_string(part.faces.size()) + " faces");
    }
    const ParameterDomain& d = part.faces[face].domain();
    if (p.uv.x() < d.u0 || p.uv.x() > d.u1 || p.uv.y() < d.v0 || p.uv.y() > d.v1)
      throw InputError(at_line(path, p) + ": (u, v) lies outside the face's parameter domain");
    s = surface_point(part, face, p.uv);
  } else {
    const ClosestPoint foot = projector.project(p.position);
    if (foot.converged) s = surface_point(part, static_cast<int>(foot.face), foot.uv);
  }
  if (!s.valid) throw InputError(at_line(path, p) + ": the contact point has no regular surface point on the part");
  const double distance = (s.point - p.position).norm();
  if (distance > options.max_contact_distance)
    throw InputError(at_line(path, p) + ": the contact point lies " + mm(distance) + " mm from the part (more than " +
                     mm(options.max_contact_distance) + " mm): not a contact point of this part");
  result.contact = {true, s};
  return result;
}

}  // namespace

PathGeometry locate_path(const Part& part, const Cutter& cutter, const Toolpath& path,
                         const PathContactOptions& options,
                         const std::function<void(std::size_t, std::size_t)>& progress) {
  PathGeometry geometry;
  std::vector<const ToolpathPoint*> flat;
  for (const ToolpathPass& pass : path.passes) {
    geometry.passes.emplace_back(pass.points.size());
    for (const ToolpathPoint& p : pass.points) flat.push_back(&p);
  }
  std::vector<PathPoint> located(flat.size());
  std::atomic<std::size_t> done{0};
  if (path.kind == ToolpathKind::contact_points) {
    const ClosestPointFinder projector(part, options.projection);
    // Sequential: the first bad line is the one reported.
    for (std::size_t k = 0; k < flat.size(); ++k) {
      located[k] = locate_contact(part, cutter, path, *flat[k], projector, options);
      if (progress && k % 256 == 0) progress(k, flat.size());
    }
  } else {
    const TipContactFinder finder(part, cutter, options.tip);
#pragma omp parallel for schedule(dynamic, 16)
    for (std::size_t k = 0; k < flat.size(); ++k) {
      PathPoint& r = located[k];
      r.tip = flat[k]->position;
      r.line = flat[k]->line;
      const TipContactResult found = finder.find(r.tip);
      if (found.status == TipContactStatus::found) {
        const TipContact& c = found.contacts.front();
        SurfacePoint s = surface_point(part, static_cast<int>(c.face), c.uv);
        if (s.valid) {
          r.contact = {true, s};
          r.gap = found.gap;
          r.in_air = found.gap > options.air_gap;
        }
      }
      const std::size_t d = ++done;
      if (progress && omp_get_thread_num() == 0 && d % 256 == 0) progress(d, flat.size());
    }
  }
  if (progress) progress(flat.size(), flat.size());
  std::size_t k = 0;
  for (auto& pass : geometry.passes)
    for (PathPoint& p : pass) {
      p = located[k++];
      p.contact.tip = p.tip;
      ++geometry.points;
      geometry.without_contact += !p.contact.valid;
      geometry.in_air += p.in_air;
      if (p.contact.valid && p.gap < -options.below_margin / std::max(p.contact.at.normal.z(), 0.05)) {
        ++geometry.below_surface;
        geometry.lowest_gap = std::min(geometry.lowest_gap, p.gap);
      }
    }
  return geometry;
}

PathGeometry locate_path(const Part& part, const PathTools& tools, const Toolpath& path,
                         const PathContactOptions& options,
                         const std::function<void(std::size_t, std::size_t)>& progress) {
  if (tools.cutters.size() == 1) return locate_path(part, tools.cutters[0], path, options, progress);
  PathGeometry out;
  out.passes.resize(path.passes.size());
  for (std::size_t c = 0; c < tools.cutters.size(); ++c) {
    std::vector<std::size_t> passes;  // of this cutter, in path order
    Toolpath sub;
    sub.kind = path.kind;
    sub.source = path.source;
    for (std::size_t p = 0; p < path.passes.size() && p < tools.of_pass.size(); ++p)
      if (static_cast<std::size_t>(tools.of_pass[p]) == c) {
        passes.push_back(p);
        sub.passes.push_back(path.passes[p]);
      }
    if (passes.empty()) continue;
    PathGeometry located = locate_path(part, tools.cutters[c], sub, options, progress);
    for (std::size_t k = 0; k < passes.size(); ++k) out.passes[passes[k]] = std::move(located.passes[k]);
    out.points += located.points;
    out.without_contact += located.without_contact;
    out.in_air += located.in_air;
    out.below_surface += located.below_surface;
    out.lowest_gap = std::min(out.lowest_gap, located.lowest_gap);
  }
  return out;
}

std::vector<std::vector<PathContact>> path_contacts(const PathGeometry& geometry) {
  std::vector<std::vector<PathContact>> passes;
  for (const auto& pass : geometry.passes) {
    passes.emplace_back();
    for (const PathPoint& p : pass) passes.back().push_back(p.in_air ? PathContact{} : p.contact);
  }
  return passes;
}

}  // namespace furrow
