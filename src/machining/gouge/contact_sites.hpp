#pragma once
// Where gouge checks and tool selection are run: contact sites, i.e. a face
// and a (u,v) on it, from a regular grid over every face or from contact
// points read from a file.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "io/machining/contact_point_file.hpp"
#include "geometry/closest_point.hpp"

namespace furrow {

struct ContactSite {
  std::size_t face = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  int grid_i = -1, grid_j = -1;  // node indices of a grid site (i along u)
  int line = 0;                  // source line of a site read from a file
  std::string id;                // id column of the file, if any
};

// The nodes of an n x n grid over each face's parameter rectangle (domain
// edges included, so borders between faces are checked) that the face's trim
// keeps; face by face, i along u outer. Throws InputError unless n >= 2.
std::vector<ContactSite> grid_sites(const Part& part, int n);

struct PointSiteOptions {
  double max_distance = 0.01;            // [mm] a contact point lies this close to the part
  double max_normal_deviation_deg = 5;   // a given normal agrees with the part's this well
  ClosestPointOptions projection;
};

// Sites for contact points read from a file (`source` names it in errors):
// each point is projected onto the part. Throws InputError naming
// `source:line` when a point is farther than max_distance from the part,
// when its normal (given, or the part's when none is given) has n_z < 0 so
// no 3-axis cutter can reach it from above, or when a given normal disagrees
// with the part's (a point on the wrong side or a reversed face).
std::vector<ContactSite> sites_from_points(const Part& part,
                                           const std::vector<ContactPointRecord>& points,
                                           const std::string& source,
                                           const PointSiteOptions& options = {});

// The sites of a command: the points of `points_file` (read in `units`) when
// it is not empty, else the grid_sites of `grid`.
std::vector<ContactSite> load_contact_sites(const Part& part, const std::string& points_file,
                                            const std::string& units, int grid,
                                            const PointSiteOptions& options = {});

}  // namespace furrow
