#pragma once
// The part alignment of a plan (plan.json "alignment", docs/cmm.md "Part
// alignment", docs/formats.md "Plan"): what the CMM programs measure before
// the free-form points so that the machine's part frame is the CAD frame.
//
// Two methods:
//   datums     3-2-1 on datum features of the part: A a plane facing +z
//              (sets the z direction and z = its height), B a line of two
//              points on a vertical plane facing ±y or ±x (its direction sets
//              x or y, its wall the other origin), C a point on a vertical
//              plane perpendicular to B's (the last origin). DMIS DATSET can
//              only name axes, so datum planes are parallel to the CAD axes;
//              `origin` is where the three meet, in CAD coordinates, which
//              the program translates back to the CAD origin. Without two
//              such walls: A, B a bore or boss with a vertical axis (both
//              in-plane origins), C a line on a wall (the direction).
//   free_form  no such planes (a single free-form face): `manual` holds
//              three well-spread points on the part the operator touches to
//              set the frame by the CMM's own best fit; furrow compare's
//              registration of all points is the fine alignment.
// In both, the operator first takes the points by joystick (the manual
// pre-alignment); with datums the program then re-measures them under
// program control.
//
// Points are ordinary plan points (ids unique over the whole plan, u, v on
// their face, approach and retract probe centres) with `order` counting 1, 2,
// ... within the alignment. Lengths in mm, part frame.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/plan_point.hpp"

namespace furrow {

struct DatumFeature {
  // cylinder: a bore or boss whose axis is perpendicular to the primary
  // plane, as secondary datum (its axis fixes both in-plane origins; the
  // tertiary, a point or a line on a wall, then fixes the turn about it).
  // The planner proposes it with a wall line as tertiary; DMIS measures it
  // as a circle (docs/cmm.md "Part alignment").
  enum class Kind { plane, line, point, cylinder };
  std::string label;  // "A", "B", "C": the DMIS feature is F(DATUM_<label>)
  Kind kind = Kind::plane;
  std::string face;   // the face the points lie on
  std::size_t face_index = 0;
  // Nominal geometry: plane: a point of it and its outward normal; line: its
  // first point and unit direction (first to last point, horizontal); point:
  // the point and its outward normal; cylinder: a point of its axis and the
  // axis (unit), with `radius`.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // outward normal of the face (cylinder: unused)
  double radius = 0;  // cylinder only [mm]
  char axis = 'Z';    // the part axis this datum's direction sets ('X', 'Y', 'Z'), 0 for none
  // The axis whose origin it sets, 0 for none (a cylinder sets both
  // in-plane origins by its kind; a line after a cylinder sets none).
  char origin_axis = 'Z';
  std::vector<PlannedPoint> points;
};
const char* to_string(DatumFeature::Kind kind);

struct PartAlignment {
  enum class Method { datums, free_form };
  Method method = Method::datums;
  std::vector<DatumFeature> datums;   // datums: A, B, C
  std::vector<PlannedPoint> manual;   // free_form: the points touched by hand
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // datums: the datum frame's origin [mm, CAD]
  std::string reason;                 // one sentence: why this method and these features

  // Every alignment point in measuring order.
  std::vector<PlannedPoint> points() const;
};
const char* to_string(PartAlignment::Method method);

}  // namespace furrow
