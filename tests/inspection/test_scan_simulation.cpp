// The simulated scan (scan_simulation.hpp) against analytic answers: points
// on the surface and on their raster rays, the grazing limit of a
// hemisphere, the shadow one plane casts on another, bumps and noise read
// back by an independent closest-point projection, spray counted and thrown
// as far as asked, the scanner frame, determinism.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/primitives.hpp"
#include "inspection/scan_simulation.hpp"
#include "io/part_file.hpp"

using namespace furrow;

namespace {

Part hemisphere(double radius) {
  Part p;
  p.faces.emplace_back("dome", make_sphere(radius, 0, 2 * kPi, 0, kPi / 2));
  return p;
}

// Distance of x from the nearest multiple of `pitch` after `origin`.
double off_lattice(double x, double origin, double pitch) {
  const double k = (x - origin) / pitch;
  return std::fabs(k - std::round(k)) * pitch;
}

}  // namespace

TEST_CASE("scan simulation: a hemisphere seen from above gives exactly the raster rays within the incidence limit") {
  const double radius = 20, pitch = 0.5;
  ScannerModel m;
  m.stripe_pitch = m.point_pitch = pitch;
  m.max_incidence_deg = 60;
  m.noise_sigma = 0;
  const SimulatedScan scan = simulate_scan(hemisphere(radius), m);
  REQUIRE(scan.points.size() > 1000);
  // Every point on the sphere and on a ray of one raster: x and y on one
  // lattice of the pitch.
  const Eigen::Vector3d first = scan.points.front();
  double worst_radius = 0, worst_lattice = 0, widest = 0;
  for (const Eigen::Vector3d& p : scan.points) {
    worst_radius = std::max(worst_radius, std::fabs(p.norm() - radius));
    worst_lattice = std::max({worst_lattice, off_lattice(p.x(), first.x(), pitch), off_lattice(p.y(), first.y(), pitch)});
    widest = std::max(widest, std::hypot(p.x(), p.y()));
  }
  CHECK(worst_radius < 1e-8);
  CHECK(worst_lattice < 1e-9);
  // The incidence from above is the polar angle: points only where
  // r_xy <= R sin 60 deg, and every lattice point of that disc is one but
  // the pole's.
  const double limit = radius * std::sin(radians(60));
  CHECK(widest <= limit + 1e-9);
  std::size_t inside = 0, rim = 0;
  for (double x = first.x() - std::ceil((first.x() + radius) / pitch) * pitch; x <= radius; x += pitch)
    for (double y = first.y() - std::ceil((first.y() + radius) / pitch) * pitch; y <= radius; y += pitch) {
      const double r = std::hypot(x, y);
      // The pole's ray (on this lattice) meets the surface where its
      // parametrisation has no normal: counted not solved, not a point.
      inside += r <= limit && r > 1e-9;
      rim += r > limit && r < radius - 1e-6;
    }
  CHECK(scan.points.size() == inside);
  CHECK(scan.counts.points == inside);
  CHECK(scan.counts.not_solved >= 1);  // the pole, and rays grazing the equator
  // The ring beyond the limit is grazing (a ray within a hair of the
  // silhouette may miss the tessellation instead; none is lost otherwise).
  CHECK(scan.counts.grazing + scan.counts.missed + scan.counts.not_solved >= rim);
  CHECK(scan.counts.grazing > rim * 95 / 100);
  CHECK(scan.counts.points + scan.counts.grazing + scan.counts.missed + scan.counts.from_behind +
            scan.counts.not_solved == scan.counts.rays);
  CHECK(scan.counts.spray == 0);
}

