// SurfaceFit keeps one residual block per point in an array of its own cost
// functions (no per-point heap functor, the problem does not own them;
// docs/registration.md "Memory"). Oracle: a second implementation of the
// same inner problem written here the ordinary way - one
// ceres::AutoDiffCostFunction per point, owned by the problem - solved with
// the same options. Both must land on the same parameters and covariance.
#include <doctest/doctest.h>

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <cmath>
#include <random>
#include <vector>

#include "inspection/registration.hpp"
#include "inspection/surface_fit.hpp"

// Ceres brings glog, whose CHECK (abort on failure) replaces doctest's:
// the checks below are spelled DOCTEST_CHECK.
using namespace furrow;

namespace {

// The residual of surface_fit.hpp, written from its contract: e = R(r) y +
// t - f; inside a face n . e - r_probe, on a boundary sign |e| - r_probe;
// zero for a point out of the fit; times the point's weight (the solver's
// residual w d).
struct Reference {
  Eigen::Vector3d y, foot, normal;
  bool active, boundary;
  double sign, radius;
  double weight = 1;

  template <class T>
  bool operator()(const T* const x, T* residual) const {
    distance(x, residual);
    residual[0] *= weight;
    return true;
  }

  template <class T>
  bool distance(const T* const x, T* residual) const {
    if (!active) {
      residual[0] = T(0);
      return true;
    }
    const T yy[3] = {T(y.x()), T(y.y()), T(y.z())};
    T ry[3];
    ceres::AngleAxisRotatePoint(x, yy, ry);
    T e[3];
    for (int k = 0; k < 3; ++k) e[k] = ry[k] + x[3 + k] - foot[k];
    if (boundary) {
      using std::sqrt;
      const T e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
      if (e2 > T(1e-24)) {
        residual[0] = sign * sqrt(e2) - radius;
        return true;
      }
    }
    T along = T(-radius);
    for (int k = 0; k < 3; ++k) along += normal[k] * e[k];
    residual[0] = along;
    return true;
  }
};

}  // namespace

TEST_CASE("surface fit: its array of residual blocks solves like one AutoDiffCostFunction per point") {
  // Points near a wavy surface z = 0.5 sin(x/7) cos(y/9), feet on it with
  // its normals, every 7th foot on a "boundary", every 11th point out of
  // the fit, a Cauchy loss (so the loss correction of the Jacobian counts)
  // and a probe radius: every branch of the residual.
  const double radius = 1.5;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-40, 40), offset(-0.05, 0.05);
  const std::size_t n = 3000;
  std::vector<Eigen::Vector3d> y(n), foot(n), normal(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = coord(rng), v = coord(rng);
    foot[i] = {u, v, 0.5 * std::sin(u / 7) * std::cos(v / 9)};
    const Eigen::Vector3d du(1, 0, 0.5 / 7 * std::cos(u / 7) * std::cos(v / 9));
    const Eigen::Vector3d dv(0, 1, -0.5 / 9 * std::sin(u / 7) * std::sin(v / 9));
    normal[i] = du.cross(dv).normalized();
    // Measured off the surface by the radius plus a little, then moved by
    // a small rigid motion the fit has to undo.
    y[i] = foot[i] + (radius + offset(rng)) * normal[i];
  }
  const Eigen::AngleAxisd turn(0.01, Eigen::Vector3d(1, 2, 3).normalized());
  const Eigen::Vector3d shift(0.2, -0.1, 0.05);
  for (Eigen::Vector3d& p : y) p = turn * p + shift;

  SurfaceFit fit(y, radius, DegreesOfFreedom{}, RobustLoss::cauchy, 0.05, 5);
  std::vector<Reference> reference(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool active = i % 11 != 0, boundary = i % 7 == 0;
    fit.set_foot(i, foot[i], normal[i], active, boundary);
    // The side of the tangent plane at the start, as set_foot records it.
    const double sign = normal[i].dot(y[i] - foot[i]) >= 0 ? 1.0 : -1.0;
    reference[i] = Reference{y[i], foot[i], normal[i], active, boundary, sign, radius};
  }

  Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
  ceres::CauchyLoss loss(0.05);
  ceres::Problem::Options po;
  po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // `loss` lives here
  ceres::Problem problem(po);
  for (const Reference& r : reference)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Reference, 1, 6>(new Reference(r)), &loss,
                             x.data());
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = 5;
  o.function_tolerance = 1e-14;
  o.gradient_tolerance = 1e-20;
  o.parameter_tolerance = 1e-14;
  o.num_threads = 1;
  o.logging_type = ceres::SILENT;

  std::string message;
  int iterations = 0;
  for (int round = 0; round < 3; ++round) {
    iterations += fit.solve(message);
    REQUIRE(message.empty());
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem, &summary);
    REQUIRE(summary.IsSolutionUsable());
  }
  DOCTEST_CHECK(iterations > 0);
  DOCTEST_CHECK(x.norm() > 1e-3);  // the fit really moved
  for (int k = 0; k < 6; ++k) DOCTEST_CHECK(std::abs(fit.parameters()(k) - x(k)) <= 1e-12 * (1 + std::abs(x(k))));
  for (std::size_t i = 0; i < n; i += 97) {
    double r = 0;
    const double* params[1] = {x.data()};
    ceres::AutoDiffCostFunction<Reference, 1, 6>(new Reference(reference[i])).Evaluate(params, &r, nullptr);
    if (reference[i].active) DOCTEST_CHECK(std::abs(fit.residual(i) - r) <= 1e-12);
  }

  // Covariance: ceres::Covariance of the reference problem at its optimum.
  std::string status;
  const auto c = fit.covariance(status);
  REQUIRE(c);
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance cov(co);
  std::vector<std::pair<const double*, const double*>> blocks = {{x.data(), x.data()}};
  REQUIRE(cov.Compute(blocks, &problem));
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> expected;
  cov.GetCovarianceBlock(x.data(), x.data(), expected.data());
  const double scale = expected.cwiseAbs().maxCoeff();
  DOCTEST_CHECK(scale > 0);
  DOCTEST_CHECK((*c - Eigen::Matrix<double, 6, 6>(expected)).cwiseAbs().maxCoeff() <= 1e-9 * scale);
}

