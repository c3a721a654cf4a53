#include "machining/gouge/gouge_scan.hpp"

#include <omp.h>

namespace furrow {

GougePoint check_site(const Cutter& cutter, const ContactSurfaces& surfaces,
                      const ContactSite& site, const GougeOptions& options) {
  GougePoint p;
  p.site = site;
  p.point = surfaces.geometry.point;
  p.normal = surfaces.geometry.normal;
  p.k1 = surfaces.geometry.k1;
  p.k2 = surfaces.geometry.k2;
  p.sides = surfaces.sides;
  p.has_neighbour = surfaces.has_neighbour;
  p.neighbour_face = surfaces.neighbour_face;
  p.neighbour_uv = surfaces.neighbour_uv;
  p.crease_angle = surfaces.crease_angle;
  p.border_search_converged = surfaces.border_search_converged;
  p.gouge = check_contact(cutter, surfaces, options);
  if (p.gouge.cutter.reachable) {
    // Located as checked: same contact normal, same axis side.
    CutterLocationOptions placed = options.location;
    placed.horizontal_side = p.gouge.cutter.toward_axis;
    p.tip = cutter_location(cutter, p.point, p.gouge.cutter.normal, placed).tip;
  }
  return p;
}

std::vector<GougePoint> scan_gouges(const Part& part, const Cutter& cutter,
                                    const std::vector<ContactSite>& sites,
                                    const GougeScanOptions& options,
                                    const std::function<void(std::size_t, std::size_t)>& progress) {
  const BorderLocator locator(part, options.border);
  std::vector<GougePoint> points(sites.size());
  const long n = static_cast<long>(sites.size());
  long done = 0;
#pragma omp parallel for schedule(dynamic, 256)
  for (long k = 0; k < n; ++k) {
    const ContactSite& site = sites[static_cast<std::size_t>(k)];
    points[static_cast<std::size_t>(k)] =
        check_site(cutter, contact_surfaces(locator, site.face, site.uv), site, options.gouge);
    if (progress) {
      long seen;
#pragma omp atomic capture
      seen = ++done;
      if (omp_get_thread_num() == 0 && k % 4096 == 0) progress(static_cast<std::size_t>(seen), sites.size());
    }
  }
  if (progress) progress(sites.size(), sites.size());
  return points;
}

}  // namespace furrow