TEST_CASE("scan simulation: a floating sheet shadows the floor exactly where its rays cross it") {
  // Floor z = 0 over [0, 40]^2; a sheet at z = 10 over [0, 20] x [0, 40].
  // Seen along (1, 0, -1) a floor point (x, y, 0) looks back to the sheet's
  // height at x - 10: it is hidden for x in [10, 30], seen for x < 10 and
  // x > 30 (a fifth and a fifth of the floor... half of it in all).
  Part part;
  part.faces.emplace_back("floor", make_plane({0, 0, 0}, {40, 0, 0}, {0, 40, 0}));
  part.faces.emplace_back("sheet", make_plane({0, 0, 10}, {20, 0, 0}, {0, 40, 0}));
  ScannerModel m;
  m.view = {1, 0, -1};
  m.stripe_pitch = m.point_pitch = 0.2;
  m.noise_sigma = 0;
  const SimulatedScan scan = simulate_scan(part, m);
  std::size_t floor_points = 0, sheet_points = 0, hidden = 0;
  for (std::size_t k = 0; k < scan.points.size(); ++k) {
    const Eigen::Vector3d& p = scan.points[k];
    if (scan.face[k] == 0) {
      ++floor_points;
      CHECK(std::fabs(p.z()) < 1e-9);
      hidden += p.x() > 10 + 1e-6 && p.x() < 30 - 1e-6;
    } else {
      ++sheet_points;
      CHECK(std::fabs(p.z() - 10) < 1e-9);
    }
  }
  CHECK(hidden == 0);
  // Both seen stretches of the floor are there at the raster's density: 800
  // mm^2 of floor, foreshortened by cos 45 deg, over 0.2 x 0.2 mm per ray
  // (within 3 %: the raster's edges).
  const double expected_floor = 800 * std::cos(radians(45)) / (0.2 * 0.2);
  CHECK(std::fabs(floor_points - expected_floor) < 0.03 * expected_floor);
  const double expected_sheet = 800 * std::cos(radians(45)) / (0.2 * 0.2);
  CHECK(std::fabs(sheet_points - expected_sheet) < 0.03 * expected_sheet);
  // The floor is seen on both sides of the shadow.
  std::size_t before = 0, after = 0;
  for (std::size_t k = 0; k < scan.points.size(); ++k)
    if (scan.face[k] == 0) (scan.points[k].x() < 10 ? before : after) += 1;
  CHECK(before > expected_floor / 3);
  CHECK(after > expected_floor / 3);
}

TEST_CASE("scan simulation: the mould's dent, noise and the scanner frame read back through an independent projection") {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const ClosestPointFinder finder(part);
  // A dent of 50 um and 10 mm radius about a point of the surface.
  const Eigen::Vector3d centre = finder.project({50, 40, 26}).point;
  ScannerModel m;
  m.stripe_pitch = m.point_pitch = 1.0;
  m.noise_sigma = 0.005;
  m.bumps.push_back({centre, 10, -0.05});
  m.part_to_scanner.rotation_deg = {10, -20, 170};
  m.part_to_scanner.translation = {100, -50, 30};
  const SimulatedScan scan = simulate_scan(part, m);
  REQUIRE(scan.points.size() > 3000);
  const Eigen::Isometry3d back = m.part_to_scanner.part_to_cmm().inverse();
  double worst = 0, dent_sum = 0, noise_sq = 0;
  std::size_t in_dent = 0, outside = 0, on_edge = 0;
  for (std::size_t k = 0; k < scan.points.size(); ++k) {
    const Eigen::Vector3d q = back * scan.points[k];
    const ClosestPoint c = finder.project(q);
    // A point on the face's edge that the noise moved past it projects to
    // the edge, not along the normal: those are not this oracle's.
    if (c.location == FootLocation::interior)
      worst = std::max(worst, std::fabs(c.signed_distance - scan.true_deviation[k]));
    else
      ++on_edge;
    // The normal written is the surface's, turned into the scanner frame.
    const DifferentialGeometry g = part.faces[scan.face[k]].geometry(scan.uv[k].x(), scan.uv[k].y());
    CHECK((back.linear() * scan.normals[k] - g.normal).norm() < 1e-12);
    CHECK((scan.nominal[k] - g.point).norm() < 1e-12);
    const double rho = (scan.nominal[k] - centre).norm();
    if (rho < 1) {
      dent_sum += c.signed_distance;
      ++in_dent;
    } else if (rho > 10) {
      noise_sq += c.signed_distance * c.signed_distance;
      ++outside;
    }
  }
  // First order in the noise: the point moves along the line of sight, and
  // its distance from the surface is its normal share (error ~ noise^2 / R).
  CHECK(worst < 1e-6);
  CHECK(on_edge < scan.points.size() / 20);
  REQUIRE(in_dent > 0);
  // At the dent's centre, within a millimetre: 1 - (1 + cos(pi/10)) / 2 of
  // its depth is at most 2.5 %.
  CHECK(std::fabs(dent_sum / in_dent + 0.05) < 0.05 * 0.025 + 3 * 0.005 / std::sqrt(double(in_dent)));
  // Away from it only the noise, whose normal share is below its sigma.
  const double rms = std::sqrt(noise_sq / outside);
  CHECK(rms < 0.005);
  CHECK(rms > 0.002);
}

