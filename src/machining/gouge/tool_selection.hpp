#pragma once
// Tool-size selection from a shop's tool library: per contact site the
// largest tool that does not gouge locally, and the largest tool that is
// gouge-free at every site.
//
// "Largest" orders by shank radius R, then corner radius r (both
// descending; names break ties so the order is deterministic). Gouge-freeness
// is not monotone in size across families (a small flat end mill gouges a
// concave wall that a bigger ball clears), so every tool gets a verdict at
// every site (the per-tool counts of the output need them all): the per-site
// pick is the first gouge-free tool in that order, the whole-surface pick the
// first tool with no gouging site.
//
// Shared interference verdicts (docs/tool_selection.md), on by default:
// the local check is cheap, the interference search (a bounded drop-cutter
// decision, drop_cutter.hpp) is not. Two end mills located at the same contact
// point with the same normal and axis side nest when the inner one has
// neither a wider flat bottom nor a larger corner radius (cutter_contains);
// a part that does not reach into the outer cutter cannot reach into the
// inner one. So once a tool is clear at a site, every tool it contains that
// is locally clear there can be taken as clear without its own search (tools
// are visited largest first, so every container comes first). Every per-site
// result (pick, needed curvature, interference depth) is then the same as
// with every search run: up to a site's pick nothing is skipped, and a site
// without a tool had no clear container. Per-tool verdicts agree too as far
// as the search is exact: the bounded drop cutter proves a clear verdict to
// within its height tolerance, and a search that hits its cell cap counts the cutter as
// resting as high as it may (never clear on a guess). A verdict can differ
// only where a container's depth lies within that tolerance above
// interference_tolerance.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "machining/cutter/contact_from_tip.hpp"
#include "machining/gouge/gouge_scan.hpp"

namespace furrow {

// The library sorted largest first (R, then r, descending; then by name).
std::vector<Cutter> order_by_size(std::vector<Cutter> library);

struct NeededCurvature {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // worst tangent direction (unit)
  double design_curvature = 0;   // the part's normal curvature there [1/mm]
  double allowed_curvature = 0;  // the smallest tool's there: the most the part may have
  double excess = 0;             // design - allowed [1/mm]
};

struct ToolSelectionOptions {
  GougeScanOptions scan;
  // Also reject tools that interfere away from the contact.
  bool check_interference = true;
  // A cutter resting more than this above its location interferes [mm].
  double interference_tolerance = 1e-6;
  TipContactOptions contact;
  // Take a tool's interference verdict from a clear tool containing it
  // (above): several times faster, the same results. False: every tool's
  // own search.
  bool share_interference = true;
};

// Whether `inner`, located at any contact point with the same normal and
// axis side as `outer`, lies inside `outer`: both are the flat-bottom disc
// of radius R - r (extended up the axis) swept by a ball of radius r, and
// the inner one's disc and ball fit when R_in - r_in <= R_out - r_out and
// r_in <= r_out (docs/tool_selection.md). A ball fits in a bull-nose of at
// least its radius; no bull-nose fits in a ball.
bool cutter_contains(const Cutter& outer, const Cutter& inner);

struct SiteSelection {
  ContactSite site;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double k1 = 0, k2 = 0;
  GougeStatus smallest_status = GougeStatus::clear;  // the smallest tool's result here
  bool machinable = true;  // not unreachable, degenerate or a concave crease
  int tool = -1;           // index into ToolSelection::library, -1 if every tool gouges
  // When machinable and tool == -1: by how much the design's curvature
  // would have to change for the smallest tool (when it gouges locally), or
  // how deep the smallest tool, located here, cuts in elsewhere.
  bool smallest_gouges_locally = false;
  NeededCurvature needed;       // when smallest_gouges_locally
  double interference = 0;      // [mm] > 0 when the smallest tool interferes
  // False on a border point whose neighbour search did not converge
  // (ContactSurfaces::border_search_converged): checked as a free edge.
  bool border_search_converged = true;
};

// What a tool does at a site.
enum class ToolVerdict : unsigned char {
  clear = 0,       // gouge-free (also for unmachinable sites: no verdict)
  local = 1,       // gouges by the local curvature comparison
  interferes = 2,  // locally clear, but cuts into the part away from the contact
};

struct ToolSelection {
  std::vector<Cutter> library;               // ordered largest first
  std::vector<std::size_t> gouging_sites;    // per tool: machinable sites where it gouges
  std::vector<std::size_t> interfering_sites;  // per tool: of those, by interference only
  int whole_surface = -1;                    // first tool with no gouging site, -1 none
  std::vector<SiteSelection> sites;          // in the order given
  std::size_t unmachinable = 0;              // sites excluded (see above)
  std::size_t without_tool = 0;              // machinable sites where every tool gouges
  std::size_t border_unresolved = 0;         // sites with border_search_converged false
  std::vector<ToolVerdict> verdicts;           // [site * library.size() + tool]
  // Interference searches run (a cost figure, not a result: it depends on
  // ToolSelectionOptions::share_interference, nothing else does).
  std::size_t interference_searches = 0;
};

// Throws InputError for an empty library.
ToolSelection select_tools(const Part& part, std::vector<Cutter> library,
                           const std::vector<ContactSite>& sites,
                           const ToolSelectionOptions& options = {},
                           const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace furrow
