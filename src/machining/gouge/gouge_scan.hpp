#pragma once
// Local gouge check of one cutter at many contact sites of a part (the
// engine of `furrow gouge`): per site the part's curvature, the cutter
// location and curvature, and the border-aware directional comparison of
// compound_border.hpp. Parallel (OpenMP) over sites; each result depends on
// its site only, so the output does not depend on the thread count.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "machining/gouge/compound_border.hpp"
#include "machining/gouge/contact_sites.hpp"
#include "machining/gouge/local_gouge.hpp"

namespace furrow {

struct GougeScanOptions {
  GougeOptions gouge;
  BorderOptions border;
};

struct GougePoint {
  ContactSite site;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // the part's at the site
  double k1 = 0, k2 = 0;                              // the part's [1/mm]
  LocalGouge gouge;  // its cutter.normal is the contact normal used (mean at borders)
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();      // cutter location, when reachable
  unsigned sides = 0;                                 // domain sides (a border when non-zero)
  bool has_neighbour = false;
  std::size_t neighbour_face = 0;
  Eigen::Vector2d neighbour_uv = Eigen::Vector2d::Zero();
  double crease_angle = 0;  // [rad] between the faces' normals at a border
  bool border_search_converged = true;  // ContactSurfaces::border_search_converged
};

// The contact surfaces at a site and its gouge check in one call (also used
// by tool selection, which checks many cutters per site).
GougePoint check_site(const Cutter& cutter, const ContactSurfaces& surfaces,
                      const ContactSite& site, const GougeOptions& options);

// `progress(done, total)` is called now and then from one thread (may be
// empty).
std::vector<GougePoint> scan_gouges(
    const Part& part, const Cutter& cutter, const std::vector<ContactSite>& sites,
    const GougeScanOptions& options = {},
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace furrow
