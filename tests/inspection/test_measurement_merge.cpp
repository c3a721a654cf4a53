// merge_measurements in-process: the order rule over more than two files,
// and the refusals (generated ids, centres with contacts, another ball).
#include <doctest/doctest.h>

#include "base/error.hpp"
#include "inspection/measurement_merge.hpp"

using namespace furrow;

namespace {

MeasurementSet set_of(const std::string& source, const std::vector<std::pair<std::string, double>>& points) {
  MeasurementSet s;
  s.source = source;
  s.ids_from_file = true;
  s.probe_radius = 1;
  for (const auto& [id, x] : points) {
    MeasuredPoint p;
    p.id = id;
    p.xyz = Eigen::Vector3d(x, 0, 0);
    s.points.push_back(p);
  }
  return s;
}

std::string refusal(const std::vector<MeasurementSet>& sets) {
  try {
    merge_measurements(sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("merge_measurements: the last file measuring an id wins, in place, every replacement is listed") {
  const MergedMeasurements m = merge_measurements({set_of("a.csv", {{"P1", 1}, {"P2", 2}, {"P3", 3}}),
                                                   set_of("b.csv", {{"P2", 20}, {"Q1", 100}}),
                                                   set_of("c.csv", {{"P2", 200}, {"P1", 10}})});
  REQUIRE(m.set.points.size() == 4);
  const std::vector<std::string> ids = {"P1", "P2", "P3", "Q1"};
  const std::vector<double> x = {10, 200, 3, 100};
  const std::vector<std::size_t> origin = {2, 2, 0, 1};
  for (std::size_t k = 0; k < 4; ++k) {
    CHECK(m.set.points[k].id == ids[k]);
    CHECK(m.set.points[k].xyz.x() == x[k]);
    CHECK(m.origin[k] == origin[k]);
  }
  CHECK(m.set.source == "a.csv + b.csv + c.csv");
  CHECK(m.file_points == std::vector<std::size_t>{3, 2, 2});
  REQUIRE(m.replaced.size() == 3);  // P2 by b, P2 (b's) by c, P1 by c
  CHECK((m.replaced[0].id == "P2" && m.replaced[0].file == 0 && m.replaced[0].by_file == 1 && m.replaced[0].was.x() == 2));
  CHECK((m.replaced[1].id == "P2" && m.replaced[1].file == 1 && m.replaced[1].by_file == 2 && m.replaced[1].was.x() == 20));
  CHECK((m.replaced[2].id == "P1" && m.replaced[2].file == 0 && m.replaced[2].by_file == 2 && m.replaced[2].was.x() == 1));
}

TEST_CASE("merge_measurements: one file as it is, refusals name the file") {
  MeasurementSet xyz = set_of("c.xyz", {{"1", 1}});
  xyz.ids_from_file = false;
  const MergedMeasurements one = merge_measurements({xyz});  // alone: read as before
  CHECK(one.set.points.size() == 1);
  CHECK_FALSE(one.set.ids_from_file);
  CHECK(one.replaced.empty());

  const MeasurementSet a = set_of("a.csv", {{"P1", 1}});
  CHECK(refusal({a, xyz}).find("c.xyz: its point ids are generated") == 0);
  MeasurementSet contacts = set_of("b.dmo", {{"P1", 1}});
  contacts.kind = ProbePointKind::contact;
  contacts.probe_radius = 0;
  CHECK(refusal({a, contacts}).find("b.dmo: holds contact points but a.csv holds centre points") == 0);
  MeasurementSet ball = set_of("b.csv", {{"P1", 1}});
  ball.probe_radius = 1.5;
  CHECK(refusal({a, ball}).find("b.csv: probe diameter 3") == 0);
}
