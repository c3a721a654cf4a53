// The fit's restricted motions (motion_manifold.hpp). Oracles: rigid
// motions composed as Eigen isometries (not the manifold's own algebra),
// and central finite differences of Plus and Minus for their Jacobians, at
// fixed points from no turn to nearly half a turn.
#include <doctest/doctest.h>

#include <ceres/manifold.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "inspection/motion_manifold.hpp"

// Ceres brings glog, whose CHECK (abort on failure) replaces doctest's:
// the checks below are spelled DOCTEST_CHECK.
using namespace furrow;

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

Eigen::Isometry3d motion_of(const Vector6& x) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  const double angle = x.head<3>().norm();
  if (angle > 0) m.linear() = Eigen::AngleAxisd(angle, x.head<3>() / angle).toRotationMatrix();
  m.translation() = x.tail<3>();
  return m;
}

// Corrections from none to 3 rad, and a few millimetres to a metre away.
std::vector<Vector6> corrections() {
  std::vector<Vector6> out;
  Vector6 x;
  out.push_back(Vector6::Zero());
  x << 1e-9, -2e-9, 3e-9, 0.5, -0.2, 0.1;
  out.push_back(x);
  x << 0.02, -0.05, 0.01, 12, -4, 30;
  out.push_back(x);
  x << 0.4, 1.1, -0.7, -250, 140, 35;
  out.push_back(x);
  x << 2.9, 0.3, -0.5, 1000, -20, 3;
  out.push_back(x);
  return out;
}

// Two motions of the points: a turn about an axis through (10, 20, 0) mm
// with some slide, and a pure slide.
MotionBasis basis() {
  MotionBasis b(6, 2);
  const Eigen::Vector3d w = Eigen::Vector3d(0.3, -0.2, 0.9).normalized(), p(10, 20, 0);
  b.col(0) << w, -w.cross(p) + 0.1 * w;
  b.col(1) << 0, 0, 0, 0.6, 0.8, 0;
  return b;
}

}  // namespace

TEST_CASE("motion manifold: a twist moves the corrected points by that rigid motion, whatever the correction") {
  const Eigen::Vector3d y(17, -42, 8);
  for (const Vector6& x : corrections()) {
    CAPTURE(x.transpose());
    Vector6 twist;
    twist << 0.03, -0.01, 0.2, 1.5, -0.5, 2;
    const Vector6 after = compose_twist(twist, x);
    // The oracle: the twist's motion applied after the correction's.
    const Eigen::Vector3d expected = motion_of(twist) * (motion_of(x) * y);
    DOCTEST_CHECK((motion_of(after) * y - expected).norm() < 1e-9);
    DOCTEST_CHECK((twist_between(after, x) - twist).norm() < 1e-9);
  }
}

TEST_CASE("motion manifold: twist_to_parameters is the derivative of compose_twist at no twist") {
  for (const Vector6& x : corrections()) {
    CAPTURE(x.transpose());
    const Eigen::Matrix<double, 6, 6> m = twist_to_parameters(x);
    for (int k = 0; k < 6; ++k) {
      const double h = 1e-6;
      const Vector6 e = Vector6::Unit(k) * h;
      const Vector6 fd = (compose_twist(e, x) - compose_twist(-e, x)) / (2 * h);
      CAPTURE(k);
      DOCTEST_CHECK((fd - m.col(k)).norm() < 1e-6 * std::max(1.0, x.tail<3>().norm()));
    }
  }
}

TEST_CASE("motion manifold: Plus and Minus are inverse on the span, their Jacobians are the finite differences") {
  const MotionBasis b = basis();
  for (const MotionFrame frame : {MotionFrame::parameters, MotionFrame::twist}) {
    const auto manifold = make_motion_manifold(b, frame);
    REQUIRE(manifold->AmbientSize() == 6);
    REQUIRE(manifold->TangentSize() == 2);
    for (const Vector6& x : corrections()) {
      CAPTURE(x.transpose());
      CAPTURE(frame == MotionFrame::twist);
      const Eigen::Vector2d delta(0.013, -0.7);
      Vector6 y;
      DOCTEST_CHECK(manifold->Plus(x.data(), delta.data(), y.data()));
      Eigen::Vector2d back;
      DOCTEST_CHECK(manifold->Minus(y.data(), x.data(), back.data()));
      DOCTEST_CHECK((back - delta).norm() < 1e-9);
      if (frame == MotionFrame::parameters) DOCTEST_CHECK((y - x - b * delta).norm() < 1e-12);

      Eigen::Matrix<double, 6, 2, Eigen::RowMajor> plus;
      Eigen::Matrix<double, 2, 6, Eigen::RowMajor> minus;
      DOCTEST_CHECK(manifold->PlusJacobian(x.data(), plus.data()));
      DOCTEST_CHECK(manifold->MinusJacobian(x.data(), minus.data()));
      const double h = 1e-6, scale = std::max(1.0, x.tail<3>().norm());
      for (int k = 0; k < 2; ++k) {
        Eigen::Vector2d d = Eigen::Vector2d::Zero();
        d(k) = h;
        Vector6 a, c;
        manifold->Plus(x.data(), d.data(), a.data());
        const Eigen::Vector2d md = -d;
        manifold->Plus(x.data(), md.data(), c.data());
        DOCTEST_CHECK(((a - c) / (2 * h) - plus.col(k)).norm() < 1e-6 * scale);
      }
      for (int k = 0; k < 6; ++k) {
        const Vector6 a = x + Vector6::Unit(k) * h, c = x - Vector6::Unit(k) * h;
        Eigen::Vector2d ma, mc;
        manifold->Minus(a.data(), x.data(), ma.data());
        manifold->Minus(c.data(), x.data(), mc.data());
        DOCTEST_CHECK(((ma - mc) / (2 * h) - minus.col(k)).norm() < 1e-6 * scale);
      }
      // Minus after Plus along the tangent: the identity on it.
      DOCTEST_CHECK((minus * plus - Eigen::Matrix2d::Identity()).norm() < 1e-9);
    }
  }
}
