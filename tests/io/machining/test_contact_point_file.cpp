#include <doctest/doctest.h>

#include "base/error.hpp"
#include "io/machining/contact_point_file.hpp"

using namespace furrow;

TEST_CASE("contact-point CSV: with and without normals, header, comments, units") {
  const auto plain = parse_contact_points_csv("# cc points\n1,2,3\n\n4, 5, 6 # trailing\n", "cc.csv");
  REQUIRE(plain.size() == 2);
  CHECK(plain[1].position == Eigen::Vector3d(4, 5, 6));
  CHECK(plain[1].line == 4);
  CHECK_FALSE(plain[0].has_normal);
  const auto normals = parse_contact_points_csv("id,nz,x,y,z,nx,ny\nP1,2,1,2,3,0,0\n", "cc.csv", "inch");
  REQUIRE(normals.size() == 1);
  CHECK(normals[0].id == "P1");
  CHECK((normals[0].position - Eigen::Vector3d(25.4, 50.8, 76.2)).norm() < 1e-12);
  CHECK(normals[0].normal == Eigen::Vector3d(0, 0, 1));
  const auto six = parse_contact_points_csv("1,2,3,0,3,4\n", "cc.csv");
  CHECK((six[0].normal - Eigen::Vector3d(0, 0.6, 0.8)).norm() < 1e-15);

  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"1,2\n", "cc.csv:1: expected 3 numbers x,y,z or 6 x,y,z,nx,ny,nz, got 2 values"},
      {"1,2,3\n4,5,6,7,8,9\n", "cc.csv:2: expected 3 values, got 6"},
      {"1,2,abc\n", "cc.csv:1: z \"abc\" is not a finite number"},
      {"1,2,nan\n", "cc.csv:1: z \"nan\" is not a finite number"},
      {"1,2,3,0,0,0\n", "cc.csv:1: the normal (0, 0, 0) has no direction"},
      {"x,y,q\n", "cc.csv:1: unknown column \"q\""},
      {"x,y,z,nx\n", "not all three"},
      {"x,x,y,z\n", "column \"x\" appears twice"},
      {"# nothing\n\n", "cc.csv: no contact points in the file"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.text);
    CHECK_THROWS_WITH_AS(parse_contact_points_csv(c.text, "cc.csv"), doctest::Contains(c.expected), InputError);
  }
}
