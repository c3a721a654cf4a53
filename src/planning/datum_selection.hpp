#pragma once
// Which features of the part align it on the CMM, and where they are probed
// (docs/cmm.md "Part alignment"; the result's layout: io/plan_alignment.hpp).
//
// Automatic choice (`--datums auto`), from the faces' analytic recognition
// (Face::analytic()):
//   A primary: the largest plane whose outward normal is +z (a vertical
//     stylus reaches it from above and it sets the z direction);
//   B secondary: the largest vertical plane facing ±x or ±y, probed as a
//     line of two points (a wall: the ball touches it horizontally with the
//     stylus vertical, where the shaft clears the part);
//   C tertiary: the largest vertical plane perpendicular to B, one point.
// Without two such walls, a bore or boss instead:
//   B secondary: the largest cylinder face with a vertical axis whose
//     reachable points at one height go round the axis (no gap wider than
//     `bore_max_gap_degrees`), 4 points spread by angle: its axis sets both
//     in-plane origins;
//   C tertiary: the largest vertical plane facing ±x or ±y, a line of two
//     points: its direction sets x or y (no origin).
// (A second bore for the direction would need a constructed line in DMIS,
// which this does not write.)
// Ties go to the lower face index. A face serves only when enough of its
// candidate points are admissible: inside its trim, `border` mm from its
// edges (trim loops and parameter boundary, edge_distance.hpp) and
// accessible (accessibility.hpp; tilt allowed up to 90 degrees for walls).
// Datum planes must be parallel to the CAD axes because DMIS DATSET names
// axes; a tilted plane is not a candidate.
// Named choice (`--datums FACE,FACE,FACE`): the same roles in that order
// (a cylinder named second makes the bore variant); a face that cannot
// play its role is an InputError naming it and why.
// When no A, B and C can be found automatically (a part of free-form faces,
// e.g. the mould), the alignment is `free_form`: three well-spread points on
// the largest face for the operator's best fit, the reason saying what was
// missing. Never an empty alignment: when not even those exist, InputError.
//
// Points on a feature are picked from a grid of candidates by farthest-point
// selection (spread, so the fit is well conditioned): 4 on A, the 2 farthest
// apart horizontally on B, on C the one nearest its candidates' centroid.
// Ids: DA1.., DB1.., DC1 and M1..M3. Deterministic.
//
// Units: mm, part frame.
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "geometry/part.hpp"
#include "io/plan_alignment.hpp"
#include "planning/accessibility.hpp"

namespace furrow {

struct DatumChoice {
  std::vector<std::string> faces;  // empty: automatic; else primary, secondary, tertiary face names
};

// "auto" or "FACE,FACE,FACE"; InputError naming `where` otherwise.
DatumChoice parse_datum_choice(const std::string& text, const std::string& where);
std::string to_string(const DatumChoice& choice);

struct DatumOptions {
  int plane_points = 4;
  int manual_points = 3;
  int grid = 24;       // candidate grid per parameter direction
  int area_grid = 64;  // midpoint-rule grid for face areas
  double border = 2;   // clearance from the face's edges [mm]
  int bore_points = 4;  // on a bore or boss, round the axis
  // A bore or boss serves when its reachable points at one height leave no
  // gap round the axis wider than this [degrees]: a half cylinder (a
  // rounded end) fixes its centre poorly.
  double bore_max_gap_degrees = 120;
};

// Area of the face's trimmed part [mm^2] (midpoint rule on `grid` x `grid`
// cells of the parameter rectangle).
double face_area(const Face& face, int grid);

// `access` carries the approach, retract and clearance plane of the plan.
PartAlignment choose_alignment(const Part& part, const ClosestPointFinder& finder, const ProbeGeometry& probe,
                               const AccessOptions& access, const DatumChoice& choice,
                               const DatumOptions& options = {});

}  // namespace furrow
