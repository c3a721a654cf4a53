#pragma once
// Tool-size selection from a shop's tool library: per contact site the
// largest tool that does not gouge locally, and the largest tool that is
// gouge-free at every site.
//
// "Largest" orders by shank radius R, then corner radius r (both
// descending; names break ties so the order is deterministic). Gouge-freeness
// is not monotone in size across families (a small flat end mill gouges a
// concave wall that a bigger ball clears), so every tool is checked at every
// site: the per-site pick is the first gouge-free tool in that order, the
// whole-surface pick the first tool with no gouging site.
//
// Besides the local check, each tool is by default also checked for
// interference away from the contact: the cutter, located at the site, is
// lowered at its axis (contact_from_tip.hpp); if it would rest higher, it
// cuts into the part elsewhere (e.g. a flat end mill on the wall of a trough
// narrower than its bottom; no curvature at the contact shows that). Such a
// tool is not gouge-free there either. (Interference with face edges, where
// the cutter rests on an edge rather than on a tangency, is not detected.)
//
// Sites that no end mill can machine are excluded from the picks and
// counted: unreachable from above (n_z < 0; a vertical wall, n_z = 0, is cut with the
// side), degenerate normals, concave
// creases. Where even the smallest tool gouges, the result says by how much
// the design would have to change: in the smallest tool's worst direction the
// part's normal curvature and the most it may be there (the tool's own
// curvature in that direction), i.e. the radius of curvature the design would
// need.
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
};

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

struct ToolSelection {
  std::vector<Cutter> library;               // ordered largest first
  std::vector<std::size_t> gouging_sites;    // per tool: machinable sites where it gouges
  std::vector<std::size_t> interfering_sites;  // per tool: of those, by interference only
  int whole_surface = -1;                    // first tool with no gouging site, -1 none
  std::vector<SiteSelection> sites;          // in the order given
  std::size_t unmachinable = 0;              // sites excluded (see above)
  std::size_t without_tool = 0;              // machinable sites where every tool gouges
  std::size_t border_unresolved = 0;         // sites with border_search_converged false
};

// Throws InputError for an empty library.
ToolSelection select_tools(const Part& part, std::vector<Cutter> library,
                           const std::vector<ContactSite>& sites,
                           const ToolSelectionOptions& options = {},
                           const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace furrow
