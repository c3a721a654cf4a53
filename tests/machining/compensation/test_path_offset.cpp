#include <doctest/doctest.h>

#include <cmath>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "geometry/primitives.hpp"
#include "machining/compensation/path_offset.hpp"

using namespace furrow;

namespace {

// A convex half-cylinder, R 25 about the y axis, the top 120 degrees, 80 mm long.
Part dome() {
  Part part;
  part.faces.emplace_back("dome", make_cylinder(25, 80, radians(30), radians(150)), Trim{}, true);
  return part;
}

Part plate() {
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {100, 0, 0}, {0, 60, 0}));
  return part;
}

// An error field from a 25 x 25 grid of samples of `value(x, y, z)` over
// face 0 (covering it: no fade inside).
ErrorField sampled_field(const Part& part, double (*value)(const Eigen::Vector3d&)) {
  std::vector<std::vector<FieldSample>> by_face(1);
  const Face& face = part.faces[0];
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j <= 24; ++j) {
      const double u = face.domain().u0 + face.domain().width_u() * i / 24;
      const double v = face.domain().v0 + face.domain().width_v() * j / 24;
      by_face[0].push_back({u, v, value(face.surface().point(u, v))});
    }
  return fit_face_fields(part, std::move(by_face), {}, "test");
}

// Passes along u at several v, tips at the exact cutter location of each
// contact: what a CAM system writes for the nominal part.
Toolpath exact_path(const Part& part, const Cutter& cutter) {
  Toolpath path;
  const Face& face = part.faces[0];
  for (double v : {0.2, 0.5, 0.8}) {
    ToolpathPass pass;
    for (double u = 0.1; u <= 0.9 + 1e-9; u += 0.05) {
      const double pu = face.domain().u0 + face.domain().width_u() * u;
      const double pv = face.domain().v0 + face.domain().width_v() * v;
      const DifferentialGeometry g = face.geometry(pu, pv);
      ToolpathPoint point;
      point.position = cutter_location(cutter, g.point, g.normal).tip;
      point.line = int(path.passes.size() * 100 + pass.points.size() + 1);
      pass.points.push_back(point);
    }
    path.passes.push_back(pass);
  }
  return path;
}

double constant_50um(const Eigen::Vector3d&) { return 0.05; }
double constant_300um(const Eigen::Vector3d&) { return 0.3; }
double tilt(const Eigen::Vector3d& p) { return 0.0005 * p.x(); }  // 0.5 um per mm along x

}  // namespace

TEST_CASE("path offset: with a constant field every cutter location moves by the field along the normal") {
  const Part part = dome();
  const ErrorField field = sampled_field(part, constant_50um);
  REQUIRE(field.faces[0]->fitted());
  for (const Cutter& cutter : {Cutter("ball", 3, 3), Cutter("bull", 4, 1), Cutter("flat", 3, 0)}) {
    CAPTURE(cutter.name());
    const Toolpath path = exact_path(part, cutter);
    const PathTools tools = single_tool(cutter, path);
    const PathGeometry geometry = locate_path(part, cutter, path);
    for (double gain : {1.0, 0.5}) {
      PathOffsetOptions options;
      options.gain = gain;
      const PathOffset moved = offset_path(part, tools, geometry, field, options);
      CHECK(moved.moved == geometry.points);
      CHECK(moved.clipped.empty());
      for (std::size_t p = 0; p < path.passes.size(); ++p)
        for (std::size_t k = 0; k < path.passes[p].points.size(); ++k) {
          const PathPoint& at = geometry.passes[p][k];
          REQUIRE(at.contact.valid);
          // The dome's outward normal at a contact: away from the y axis.
          const Eigen::Vector3d c = at.contact.at.point;
          const Eigen::Vector3d n = Eigen::Vector3d(c.x(), 0, c.z()).normalized();
          const Eigen::Vector3d expected = path.passes[p].points[k].position - gain * 0.05 * n;
          CHECK((moved.tips[p][k] - expected).norm() < 1e-7);
          CHECK(std::abs(moved.offsets[p][k] + gain * 0.05) < 1e-9);
        }
    }
  }
}

TEST_CASE("path offset: a tilt field tilts the ball onto the tilted plane") {
  const Part part = plate();
  const ErrorField field = sampled_field(part, tilt);
  const Cutter ball("ball", 3, 3);
  const Toolpath path = exact_path(part, ball);
  const PathGeometry geometry = locate_path(part, ball, path);
  const PathOffset moved = offset_path(part, single_tool(ball, path), geometry, field);
  CHECK(moved.moved == geometry.points);
  for (std::size_t p = 0; p < path.passes.size(); ++p)
    for (std::size_t k = 0; k < path.passes[p].points.size(); ++k) {
      // The part to cut is the plane z = -0.0005 x; the ball touching it
      // at the moved contact P' = P - 0.0005 x z has its centre R along
      // that plane's normal (0.0005, 0, 1) / |.|, its tip R below.
      const Eigen::Vector3d P = geometry.passes[p][k].contact.at.point;
      const Eigen::Vector3d moved_contact = P - 0.0005 * P.x() * Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d n = Eigen::Vector3d(0.0005, 0, 1).normalized();
      const Eigen::Vector3d expected = moved_contact + 3 * n - 3 * Eigen::Vector3d::UnitZ();
      CHECK((moved.tips[p][k] - expected).norm() < 1e-9);
    }
}