TEST_CASE("surface fit: weighted points solve like the reference with w d per point, and cost() is that problem's") {
  // The first case's surface, smaller, with weights from 0.2 to 1 (the
  // range of cos(incidence) a scan's fit points carry) and no boundary.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-40, 40), offset(-0.05, 0.05), weight(0.2, 1.0);
  const std::size_t n = 1500;
  std::vector<Eigen::Vector3d> y(n), foot(n), normal(n);
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = coord(rng), v = coord(rng);
    foot[i] = {u, v, 0.5 * std::sin(u / 7) * std::cos(v / 9)};
    const Eigen::Vector3d du(1, 0, 0.5 / 7 * std::cos(u / 7) * std::cos(v / 9));
    const Eigen::Vector3d dv(0, 1, -0.5 / 9 * std::sin(u / 7) * std::sin(v / 9));
    normal[i] = du.cross(dv).normalized();
    y[i] = foot[i] + offset(rng) * normal[i];
    w[i] = weight(rng);
  }
  const Eigen::AngleAxisd turn(0.01, Eigen::Vector3d(1, 2, 3).normalized());
  for (Eigen::Vector3d& p : y) p = turn * p + Eigen::Vector3d(0.2, -0.1, 0.05);

  SurfaceFit fit(y, 0, DegreesOfFreedom{}, RobustLoss::cauchy, 0.05, 5);
  Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
  ceres::CauchyLoss loss(0.05);
  ceres::Problem::Options po;
  po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  for (std::size_t i = 0; i < n; ++i) {
    fit.set_foot(i, foot[i], normal[i], true, false);
    fit.set_weight(i, w[i]);
    Reference r{y[i], foot[i], normal[i], true, false, 1.0, 0.0};
    r.weight = w[i];
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Reference, 1, 6>(new Reference(r)), &loss, x.data());
  }
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = 5;
  o.function_tolerance = 1e-14;
  o.gradient_tolerance = 1e-20;
  o.parameter_tolerance = 1e-14;
  o.num_threads = 1;
  o.logging_type = ceres::SILENT;
  std::string message;
  for (int round = 0; round < 3; ++round) {
    fit.solve(message);
    REQUIRE(message.empty());
    ceres::Solver::Summary summary;
    ceres::Solve(o, &problem, &summary);
    REQUIRE(summary.IsSolutionUsable());
  }
  DOCTEST_CHECK(x.norm() > 1e-3);
  for (int k = 0; k < 6; ++k) DOCTEST_CHECK(std::abs(fit.parameters()(k) - x(k)) <= 1e-12 * (1 + std::abs(x(k))));
  // The deviation stays unweighted.
  for (std::size_t i = 0; i < n; i += 53) {
    double r = 0;
    const double* params[1] = {x.data()};
    Reference plain{y[i], foot[i], normal[i], true, false, 1.0, 0.0};
    ceres::AutoDiffCostFunction<Reference, 1, 6>(new Reference(plain)).Evaluate(params, &r, nullptr);
    DOCTEST_CHECK(std::abs(fit.residual(i) - r) <= 1e-12);
  }
  std::string status;
  const auto c = fit.covariance(status);
  REQUIRE(c);
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance cov(co);
  std::vector<std::pair<const double*, const double*>> blocks = {{x.data(), x.data()}};
  REQUIRE(cov.Compute(blocks, &problem));
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> expected;
  cov.GetCovarianceBlock(x.data(), x.data(), expected.data());
  const double scale = expected.cwiseAbs().maxCoeff();
  DOCTEST_CHECK((*c - Eigen::Matrix<double, 6, 6>(expected)).cwiseAbs().maxCoeff() <= 1e-9 * scale);

  // cost() is the weighted problem's: without a loss its gradient is
  // sum w^2 d grad(d), checked by central differences at parameters away
  // from zero (h = 1e-6: truncation and rounding both below 1e-8 relative).
  fit.set_loss(RobustLoss::none, 1);
  Eigen::Matrix<double, 6, 1> p0;
  p0 << 0.004, -0.003, 0.002, 0.05, -0.04, 0.03;
  fit.set_parameters(p0);
  Eigen::Matrix<double, 1, 6> gradient = Eigen::Matrix<double, 1, 6>::Zero();
  for (std::size_t i = 0; i < n; ++i) gradient += w[i] * w[i] * fit.residual(i) * fit.jacobian(i);
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    CAPTURE(k);
    Eigen::Matrix<double, 6, 1> a = p0, b = p0;
    a(k) += h;
    b(k) -= h;
    fit.set_parameters(a);
    const double ca = fit.cost();
    fit.set_parameters(b);
    const double cb = fit.cost();
    DOCTEST_CHECK(std::abs((ca - cb) / (2 * h) - gradient(k)) <= 1e-6 * (1 + std::abs(gradient(k))));
  }
  // The row weight of the covariance: w^2 without a loss.
  fit.set_parameters(p0);
  for (std::size_t i = 0; i < n; i += 97) DOCTEST_CHECK(std::abs(fit.loss_weight(i) - w[i] * w[i]) <= 1e-15);
}
