#pragma once
// Circular and helical G-code arcs (G2/G3) flattened into the polyline the
// rest of the pipeline cuts (docs/formats.md "Tool paths").
//
// Coordinates are millimetres in the part frame (the reader has already
// applied G20/G21 and G90/G91). The arc lies in one of the planes G17 (XY,
// normal +Z), G18 (ZX, normal +Y) or G19 (YZ, normal +X); G2 turns clockwise
// and G3 counter-clockwise seen from the plane normal's positive side. Motion
// along the normal is linear in the swept angle (a helix).
//
// Why flatten here: every later stage (z-map sweeps, contact mapping, error
// prediction) works on straight moves. A polyline within a chord sag of
// 1e-4 mm (the default, ToolpathReadOptions::arc_tolerance) lies inside the
// arc by at most that sag, so the cut it predicts differs from the arc's by
// at most 0.1 µm, the resolution the reports print.
//
// Failure: an arc that does not describe one circle throws InputError with a
// message without file or line (the reader prefixes both): zero radius, a
// centre farther from the end than from the start by more than the radius
// tolerance, an R-format full circle, an R smaller than half the chord.
#include <Eigen/Core>
#include <vector>

namespace furrow {

enum class ArcPlane { xy = 17, zx = 18, yz = 19 };

struct ArcMove {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // mm, tool tip before the arc
  Eigen::Vector3d end = Eigen::Vector3d::Zero();    // mm, tool tip after it
  ArcPlane plane = ArcPlane::xy;
  bool clockwise = true;  // G2; false for G3
  // Either the centre as an offset from the start (I J K, mm; only the two
  // in-plane components are used) or a signed radius R (R < 0: the arc
  // longer than half a circle).
  bool by_radius = false;
  Eigen::Vector3d centre_offset = Eigen::Vector3d::Zero();
  double radius = 0;
};

struct ArcTolerances {
  double sag = 1e-4;  // mm, largest distance between a chord and the arc
  // Start and end radius may differ by max(absolute, relative * radius): CAM
  // posts round coordinates to 3-4 decimals (in inch 0.0001" = 2.5 µm), so an
  // exact match would refuse correct files. The radius then changes linearly
  // along the arc so both endpoints stay exact.
  double radius_absolute = 0.005;  // mm
  double radius_relative = 1e-3;
  // In-plane start and end closer than this are one point: with I J K a full
  // circle, with R an error.
  double same_point = 1e-9;  // mm
};

// Points after the start, the last one exactly `end`. Every point lies on the
// arc (to rounding); consecutive points are no farther apart in angle than a
// chord of sag `tolerances.sag` allows (measured on the larger of the start
// and end radii), and at least 4 per full turn.
std::vector<Eigen::Vector3d> flatten_arc(const ArcMove& arc, const ArcTolerances& tolerances = {});

}  // namespace furrow