TEST_CASE("path offset: offsets beyond the maximum are clipped and listed") {
  const Part part = dome();
  const ErrorField field = sampled_field(part, constant_300um);
  const Cutter ball("ball", 3, 3);
  const Toolpath path = exact_path(part, ball);
  const PathGeometry geometry = locate_path(part, ball, path);
  PathOffsetOptions options;
  options.max_offset = 0.2;
  const PathOffset moved = offset_path(part, single_tool(ball, path), geometry, field, options);
  CHECK(moved.clipped.size() == geometry.points);
  CHECK(moved.largest_offset == 0.2);
  for (const OffsetPoint& c : moved.clipped) {
    CHECK(std::abs(c.requested + 0.3) < 1e-9);
    CHECK(c.applied == -0.2);
    CHECK(c.line == path.passes[c.pass].points[c.point].line);
    const Eigen::Vector3d contact = geometry.passes[c.pass][c.point].contact.at.point;
    const Eigen::Vector3d n = Eigen::Vector3d(contact.x(), 0, contact.z()).normalized();
    CHECK((moved.tips[c.pass][c.point] - (path.passes[c.pass].points[c.point].position - 0.2 * n)).norm() < 1e-9);
  }
}

TEST_CASE("path offset: points off the part or in the air keep their tips") {
  const Part part = plate();
  const ErrorField field = sampled_field(part, constant_50um);
  const Cutter ball("ball", 3, 3);
  Toolpath path;
  ToolpathPass pass;
  for (const Eigen::Vector3d& tip : {Eigen::Vector3d(50, 30, 0), Eigen::Vector3d(50, 30, 20),
                                     Eigen::Vector3d(150, 30, 0), Eigen::Vector3d(60, 30, 0)}) {
    ToolpathPoint point;
    point.position = tip;
    pass.points.push_back(point);
  }
  path.passes.push_back(pass);
  const PathGeometry geometry = locate_path(part, ball, path);
  const PathOffset moved = offset_path(part, single_tool(ball, path), geometry, field);
  CHECK(moved.moved == 2);
  CHECK(moved.in_air == 1);
  CHECK(moved.no_contact == 1);
  CHECK((moved.tips[0][0] - Eigen::Vector3d(50, 30, -0.05)).norm() < 1e-9);
  CHECK(moved.tips[0][1] == Eigen::Vector3d(50, 30, 20));
  CHECK(moved.tips[0][2] == Eigen::Vector3d(150, 30, 0));
  CHECK((moved.tips[0][3] - Eigen::Vector3d(60, 30, -0.05)).norm() < 1e-9);
  PathOffsetOptions bad;
  bad.gain = 0;
  CHECK_THROWS_AS(offset_path(part, single_tool(ball, path), geometry, field, bad), InputError);
  bad.gain = 1, bad.max_offset = -1;
  CHECK_THROWS_AS(offset_path(part, single_tool(ball, path), geometry, field, bad), InputError);
}

TEST_CASE("path offset: an offset that would make a concave radius tighter than the ball is cut back to the last clear one") {
  // The inside of a tube of radius 10 (the unreversed cylinder faces its
  // axis: concave), its bottom 140 degrees, and a ball of radius 9.95 that
  // just fits it.
  Part part;
  part.faces.emplace_back("trough", make_cylinder(10, 40, radians(200), radians(340)));
  const Cutter ball("ball", 9.95, 9.95);
  const Toolpath path = exact_path(part, ball);
  const PathGeometry geometry = locate_path(part, ball, path);
  PathOffsetOptions options;
  // Oracle: the offset surface at d has radius 10 - d; the ball gouges when
  // 1 / (10 - d) exceeds 1 / 9.95 by more than the curvature tolerance.
  const double tolerance = options.gouge.curvature_tolerance;
  const double last_clear = 10 - 1 / (1 / 9.95 + tolerance);
  {
    // An overcut of 80 um asks for d = +0.08: radius 9.92 < 9.95.
    const ErrorField field = sampled_field(part, [](const Eigen::Vector3d&) { return -0.08; });
    const PathOffset moved = offset_path(part, single_tool(ball, path), geometry, field, options);
    CHECK(moved.gouge_clipped.size() == geometry.points);
    CHECK(moved.clipped.empty());
    for (const OffsetPoint& c : moved.gouge_clipped) {
      CHECK(std::abs(c.requested - 0.08) < 1e-9);
      CHECK(std::abs(c.applied - last_clear) < 1e-9);
      // The tip moves by the applied offset along the normal (towards the axis).
      const Eigen::Vector3d contact = geometry.passes[c.pass][c.point].contact.at.point;
      const Eigen::Vector3d n = -Eigen::Vector3d(contact.x(), 0, contact.z()).normalized();
      CHECK((moved.tips[c.pass][c.point] - (path.passes[c.pass].points[c.point].position + c.applied * n)).norm() <
            1e-7);
    }
  }
  {
    // Material left asks for d < 0: the radius grows, nothing to cut back.
    const ErrorField field = sampled_field(part, [](const Eigen::Vector3d&) { return 0.08; });
    const PathOffset moved = offset_path(part, single_tool(ball, path), geometry, field, options);
    CHECK(moved.gouge_clipped.empty());
    CHECK(moved.moved == geometry.points);
  }
  {
    // Without the check the full offset is applied: the test above could fail.
    options.check_gouge = false;
    const ErrorField field = sampled_field(part, [](const Eigen::Vector3d&) { return -0.08; });
    const PathOffset moved = offset_path(part, single_tool(ball, path), geometry, field, options);
    CHECK(moved.gouge_clipped.empty());
    CHECK(std::abs(moved.largest_offset - 0.08) < 1e-9);
  }
}
