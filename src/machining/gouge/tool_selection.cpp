#include "machining/gouge/tool_selection.hpp"

#include <omp.h>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "base/error.hpp"

namespace furrow {

namespace {

// The cutter located by `g` at `point`, lowered at its axis: whether it
// rests more than `tolerance` above its location (it cuts in elsewhere), by
// the bounded search's decision form, which stops at the first point that
// proves it. A search that hit its cell cap counts as interfering (a clear
// verdict is passed on to nested tools, so it must be proven). The depth,
// reported only for a site's smallest tool, is then measured in full by
// `finder` when given.
struct Interference {
  bool interferes = false;
  double depth = 0;  // [mm] how far above its location the cutter rests, when interferes
};

Interference interference(const Cutter& cutter, const DropCutter& drop, const TipContactFinder* finder,
                          const Eigen::Vector3d& point, const LocalGouge& g, const GougeOptions& options,
                          double tolerance) {
  CutterLocationOptions placed = options.location;
  placed.horizontal_side = g.cutter.toward_axis;
  const CutterLocation loc = cutter_location(cutter, point, g.cutter.normal, placed);
  const DropCutterResult d = drop.rests_above(loc.tip.head<2>(), loc.tip.z() + tolerance);
  Interference out;
  out.interferes = d.tip_z > loc.tip.z() + tolerance || !d.complete;
  if (!out.interferes || !finder) return out;
  const TipContactResult r = finder->find(loc.tip);
  out.depth = r.status == TipContactStatus::found ? -r.gap : 0.0;
  if (!r.complete) out.depth = std::max(out.depth, r.unresolved - loc.tip.z());
  // The decision proved a point at least this high.
  out.depth = std::max(out.depth, d.tip_z - loc.tip.z());
  if (!d.complete) out.depth = std::max(out.depth, d.unresolved - loc.tip.z());
  return out;
}

}  // namespace

bool cutter_contains(const Cutter& outer, const Cutter& inner) {
  return inner.flat_radius() <= outer.flat_radius() && inner.corner_radius() <= outer.corner_radius();
}

std::vector<Cutter> order_by_size(std::vector<Cutter> library) {
  std::stable_sort(library.begin(), library.end(), [](const Cutter& a, const Cutter& b) {
    if (a.radius() != b.radius()) return a.radius() > b.radius();
    if (a.corner_radius() != b.corner_radius()) return a.corner_radius() > b.corner_radius();
    return a.name() < b.name();
  });
  return library;
}

ToolSelection select_tools(const Part& part, std::vector<Cutter> library,
                           const std::vector<ContactSite>& sites,
                           const ToolSelectionOptions& options,
                           const std::function<void(std::size_t, std::size_t)>& progress) {
  if (library.empty()) throw InputError("tool selection: the tool library is empty");
  ToolSelection result;
  result.library = order_by_size(std::move(library));
  const std::size_t tools = result.library.size();
  // contains[outer * tools + inner]: only outer < inner can hold (the order).
  std::vector<unsigned char> contains(tools * tools, 0);
  for (std::size_t a = 0; a < tools; ++a)
    for (std::size_t b = a + 1; b < tools; ++b)
      contains[a * tools + b] = cutter_contains(result.library[a], result.library[b]);
  const bool share = options.check_interference && options.share_interference;
  // Each tool's bounded search; the full contact search only for the
  // smallest tool, whose interference depth is reported.
  std::vector<std::unique_ptr<DropCutter>> drops;
  std::unique_ptr<TipContactFinder> smallest;
  if (options.check_interference) {
    for (const Cutter& c : result.library)
      drops.push_back(std::make_unique<DropCutter>(part, c, options.contact.bound));
    smallest = std::make_unique<TipContactFinder>(part, result.library.back(), options.contact);
  }

  result.sites.resize(sites.size());
  std::vector<ToolVerdict>& verdicts = result.verdicts;
  verdicts.assign(sites.size() * tools, ToolVerdict::clear);
  std::vector<unsigned> searches(sites.size(), 0);
  const GougeOptions& gouge = options.scan.gouge;
  const BorderLocator locator(part, options.scan.border);
  const long n = static_cast<long>(sites.size());
  long done = 0;
#pragma omp parallel for schedule(dynamic, 16)
  for (long k = 0; k < n; ++k) {
    const ContactSite& site = sites[static_cast<std::size_t>(k)];
    const ContactSurfaces surfaces = contact_surfaces(locator, site.face, site.uv);
    SiteSelection& s = result.sites[static_cast<std::size_t>(k)];
    ToolVerdict* verdict = &verdicts[static_cast<std::size_t>(k) * tools];
    s.site = site;
    s.point = surfaces.geometry.point;
    s.normal = surfaces.geometry.normal;
    s.k1 = surfaces.geometry.k1;
    s.k2 = surfaces.geometry.k2;
    s.border_search_converged = surfaces.border_search_converged;
    // The clear tools so far and how each was located (normal, axis side).
    std::vector<std::size_t> clear;
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> placed(tools);
    for (std::size_t t = 0; t < tools; ++t) {
      const Cutter& cutter = result.library[t];
      const LocalGouge g = check_contact(cutter, surfaces, gouge);
      const bool last = t + 1 == tools;
      if (g.status == GougeStatus::unreachable || g.status == GougeStatus::degenerate ||
          g.status == GougeStatus::concave_crease) {
        s.machinable = false;
        s.smallest_status = g.status;
        break;
      }
      double depth = 0;
      if (g.gouges()) {
        verdict[t] = ToolVerdict::local;
      } else if (options.check_interference) {
        placed[t] = {g.cutter.normal, g.cutter.toward_axis};
        // A clear container located the same way decides it (the header);
        // the depth is then never reported, as this site has a tool.
        const bool inside_clear = share && std::any_of(clear.begin(), clear.end(), [&](std::size_t a) {
          return contains[a * tools + t] && placed[a] == placed[t];
        });
        if (!inside_clear) {
          const Interference i = interference(cutter, *drops[t], last ? smallest.get() : nullptr, s.point,
                                              g, gouge, options.interference_tolerance);
          ++searches[static_cast<std::size_t>(k)];
          if (i.interferes) verdict[t] = ToolVerdict::interferes;
          depth = i.depth;
        }
      }
      if (verdict[t] == ToolVerdict::clear) clear.push_back(t);
      if (verdict[t] == ToolVerdict::clear && s.tool < 0) s.tool = static_cast<int>(t);
      if (!last) continue;
      s.smallest_status = g.status;
      if (s.tool >= 0) continue;
      s.smallest_gouges_locally = g.gouges();
      if (verdict[t] == ToolVerdict::interferes) s.interference = depth;
      if (g.gouges()) {
        s.needed.direction = g.direction(g.max_excess_angle);
        s.needed.excess = g.max_excess;
        // The part's curvature in that direction, from the face it points
        // into (the neighbour's at a border when it points there).
        const DifferentialGeometry* geometry = &surfaces.geometry;
        if (surfaces.has_neighbour && surfaces.neighbour_inward_count > 0 &&
            s.needed.direction.dot(surfaces.neighbour_inward[0]) > 0)
          geometry = &surfaces.neighbour_geometry;
        s.needed.design_curvature = geometry->normal_curvature(s.needed.direction);
        s.needed.allowed_curvature = s.needed.design_curvature - s.needed.excess;
      }
    }
    if (progress) {
      long seen;
#pragma omp atomic capture
      seen = ++done;
      if (omp_get_thread_num() == 0 && k % 256 == 0) progress(static_cast<std::size_t>(seen), sites.size());
    }
  }
  if (progress) progress(sites.size(), sites.size());

  result.gouging_sites.assign(tools, 0);
  result.interfering_sites.assign(tools, 0);
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const SiteSelection& s = result.sites[k];
    result.border_unresolved += !s.border_search_converged;
    result.interference_searches += searches[k];
    if (!s.machinable) {
      ++result.unmachinable;
      continue;
    }
    if (s.tool < 0) ++result.without_tool;
    for (std::size_t t = 0; t < tools; ++t) {
      result.gouging_sites[t] += verdicts[k * tools + t] != ToolVerdict::clear;
      result.interfering_sites[t] += verdicts[k * tools + t] == ToolVerdict::interferes;
    }
  }
  for (std::size_t t = 0; t < tools && result.whole_surface < 0; ++t)
    if (result.gouging_sites[t] == 0) result.whole_surface = static_cast<int>(t);
  return result;
}

}  // namespace furrow
