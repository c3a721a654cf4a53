// Sampling inside regions: every strategy gives exactly the requested count
// of admissible points (on the surface, in the region and the trim, border
// clearance by brute force), reproducibly; area-uniform on a skewed
// parametrisation; curvature and risk strategies put points where asked.
#include <doctest/doctest.h>

#include <cmath>

#include "base/error.hpp"
#include "planning/sampling_strategy.hpp"
#include "plan_fixtures.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

const SamplingStrategy kPlain[] = {SamplingStrategy::grid, SamplingStrategy::stratified, SamplingStrategy::hammersley,
                                   SamplingStrategy::halton, SamplingStrategy::random, SamplingStrategy::curvature};

void check_points(const Part& part, const RegionMap& map, const RegionDomain& domain, const RegionSample& s,
                  double border) {
  const Face& face = domain.face();
  for (const SampledPoint& p : s.points) {
    CHECK((face.surface().point(p.uv.x(), p.uv.y()) - p.xyz).norm() <= 1e-9);
    CHECK(face.contains(p.uv.x(), p.uv.y()));
    const auto region = map.region_at(domain.face_index(), p.uv.x(), p.uv.y());
    REQUIRE(region.has_value());
    CHECK(*region == domain.region_id());
    CHECK(brute_edge_distance(part, map, domain.region_id(), p.xyz) >= border);
  }
}

// A risk map with a Gaussian bump of predicted error at (u0, v0).
class BumpRisk : public RiskMap {
 public:
  BumpRisk(Eigen::Vector2d centre, double width) : centre_(centre), width_(width) {}
  double error_magnitude(int, const Eigen::Vector2d& uv) const override {
    return 0.05 * std::exp(-(uv - centre_).squaredNorm() / (width_ * width_));
  }
  const std::vector<RiskSite>& gouge_sites() const override { return sites_; }

 private:
  Eigen::Vector2d centre_;
  double width_;
  std::vector<RiskSite> sites_;
};

}  // namespace

TEST_CASE("every strategy: exactly n admissible points per mould region, reproducible") {
  const Part part = mould();
  const RegionMap map = partition_of(part, 200, 160);
  RegionDomainOptions o;
  o.border = 2;
  for (const Region& region : map.regions) {
    const RegionDomain domain(part, map, region.id, o);
    for (SamplingStrategy s : kPlain) {
      CAPTURE(region.id);
      CAPTURE(to_string(s));
      const RegionSample a = sample_region(domain, s, 23, region_seed(7, region.id), 0.02);
      CHECK(a.points.size() == 23);
      CHECK(a.short_by == 0);
      check_points(part, map, domain, a, o.border);
      const RegionSample b = sample_region(domain, s, 23, region_seed(7, region.id), 0.02);
      REQUIRE(b.points.size() == a.points.size());
      for (std::size_t k = 0; k < a.points.size(); ++k) CHECK(a.points[k].uv == b.points[k].uv);
      if (s != SamplingStrategy::grid) {
        const RegionSample c = sample_region(domain, s, 23, region_seed(8, region.id), 0.02);
        CHECK(c.points.front().uv != a.points.front().uv);
      }
    }
  }
}

TEST_CASE("a trimmed face with a hole: points keep the border clearance from the trim") {
  // Plane 60 x 60 mm, trim: the square minus a round hole of radius 0.2 (12 mm) at the centre.
  UvLoop outer{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, hole;
  for (int k = 0; k < 48; ++k) hole.emplace_back(0.5 + 0.2 * std::cos(k * 0.1308996939), 0.5 + 0.2 * std::sin(k * 0.1308996939));
  const Part part = one_face(make_plane({0, 0, 0}, {60, 0, 0}, {0, 60, 0}), "holed", Trim({outer, hole}));
  const RegionMap map = partition_of(part, 90, 90);
  REQUIRE(map.regions.size() == 1);
  RegionDomainOptions o;
  o.border = 3;
  const RegionDomain domain(part, map, 0, o);
  for (SamplingStrategy s : kPlain) {
    const RegionSample got = sample_region(domain, s, 60, 3, 0);
    CHECK(got.points.size() == 60);
    check_points(part, map, domain, got, o.border);
    for (const SampledPoint& p : got.points) CHECK((p.xyz - Eigen::Vector3d(30, 30, 0)).norm() >= 12 + 3 - 1e-6);
  }
}

TEST_CASE("points are spread by area on the surface, not by parameter") {
  // x = 100 u^2 (a quadratic Bezier in u), y = 50 v: uniform in (u, v) would
  // crowd points near x = 0 (mean x 33.3); uniform by area gives mean x 50.
  const std::vector<double> k2{0, 0, 0, 1, 1, 1}, k1{0, 0, 1, 1};
  std::vector<std::vector<Eigen::Vector3d>> net(3, std::vector<Eigen::Vector3d>(2));
  const double xs[] = {0, 0, 100};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) net[i][j] = {xs[i], 50.0 * j, 0};
  const Part part = one_face(NurbsSurface(2, 1, k2, k1, net), "skewed");
  const RegionMap map = partition_of(part, 200, 100);
  REQUIRE(map.regions.size() == 1);
  RegionDomainOptions o;
  o.border = 2;
  const RegionDomain domain(part, map, 0, o);
  const RegionSample got = sample_region(domain, SamplingStrategy::halton, 400, 1, 0);
  double mean_x = 0;
  for (const SampledPoint& p : got.points) mean_x += p.xyz.x() / 400;
  CHECK(mean_x == doctest::Approx(50).epsilon(0.02));
}

