#include "inspection/motion_manifold.hpp"

#include <ceres/manifold.h>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <cmath>

namespace furrow {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d k;
  k << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return k;
}

Eigen::Matrix3d rotation(const Eigen::Vector3d& r) {
  const double angle = r.norm();
  return angle > 0 ? Eigen::AngleAxisd(angle, r / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
}

Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& m) {
  const Eigen::AngleAxisd aa(m);
  return aa.angle() * aa.axis();
}

// The left Jacobian of the rotation vector, J(r) = d exp / d r seen from the
// left, and its inverse: exp(w) exp(r) = exp(r + J(r)^-1 w) to first order.
// Series below 1e-4 rad, where the closed forms lose their digits.
Eigen::Matrix3d left_jacobian(const Eigen::Vector3d& r) {
  const double t = r.norm();
  const Eigen::Matrix3d k = skew(r);
  const double a = t < 1e-4 ? 0.5 - t * t / 24 : (1 - std::cos(t)) / (t * t);
  const double b = t < 1e-4 ? 1.0 / 6 - t * t / 120 : (t - std::sin(t)) / (t * t * t);
  return Eigen::Matrix3d::Identity() + a * k + b * k * k;
}

Eigen::Matrix3d inverse_left_jacobian(const Eigen::Vector3d& r) {
  const double t = r.norm();
  const Eigen::Matrix3d k = skew(r);
  const double c =
      t < 1e-4 ? 1.0 / 12 + t * t / 720 : (1 - t * std::sin(t) / (2 * (1 - std::cos(t)))) / (t * t);
  return Eigen::Matrix3d::Identity() - 0.5 * k + c * k * k;
}

// The inverse of twist_to_parameters: the twist a change of the parameters
// makes, w = J(r) dr, v = dt + t x w.
Matrix6 parameters_to_twist(const Vector6& x) {
  const Eigen::Matrix3d j = left_jacobian(x.head<3>());
  Matrix6 m = Matrix6::Zero();
  m.topLeftCorner<3, 3>() = j;
  m.bottomLeftCorner<3, 3>() = skew(x.tail<3>()) * j;
  m.bottomRightCorner<3, 3>().setIdentity();
  return m;
}

class MotionSubspace : public ceres::Manifold {
 public:
  MotionSubspace(const MotionBasis& basis, MotionFrame frame)
      : basis_(basis), left_inverse_(basis.completeOrthogonalDecomposition().pseudoInverse()), frame_(frame) {}
  int AmbientSize() const override { return 6; }
  int TangentSize() const override { return static_cast<int>(basis_.cols()); }

  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    const Vector6 step = basis_ * Eigen::Map<const Eigen::VectorXd>(delta, basis_.cols());
    const Eigen::Map<const Vector6> at(x);
    Eigen::Map<Vector6> out(x_plus_delta);
    out = frame_ == MotionFrame::parameters ? Vector6(at + step) : compose_twist(step, at);
    return true;
  }
  bool PlusJacobian(const double* x, double* jacobian) const override {
    Eigen::Map<RowMajor> out(jacobian, 6, basis_.cols());
    if (frame_ == MotionFrame::parameters)
      out = basis_;
    else
      out = twist_to_parameters(Eigen::Map<const Vector6>(x)) * basis_;
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    const Eigen::Map<const Vector6> to(y), from(x);
    const Vector6 difference = frame_ == MotionFrame::twist ? twist_between(to, from) : Vector6(to - from);
    Eigen::Map<Eigen::VectorXd> out(y_minus_x, basis_.cols());
    out = left_inverse_ * difference;
    return true;
  }
  bool MinusJacobian(const double* x, double* jacobian) const override {
    Eigen::Map<RowMajor> out(jacobian, basis_.cols(), 6);
    if (frame_ == MotionFrame::parameters)
      out = left_inverse_;
    else
      out = left_inverse_ * parameters_to_twist(Eigen::Map<const Vector6>(x));
    return true;
  }

 private:
  MotionBasis basis_;
  Eigen::MatrixXd left_inverse_;
  MotionFrame frame_;
};

}  // namespace

std::unique_ptr<ceres::Manifold> make_motion_manifold(const MotionBasis& basis, MotionFrame frame) {
  return std::make_unique<MotionSubspace>(basis, frame);
}

Matrix6 twist_to_parameters(const Vector6& x) {
  // dr = J(r)^-1 w; dt = v + w x t = v - [t]x w.
  Matrix6 m = Matrix6::Zero();
  m.topLeftCorner<3, 3>() = inverse_left_jacobian(x.head<3>());
  m.bottomLeftCorner<3, 3>() = -skew(x.tail<3>());
  m.bottomRightCorner<3, 3>().setIdentity();
  return m;
}

Vector6 twist_between(const Vector6& to, const Vector6& from) {
  const Eigen::Matrix3d rw = rotation(to.head<3>()) * rotation(from.head<3>()).transpose();
  Vector6 out;
  out.head<3>() = rotation_vector(rw);
  out.tail<3>() = to.tail<3>() - rw * from.tail<3>();
  return out;
}

Vector6 compose_twist(const Vector6& twist, const Vector6& x) {
  const Eigen::Matrix3d rw = rotation(twist.head<3>());
  Vector6 out;
  out.head<3>() = rotation_vector(rw * rotation(x.head<3>()));
  out.tail<3>() = rw * x.tail<3>() + twist.tail<3>();
  return out;
}

}  // namespace furrow
