#pragma once
// One probe point of a plan and the probe it is planned for (plan_file.hpp,
// docs/formats.md "Plan"): shared by the plan's points and its alignment.
#include <Eigen/Core>
#include <optional>
#include <string>

namespace furrow {

struct ProbeDefinition {
  std::string name;     // free text ("TESASTAR 2 mm ruby")
  double diameter = 0;  // ball diameter [mm], > 0
  double radius() const { return diameter / 2; }
};

// The orientation of an indexable probe head's tip (docs/cmm.md "Indexable
// heads"): A tilts the stylus away from -z, B turns it about z, degrees.
// Absent on points planned for the fixed vertical stylus.
struct TipAngles {
  double a = 0;  // [degrees]
  double b = 0;  // [degrees]
  bool operator==(const TipAngles& o) const { return a == o.a && b == o.b; }
  bool operator!=(const TipAngles& o) const { return !(*this == o); }
};

// A tip a plan uses (plan.json `tips`, docs/cmm.md "Tips chosen by the
// planner"): whether the head file listed it as qualified; one that is not
// must be qualified on the CMM before the program runs.
struct PlanTip {
  TipAngles angles;
  bool qualified = true;
  bool operator==(const PlanTip& o) const { return angles == o.angles && qualified == o.qualified; }
};

struct PlannedPoint {
  std::string id;    // unique, non-empty, no ',' or white space (also a DMIS label)
  int order = 0;     // execution order, unique, >= 1
  std::string face;  // Face::name() of the face it lies on
  std::size_t face_index = 0;
  std::optional<int> region;  // region index in the partition, if the plan has regions
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();       // nominal contact point [mm]
  Eigen::Vector3d ijk = Eigen::Vector3d::UnitZ();      // unit normal, out of the material
  Eigen::Vector3d approach = Eigen::Vector3d::Zero();  // probe centre where the touch starts [mm]
  Eigen::Vector3d retract = Eigen::Vector3d::Zero();   // probe centre after the touch [mm]
  std::optional<TipAngles> tip;  // with an indexable head: the tip that takes the point

  // Nominal probe-ball centre at contact: xyz + r ijk.
  Eigen::Vector3d centre(double probe_radius) const { return xyz + probe_radius * ijk; }
};

}  // namespace furrow