TEST_CASE("curvature-adaptive sampling follows area * (1 + |k| / mean |k|)") {
  // Parabolic trough z = 0.02 (x - 50)^2, x in [0, 100], y in [0, 40]:
  // curvature 0.04 at the bottom, 0.0036 at the rims.
  // Exact as a quadratic Bezier in u: x = 0, 50, 100 and z = 50, -50, 50 (x c 50).
  const double c = 0.02;
  const std::vector<double> k2{0, 0, 0, 1, 1, 1}, k1{0, 0, 1, 1};
  std::vector<std::vector<Eigen::Vector3d>> net(3, std::vector<Eigen::Vector3d>(2));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) net[i][j] = {50.0 * i, 40.0 * j, (i == 1 ? -1 : 1) * c * 2500};
  const Part part = one_face(NurbsSurface(2, 1, k2, k1, net), "trough");
  const RegionMap map = partition_of(part, 200, 80);
  REQUIRE(map.regions.size() == 1);
  RegionDomainOptions o;
  o.border = 2;
  const RegionDomain domain(part, map, 0, o);
  // Oracle: the expected share of points with |x - 50| < 15 by quadrature of
  // the density along x (it does not vary along y).
  auto kappa = [&](double x) { return 2 * c / std::pow(1 + std::pow(2 * c * (x - 50), 2), 1.5); };
  auto ds = [&](double x) { return std::sqrt(1 + std::pow(2 * c * (x - 50), 2)); };
  double mean_k = 0, length = 0;
  for (int k = 0; k < 10000; ++k) {
    const double x = 2 + 96 * (k + 0.5) / 10000;
    mean_k += kappa(x) * ds(x);
    length += ds(x);
  }
  mean_k /= length;
  double inside = 0, total = 0;
  for (int k = 0; k < 10000; ++k) {
    const double x = 2 + 96 * (k + 0.5) / 10000;
    const double w = ds(x) * (1 + kappa(x) / mean_k);
    total += w;
    if (std::abs(x - 50) < 15) inside += w;
  }
  const double expected = inside / total;
  const RegionSample got = sample_region(domain, SamplingStrategy::curvature, 600, 5, mean_k);
  const RegionSample plain = sample_region(domain, SamplingStrategy::halton, 600, 5, mean_k);
  auto share = [](const RegionSample& s) {
    double n = 0;
    for (const SampledPoint& p : s.points) n += std::abs(p.xyz.x() - 50) < 15;
    return n / static_cast<double>(s.points.size());
  };
  MESSAGE("share of points within 15 mm of the trough's bottom: curvature " << share(got) << " (expected " << expected
                                                                            << "), halton " << share(plain));
  CHECK(share(got) == doctest::Approx(expected).epsilon(0.05).scale(0));
  CHECK(share(got) > share(plain) + 0.05);
}

TEST_CASE("risk-driven sampling starts at the maximum of the predicted error") {
  const Part part = one_face(make_plane({0, 0, 0}, {80, 0, 0}, {0, 60, 0}), "flat");
  const RegionMap map = partition_of(part, 80, 60);
  const BumpRisk risk({0.7, 0.3}, 0.08);
  RegionDomainOptions o;
  o.border = 2;
  const RegionDomain domain(part, map, 0, o, &risk);
  const RegionSample got = sample_region(domain, SamplingStrategy::risk, 40, 2, 0);
  REQUIRE(got.points.size() == 40);
  // The first point is the bump's peak to within one sample-grid cell.
  const double cell = 80.0 / domain.grid_cells();
  CHECK((got.points.front().xyz - Eigen::Vector3d(56, 18, 0)).norm() <= cell);
  int near = 0;
  for (const SampledPoint& p : got.points) near += (p.xyz - Eigen::Vector3d(56, 18, 0)).norm() < 10;
  // Area share of that disc is 6.5 %; the risk density puts far more there.
  CHECK(near >= 10);
  CHECK_THROWS_AS(parse_sampling_strategy("sobol", "--strategy"), InputError);
  CHECK(parse_sampling_strategy("hammersley", "--strategy") == SamplingStrategy::hammersley);
}

TEST_CASE("gouge-site sampling: the point nearest the site centre first, the rest on the site") {
  const Part part = one_face(make_plane({0, 0, 0}, {80, 0, 0}, {0, 60, 0}), "flat");
  const RegionMap map = partition_of(part, 80, 60);
  RegionDomainOptions o;
  o.border = 2;
  const RegionDomain domain(part, map, 0, o);
  const Eigen::AlignedBox2d box(Eigen::Vector2d(0.4, 0.4), Eigen::Vector2d(0.5, 0.5));
  const RegionSample got = sample_site(domain, box, {0.45, 0.42}, 4, 3);
  REQUIRE(got.points.size() == 4);
  CHECK(got.points[0].uv.isApprox(Eigen::Vector2d(0.45, 0.42)));
  for (const SampledPoint& p : got.points) CHECK(box.contains(p.uv));
  // A site inside the border strip: the nearest admissible point, still on the site.
  const Eigen::AlignedBox2d edge(Eigen::Vector2d(0.0, 0.4), Eigen::Vector2d(0.05, 0.5));
  const RegionSample e = sample_site(domain, edge, {0.0, 0.45}, 2, 3);
  REQUIRE(!e.points.empty());
  CHECK(edge.contains(e.points[0].uv));
  CHECK(e.points[0].xyz.x() >= 2);
  CHECK(e.points[0].xyz.x() <= 2 + 0.1 * 80 / 17 * 1.01);  // within one candidate step of the border
}
