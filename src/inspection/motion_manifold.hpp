#pragma once
// How the fit's correction may move when only some motions are allowed
// (surface_fit.hpp restrict_motion): the Ceres manifold over the six
// parameters x = (r, t) of the correction y -> R(r) y + t (r: rotation
// vector [rad], t [mm]), with the allowed motions as the columns of a basis
// B, in one of two senses:
//
//   parameters: x + B delta. A column is a change of the parameters
//     themselves. This is what locking degrees of freedom means (--dof
//     tx,...: the fitted transform's own x translation stays put).
//   twist: the points already corrected are moved once more by the rigid
//     motion delta_w x p + delta_v about the part origin, (delta_w,
//     delta_v) = B delta. A column is a motion of the corrected points, as
//     the observability analysis finds them (observability.hpp), and it is
//     the same motion whatever the correction so far. Taken as a change of
//     the parameters instead, it would be a different motion once r is not
//     zero: a held symmetry mixed, by about |r| / 2, with motions the
//     points do see, and the fit kept from its least-squares optimum in
//     them (docs/registration.md "Weakly constrained directions").
//
// Both are exact to round-off; Plus and Minus are inverse on span(B).
#include <Eigen/Core>
#include <memory>

#include "inspection/observability.hpp"

namespace ceres {
class Manifold;
}

namespace furrow {

enum class MotionFrame { parameters, twist };

// The manifold for a basis of 1 to 5 columns (6 columns need none; the
// caller leaves the block unconstrained).
std::unique_ptr<ceres::Manifold> make_motion_manifold(const MotionBasis& basis, MotionFrame frame);

// d x / d (w, v) at delta = 0 for the twist sense: the change of the
// parameters x that moves the corrected points by w x p + v. Rows and
// columns: rx ry rz tx ty tz.
Eigen::Matrix<double, 6, 6> twist_to_parameters(const Eigen::Matrix<double, 6, 1>& x);

// The parameters of the correction after the twist (w, v): rotation vector
// of R(w) R(r), translation R(w) t + v.
Eigen::Matrix<double, 6, 1> compose_twist(const Eigen::Matrix<double, 6, 1>& twist,
                                          const Eigen::Matrix<double, 6, 1>& x);

// The twist (w, v) with compose_twist((w, v), from) = to.
Eigen::Matrix<double, 6, 1> twist_between(const Eigen::Matrix<double, 6, 1>& to,
                                          const Eigen::Matrix<double, 6, 1>& from);

}  // namespace furrow
