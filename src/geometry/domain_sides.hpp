#pragma once
// The four sides of a face's parameter rectangle: which sides a (u,v) lies
// on, and each side as a curve with its own running parameter (v along the
// u sides, u along the v sides). Face borders (compound_border.hpp, which
// adds the trim loops) and edge contacts (contact_from_tip.hpp) are found
// along them.
#include <Eigen/Core>
#include <utility>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

// Sides of a face's parameter rectangle (bit flags).
enum DomainSide : unsigned { kSideUMin = 1, kSideUMax = 2, kSideVMin = 4, kSideVMax = 8 };
constexpr unsigned kAllSides[] = {kSideUMin, kSideUMax, kSideVMin, kSideVMax};

// Sides (bit set) that (u,v) lies on, within `relative_tolerance` of the
// domain width.
unsigned domain_sides(const ParameterDomain& domain, const Eigen::Vector2d& uv,
                      double relative_tolerance);

// True for kSideUMin / kSideUMax (the side runs along v).
inline bool runs_along_v(unsigned side) { return side == kSideUMin || side == kSideUMax; }

// (u,v) at running parameter t along `side`, and the range of t.
Eigen::Vector2d side_uv(const ParameterDomain& domain, unsigned side, double t);
std::pair<double, double> side_range(const ParameterDomain& domain, unsigned side);

}  // namespace furrow
