#pragma once
// Every point of a tool path located on the part: its tool tip and its
// contact point (face, (u, v), surface point and normal).
//
//   - G-code / CSV tips: the contact is where the cutter, lowered at that xy,
//     rests on the part (contact_from_tip.hpp: the highest tangency). `gap`
//     is the tip's height above that resting position: 0 on the
//     cutter-location surface, > 0 in the air, < 0 when the tip is below it
//     (the cutter cuts into the part there: a gouge the z-map will show).
//   - CSV contact points with normals: the tip is the cutter location of the
//     given point and normal (what the CAM system meant); the contact on the
//     part is the point's (u, v) when the file gives it (checked against the
//     point), else its foot point (closest_point.hpp). A point farther than
//     `max_contact_distance` from the part, or whose normal has n_z < 0,
//     is an InputError naming the file and line: the path does not belong
//     to this part or cannot be cut from above.
// Tips more than `air_gap` above the part (approach, retract and link moves
// written as G1) are marked in_air: the per-step predictor skips moves from
// or to such a point (approach moves are not furrows; the z-map still
// applies them).
#include <functional>
#include <vector>

#include "io/machining/toolpath_file.hpp"
#include "geometry/closest_point.hpp"
#include "machining/cutter/contact_from_tip.hpp"
#include "machining/cutter/path_tools.hpp"
#include "machining/prediction/pass_scallops.hpp"

namespace furrow {

struct PathContactOptions {
  TipContactOptions tip;
  ClosestPointOptions projection;
  double max_contact_distance = 0.01;  // [mm]
  double air_gap = 1.0;                // [mm]
  // A tip lower than this under its resting position counts as below the
  // surface [mm], divided by the contact's n_z (the gap is vertical, and a
  // horizontal offset on a slope shows as a vertical one): G-code
  // coordinates have 4 decimals, so a tip written from an exact cutter
  // location may sit up to 0.05 um off it per axis.
  double below_margin = 1e-4;
  CutterLocationOptions location;
};

struct PathPoint {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  PathContact contact;  // invalid: no contact found under the tip
  double gap = 0;       // [mm], tips only (0 for contact-point input)
  bool in_air = false;
  int line = 0;         // source line
};

struct PathGeometry {
  std::vector<std::vector<PathPoint>> passes;
  std::size_t points = 0, without_contact = 0, in_air = 0;
  std::size_t below_surface = 0;  // tips with gap < -below_margin / n_z
  double lowest_gap = 0;          // [mm] most negative gap (0 when none)
};

// Contacts of every pass point. Parallel over points; deterministic.
// `progress(done, total)` counts points.
PathGeometry locate_path(const Part& part, const Cutter& cutter, const Toolpath& path,
                         const PathContactOptions& options = {},
                         const std::function<void(std::size_t, std::size_t)>& progress = {});

// The same for a program that changes tools: each pass located with the
// cutter it is cut with (tools.of_pass, machining/cutter/path_tools.hpp),
// the passes of one cutter together; the result is in path order. One
// cutter: exactly locate_path above.
PathGeometry locate_path(const Part& part, const PathTools& tools, const Toolpath& path,
                         const PathContactOptions& options = {},
                         const std::function<void(std::size_t, std::size_t)>& progress = {});

// The contacts pass by pass, as pass_scallops.hpp wants them.
std::vector<std::vector<PathContact>> path_contacts(const PathGeometry& geometry);

}  // namespace furrow
