#pragma once
// Predicted gouge sites: connected areas of a face where the z-map error map
// (error_map.hpp) shows an overcut deeper than a threshold (docs/architecture.md
// "Inspection": the sites gouge confirmation later checks one by one).
//
// Per face, the samples with error < -threshold form a binary image over
// (u, v); its 8-connected components (OpenCV connectedComponentsWithStats)
// are the sites. Each site has its depth (the largest overcut, refined from
// the deepest sample by a local search on the exact z-map error), where that
// is, its area on the surface (area element times the sample's parameter
// area), its area-weighted centroid, and its extent in xyz and in (u, v)
// (sample cells, so the uv box covers every flagged sample completely).
// Ids run 1, 2, ... face by face in raster order of the component's first
// sample: deterministic.
#include <Eigen/Geometry>
#include <vector>

#include "machining/prediction/error_map.hpp"

namespace furrow {

struct GougeSiteOptions {
  double threshold = 0.01;  // [mm] overcut deeper than this belongs to a site
};

struct GougeSite {
  int id = 0;
  std::size_t face = 0;
  double depth = 0;               // [mm] largest overcut, > threshold
  SurfacePoint deepest;           // where it is
  double area = 0;                // [mm^2] on the surface
  int samples = 0;                // error-map samples in the site
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();     // area-weighted, on the samples
  Eigen::Vector2d centroid_uv = Eigen::Vector2d::Zero();
  Eigen::AlignedBox3d box;        // of the samples' surface points
  Eigen::AlignedBox2d uv_box;     // of the samples' parameter cells
};

std::vector<GougeSite> find_gouge_sites(const Part& part, const ZMap& zmap, const ErrorMap& map,
                                        const GougeSiteOptions& options = {},
                                        const ErrorMapOptions& refine = {});

}  // namespace furrow