TEST_CASE("scan simulation: spray is the asked share, thrown as far as asked, and the same seed gives the same scan") {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  ScannerModel m;
  m.stripe_pitch = m.point_pitch = 1.0;
  m.noise_sigma = 0;
  m.spray_share = 0.02;
  m.spray_min = 0.3;
  m.spray_max = 3;
  const SimulatedScan scan = simulate_scan(part, m);
  std::size_t sprayed = 0;
  const ClosestPointFinder finder(part);
  for (std::size_t k = 0; k < scan.points.size(); ++k) {
    const double along_sight = (scan.points[k] - (scan.nominal[k])).norm();
    if (scan.spray[k]) {
      ++sprayed;
      CHECK(along_sight >= 0.3 - 1e-12);
      CHECK(along_sight <= 3 + 1e-12);
    } else {
      CHECK(along_sight < 1e-12);
      CHECK(finder.project(scan.points[k]).distance < 1e-8);
    }
  }
  CHECK(sprayed == static_cast<std::size_t>(std::llround(0.02 * scan.points.size())));
  CHECK(scan.counts.spray == sprayed);
  const SimulatedScan again = simulate_scan(part, m);
  REQUIRE(again.points.size() == scan.points.size());
  bool same = true;
  for (std::size_t k = 0; k < scan.points.size(); ++k) same = same && again.points[k] == scan.points[k];
  CHECK(same);
  // A view direction of any length is a direction: one near the largest
  // double (whose plain norm overflows) looks where its unit vector does.
  ScannerModel huge = m, unit = m;
  huge.view = {1e308, 0, -1e308};
  unit.view = {1, 0, -1};
  const SimulatedScan seen_huge = simulate_scan(part, huge), seen_unit = simulate_scan(part, unit);
  REQUIRE(seen_unit.points.size() > 1000);
  REQUIRE(seen_huge.points.size() == seen_unit.points.size());
  double apart = 0;  // the two unit vectors may differ in their last bit
  for (std::size_t k = 0; k < seen_unit.points.size(); ++k)
    apart = std::max(apart, (seen_huge.points[k] - seen_unit.points[k]).norm());
  CHECK(apart < 1e-9);
  m.seed = 2;
  const SimulatedScan other = simulate_scan(part, m);
  bool differs = false;
  for (std::size_t k = 0; k < scan.points.size(); ++k) differs = differs || other.spray[k] != scan.spray[k];
  CHECK(differs);
}

TEST_CASE("scan simulation: a bad scanner model is refused before any work") {
  const Part part = hemisphere(10);
  auto refused = [&](auto change, const std::string& says) {
    ScannerModel m;
    change(m);
    try {
      simulate_scan(part, m);
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find(says) != std::string::npos);
    }
  };
  refused([](ScannerModel& m) { m.view = Eigen::Vector3d::Zero(); }, "view");
  refused([](ScannerModel& m) { m.stripe_pitch = 0; }, "stripe pitch");
  refused([](ScannerModel& m) { m.point_pitch = -1; }, "point pitch");
  refused([](ScannerModel& m) { m.max_incidence_deg = 90; }, "incidence");
  refused([](ScannerModel& m) { m.noise_sigma = std::nan(""); }, "noise");
  refused([](ScannerModel& m) { m.spray_share = 1; }, "spray share");
  refused([](ScannerModel& m) { m.spray_min = 2, m.spray_max = 1; }, "spray range");
  refused([](ScannerModel& m) { m.bumps.push_back({{0, 0, 0}, 0, 1}); }, "bump radius");
  refused([](ScannerModel& m) { m.stripe_pitch = m.point_pitch = 1e-4; }, "50 million");
}
