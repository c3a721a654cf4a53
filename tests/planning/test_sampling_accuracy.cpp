// Why low-discrepancy plans: fitting a known tilted plane and a known sphere
// to points measured on a part with a form error, Hammersley, Halton and
// stratified plans give a fit whose error varies less from plan to plan
// (over 40 seeds) than random plans of the same size. The plane is fitted in
// closed form (SVD), the sphere with Ceres.
//
// The measured part is the nominal surface displaced along its normal by a
// smooth form error (waviness and a bowl, tens of micrometres) plus 0.5 um
// of probing noise. Every plan is sampled by the planner's own region
// sampler on the partition of the face.
#include <ceres/ceres.h>
#include <doctest/doctest.h>

#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "base/numbers.hpp"
#include "planning/sampling_strategy.hpp"
#include "plan_fixtures.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

constexpr int kPoints = 30;
constexpr int kSeeds = 40;

struct Measured {
  std::vector<Eigen::Vector3d> points;
};

// Points of a plan, displaced by form(p) along the normal, plus noise.
Measured measure(const RegionDomain& domain, SamplingStrategy s, std::uint64_t seed,
                 double (*form)(const Eigen::Vector3d&)) {
  const RegionSample sample = sample_region(domain, s, kPoints, region_seed(seed, 0), 0);
  REQUIRE(sample.points.size() == static_cast<std::size_t>(kPoints));
  std::mt19937_64 rng(seed * 7919);
  std::normal_distribution<double> noise(0, 0.5e-3);
  Measured m;
  for (const SampledPoint& p : sample.points) {
    const Eigen::Vector3d n = domain.face().geometry(p.uv.x(), p.uv.y()).normal;
    m.points.push_back(p.xyz + (form(p.xyz) + noise(rng)) * n);
  }
  return m;
}

double plane_form(const Eigen::Vector3d& p) {
  return 0.010 * std::sin(2 * kPi * p.x() / 37) * std::cos(2 * kPi * p.y() / 29) +
         0.020 * std::pow((p.x() - 50) / 50, 2);
}

// Total least squares plane: centroid and the smallest singular direction.
// Error: RMS height difference to the nominal plane z = 0.3 x + 0.2 y over
// the face's 100 x 80 mm footprint (on an 11 x 9 grid).
double plane_fit_error(const Measured& m) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : m.points) c += p / static_cast<double>(m.points.size());
  Eigen::MatrixXd a(m.points.size(), 3);
  for (std::size_t k = 0; k < m.points.size(); ++k) a.row(static_cast<Eigen::Index>(k)) = (m.points[k] - c).transpose();
  const Eigen::Vector3d n = Eigen::JacobiSVD<Eigen::MatrixXd>(a, Eigen::ComputeThinV).matrixV().col(2);
  double sum = 0;
  int count = 0;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double x = 10.0 * i, y = 10.0 * j;
      const double z_fit = c.z() - (n.x() * (x - c.x()) + n.y() * (y - c.y())) / n.z();
      sum += std::pow(z_fit - (0.3 * x + 0.2 * y), 2);
      ++count;
    }
  return std::sqrt(sum / count);
}

double sphere_form(const Eigen::Vector3d& p) {
  const double phi = std::atan2(p.y(), p.x());
  const double lat = std::asin(std::clamp(p.z() / 40, -1.0, 1.0));
  return 0.015 * std::cos(3 * phi) * std::sin(4 * lat) + 0.01 * std::cos(2 * lat);
}

struct SphereResidual {
  explicit SphereResidual(const Eigen::Vector3d& p) : p_(p) {}
  template <class T>
  bool operator()(const T* centre, const T* radius, T* residual) const {
    const T dx = T(p_.x()) - centre[0], dy = T(p_.y()) - centre[1], dz = T(p_.z()) - centre[2];
    residual[0] = ceres::sqrt(dx * dx + dy * dy + dz * dz) - radius[0];
    return true;
  }
  Eigen::Vector3d p_;
};

// Geometric least squares sphere (Ceres). Error: fitted minus nominal radius.
double sphere_fit_error(const Measured& m) {
  double centre[3] = {0.5, -0.5, 1}, radius[1] = {38};
  ceres::Problem problem;
  for (const auto& p : m.points)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SphereResidual, 1, 3, 1>(new SphereResidual(p)), nullptr,
                             centre, radius);
  ceres::Solver::Options options;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  options.gradient_tolerance = 1e-16;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  REQUIRE(summary.IsSolutionUsable());
  return radius[0] - 40;
}

struct Spread {
  double mean = 0, variance = 0;
};

Spread spread(const RegionDomain& d, SamplingStrategy s, double (*form)(const Eigen::Vector3d&),
              double (*fit)(const Measured&)) {
  std::vector<double> errors;
  for (int seed = 1; seed <= kSeeds; ++seed) errors.push_back(fit(measure(d, s, static_cast<std::uint64_t>(seed), form)));
  return {test::mean(errors), test::variance(errors)};
}

void compare(const RegionDomain& d, double (*form)(const Eigen::Vector3d&), double (*fit)(const Measured&),
             const char* what) {
  const Spread random = spread(d, SamplingStrategy::random, form, fit);
  for (SamplingStrategy s : {SamplingStrategy::hammersley, SamplingStrategy::halton, SamplingStrategy::stratified}) {
    const Spread q = spread(d, s, form, fit);
    MESSAGE(std::string(what) << ", " << kPoints << " points, " << kSeeds << " seeds: " << std::string(to_string(s)) << " mean "
                 << q.mean * 1e3 << " um, std " << std::sqrt(q.variance) * 1e3 << " um;  random mean "
                 << random.mean * 1e3 << " um, std " << std::sqrt(random.variance) * 1e3 << " um  (variance ratio "
                 << q.variance / random.variance << ")");
    DOCTEST_CHECK(q.variance < random.variance);  // glog (via ceres.h) owns CHECK here
  }
}

}  // namespace

TEST_CASE("a tilted plane is reconstructed with less spread from low-discrepancy plans") {
  const Part part = one_face(make_plane({0, 0, 0}, {100, 0, 30}, {0, 80, 16}), "tilted");
  const RegionMap map = partition_of(part, 100, 80);
  REQUIRE(map.regions.size() == 1);
  RegionDomainOptions o;
  o.border = 2;
  const RegionDomain domain(part, map, 0, o);
  compare(domain, plane_form, plane_fit_error, "plane: RMS height error of the fitted plane");
}

TEST_CASE("a sphere's radius is reconstructed with less spread from low-discrepancy plans") {
  // Cap of a sphere of radius 40: latitude 20..80 degrees, longitude 0..180.
  const Part part = one_face(make_sphere(40, 0, kPi, 20 * kPi / 180, 80 * kPi / 180), "cap");
  const RegionMap map = partition_of(part, 120, 80);
  REQUIRE(map.regions.size() == 1);
  RegionDomainOptions o;
  o.border = 2;
  const RegionDomain domain(part, map, 0, o);
  compare(domain, sphere_form, sphere_fit_error, "sphere: fitted minus nominal radius");
}
