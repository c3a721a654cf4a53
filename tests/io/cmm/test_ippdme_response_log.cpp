// I++ DME response logs (ippdme_response_log.hpp): data matched to commands
// by tag, out of order, errors, and the program the log answers.
#include <doctest/doctest.h>

#include "base/error.hpp"
#include "io/cmm/ippdme_response_log.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/cmm/measurement_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

MeasurementSet read_log(const std::string& text, const std::string& program = "") {
  MeasurementReadOptions o;
  o.ippdme_program = program;
  o.probe_diameter = 2;  // the answers are ball centres
  return parse_measurements(text, "run.log", MeasurementFormat::ippdme_log, o);
}

std::string error_of(const std::string& text, const std::string& program = "") {
  try {
    read_log(text, program);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Two points, one approach move each: commands 9..12 are GoTo, PtMeas, GoTo, PtMeas.
ProbeProgram two_point_program() {
  ProbeProgram p;
  p.name = "t";
  p.probe = {"ruby", 2};
  p.stylus_length = 30;
  p.head_length = 30;
  p.move_speed = 50;
  p.measure_speed = 4;
  p.approach = 2, p.retract = 2, p.search = 4;
  for (int k = 0; k < 2; ++k) {
    ProgramStep s;
    s.point.id = "P" + std::to_string(k + 1);
    s.point.order = k + 1;
    s.point.xyz = Eigen::Vector3d(10 * k, 5, 1);
    s.point.ijk = Eigen::Vector3d(0, 0, 1);
    s.moves_before = {Eigen::Vector3d(10 * k, 5, 4)};
    p.steps.push_back(s);
  }
  return p;
}

}  // namespace

TEST_CASE("I++ DME log: responses out of order are matched by tag") {
  const std::string log =
      "00001 &\r\n00001 %\r\n"
      "00010 &\r\n"
      "00012 &\r\n"
      "00012 # X(10.002), Y(5), Z(1.001), IJK(0, 0, 2)\r\n"
      "00010 # X(-0.001), Y(5.5), Z(0.999)\r\n"
      "00012 %\r\n"
      "00010 %\r\n";
  const MeasurementSet set = read_log(log);
  REQUIRE(set.points.size() == 2);
  CHECK(set.kind == ProbePointKind::probe_centre);  // the server answers with the ball's centre
  CHECK(set.probe_radius == 1);
  CHECK_FALSE(set.ids_from_file);
  CHECK(set.points[0].id == "00012");
  CHECK(set.points[0].line == 5);
  CHECK(set.points[0].xyz == Eigen::Vector3d(10.002, 5, 1.001));
  CHECK(*set.points[0].ijk == Eigen::Vector3d(0, 0, 1));
  CHECK(set.points[1].id == "00010");
  CHECK_FALSE(set.points[1].ijk.has_value());
}

TEST_CASE("I++ DME log: an error without a point is a point not measured, with a point it is kept") {
  const MeasurementSet set = read_log("00010 PtMeas(X(1), Y(2), Z(3))\n00010 &\n00010 # X(1), Y(2), Z(3)\n00010 %\n"
                                      "00011 PtMeas(X(4), Y(5), Z(6))\n00011 &\n"
                                      "00011 ! Error(2, 0500, \"PtMeas\", \"Probe hit not detected\")\n00011 %\n");
  REQUIRE(set.points.size() == 1);
  REQUIRE(set.not_measured.size() == 1);
  CHECK(set.not_measured[0].id == "00011");
  CHECK(set.not_measured[0].line == 7);
  CHECK(set.not_measured[0].reason == "Error(2, 0500, \"PtMeas\", \"Probe hit not detected\")");
  CHECK(*set.not_measured[0].nominal == Eigen::Vector3d(4, 5, 6));
  const MeasurementSet kept = read_log("00010 &\n00010 ! Error(1, 0007, \"PtMeas\", \"Slow\")\n"
                                       "00010 # X(1), Y(2), Z(3)\n00010 %\n");
  CHECK(kept.points.size() == 1);
  CHECK(kept.not_measured.empty());
  CHECK(error_of("00010 &\n00010 &\n") == "run.log:2: tag 00010 is used again before its command completed");
  CHECK(error_of("00010 PtMeas(X(1), Y(2), Z(3))\n00010 # X(1), Y(2), Z(a)\n") ==
        "run.log:2: data: Z() needs one number");
  CHECK(error_of("00010 # X(1), Y(2), Z(3)\n00010 # X(1), Y(2), Z(3)\n") ==
        "run.log:2: a second data line for PtMeas 00010 (first on line 1)");
  CHECK(error_of("hello\n") == "run.log:1: not an I++ DME response or command: \"hello\"");
  CHECK(error_of("00010 %\n") == "run.log:1: tag 00010 completes a command that was not started");
  CHECK(error_of("00010 ! Oops(1)\n") == "run.log:1: error: expected Error(severity, number, \"command\", \"text\")");
  // Every PtMeas answered with an error: nothing to compare, and the message says why.
  CHECK(error_of("00011 PtMeas(X(4), Y(5), Z(6))\n00011 ! Error(2, 1006, \"PtMeas\", \"Surface not found\")\n") ==
        "run.log: no measured points in the file (1 PtMeas not measured, the first: 00011: "
        "Error(2, 1006, \"PtMeas\", \"Surface not found\"))");
}

TEST_CASE("I++ DME log: a reused tag is a new command, the client's own lines tell PtMeas from the rest") {
  const MeasurementSet set = read_log("00005 PtMeas(X(1), Y(2), Z(3), IJK(0, 0, 1))\n"
                                      "00005 &\n00005 # X(1), Y(2), Z(3)\n00005 %\n"
                                      "00005 Get(X(), Y(), Z())\n"
                                      "00005 &\n00005 # X(7), Y(8), Z(9)\n00005 %\n"
                                      "00005 PtMeas(X(4), Y(5), Z(6), IJK(0, 0, 1))\n"
                                      "00005 &\n00005 # X(4), Y(5), Z(6)\n00005 %\n");
  REQUIRE(set.points.size() == 2);
  CHECK(set.points[1].id == "00005_3");
  CHECK(set.points[1].xyz == Eigen::Vector3d(4, 5, 6));
  CHECK(*set.points[1].nominal == Eigen::Vector3d(4, 5, 6));
}

TEST_CASE("I++ DME log with its program: PtMeas targets become nominals, a missing point is not measured") {
  const std::string dir = test::scratch_dir("ippdme-log-program");
  const std::string prg = dir + "/t.prg";
  test::write_text(prg, ippdme_program_text(two_point_program()));
  // Tags 00012 and 00014 are the two PtMeas (10 set-up commands, then GoTo/PtMeas pairs).
  const std::string both = "00014 &\n00014 # X(10), Y(5), Z(1.5)\n00014 %\n00012 &\n00012 # X(0), Y(5), Z(0.5)\n00012 %\n";
  const MeasurementSet set = read_log(both, prg);
  REQUIRE(set.points.size() == 2);
  CHECK(*set.points[0].nominal == Eigen::Vector3d(10, 5, 1));
  CHECK(*set.points[1].nominal == Eigen::Vector3d(0, 5, 1));
  const MeasurementSet one = read_log("00012 &\n00012 # X(0), Y(5), Z(0.5)\n00012 %\n", prg);
  CHECK(one.points.size() == 1);
  REQUIRE(one.not_measured.size() == 1);
  CHECK(one.not_measured[0].id == "00014");
  CHECK(one.not_measured[0].reason == "PtMeas on line 27 of " + prg + " has no answer in the log");
  // Data answering a GoTo of the program is not a point.
  const MeasurementSet go = read_log("00011 &\n00011 # X(0), Y(5), Z(0.5)\n00011 %\n" + both, prg);
  CHECK(go.points.size() == 2);
}

TEST_CASE("I++ DME log writer: tags wrap after 99999, every coordinate reads back exactly") {
  MeasurementSet set;
  set.kind = ProbePointKind::contact;
  for (int k = 0; k < 100001; ++k) {
    MeasuredPoint p;
    p.xyz = Eigen::Vector3d(k * 0.1, -1.0 / (k + 1), 1e-7 * k);
    if (k % 2) p.ijk = Eigen::Vector3d(0, 0, 1);
    set.points.push_back(p);
  }
  const std::string text = ippdme_response_log_text(set);
  CHECK(is_ippdme_response_log(text));
  const MeasurementSet back = read_log(text);
  REQUIRE(back.points.size() == set.points.size());
  for (std::size_t k = 0; k < set.points.size(); ++k)
    if (back.points[k].xyz != set.points[k].xyz) FAIL_CHECK("point " << k);
  CHECK(back.points[99998].id == "99999");
  CHECK(back.points[99999].id == "00001_2");
  CHECK(back.points[100000].id == "00002_2");
}
