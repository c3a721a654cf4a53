// DMIS and I++ DME programs: golden files of a tiny hand-made program
// (reviewed by hand against the DMIS 5.2 statement forms and NIST's I++
// DME command parser rules), round trips through the strict readers, the
// measurement reader finding our labels and nominals in a CMM results file,
// and the strict readers refusing what we do not write.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "base/error.hpp"
#include "io/cmm/dmis_program_reader.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/cmm/measurement_file.hpp"
#include "program_fixtures.hpp"

using namespace furrow;

namespace {

std::string golden(const std::string& name) {
  std::ifstream in(std::string(FURROW_SOURCE_DIR) + "/tests/io/cmm/golden/" + name, std::ios::binary);
  REQUIRE(in.good());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

void check_same_program(const ProbeProgram& got, const ProbeProgram& want, bool with_ids, double tolerance) {
  REQUIRE(got.steps.size() == want.steps.size());
  for (std::size_t k = 0; k < want.steps.size(); ++k) {
    const ProgramStep& g = got.steps[k];
    const ProgramStep& w = want.steps[k];
    if (with_ids) CHECK(g.point.id == w.point.id);
    CHECK(g.point.order == static_cast<int>(k) + 1);
    CHECK((g.point.xyz - w.point.xyz).cwiseAbs().maxCoeff() <= tolerance);
    CHECK((g.point.ijk - w.point.ijk.normalized()).cwiseAbs().maxCoeff() <= 1e-8);
    REQUIRE(g.moves_before.size() == w.moves_before.size());
    for (std::size_t m = 0; m < w.moves_before.size(); ++m)
      CHECK((g.moves_before[m] - w.moves_before[m]).cwiseAbs().maxCoeff() <= tolerance);
  }
  REQUIRE(got.final_moves.size() == want.final_moves.size());
  for (std::size_t m = 0; m < want.final_moves.size(); ++m)
    CHECK((got.final_moves[m] - want.final_moves[m]).cwiseAbs().maxCoeff() <= tolerance);
  CHECK(got.approach == want.approach);
  CHECK(got.move_speed == want.move_speed);
  CHECK(got.measure_speed == want.measure_speed);
  CHECK(got.retract == want.retract);
  CHECK(got.search == want.search);
}

}  // namespace

TEST_CASE("DMIS program of the tiny part matches its golden file and reads back") {
  const ProbeProgram p = test::tiny_program();
  const std::string text = dmis_program_text(p);
  CHECK(text == golden("tiny.dmi"));
  const ProbeProgram back = parse_dmis_program(text, "tiny.dmi");
  check_same_program(back, p, true, 0);
  CHECK(back.name == "tiny");
  CHECK(back.probe.name == "PROBE1");  // DMIS labels are upper case
  CHECK(back.probe.diameter == 2);
  CHECK(back.head_length == 62.5);     // SNSDEF carries the head-to-ball length, not the stylus
  CHECK(back.part == "tiny_plane.json");
  CHECK(back.revision == "C");
  REQUIRE(back.tolerance.has_value());
  CHECK(back.tolerance->lower == -0.02);
  CHECK(back.tolerance->upper == 0.03);
  // The date is in the header comment, from the program, not from the clock.
  CHECK(text.find("$$ part: tiny_plane.json; revision: C; date: 2026-03-14\r\n") != std::string::npos);
}

TEST_CASE("DMIS labels are upper case, header fields, speeds and the tolerance follow the program") {
  ProbeProgram p = test::tiny_program();
  p.probe.name = "ruby_2mm";
  p.steps[0].point.id = "a1";
  p.move_speed = 80;
  p.measure_speed = 2.5;
  p.tolerance.reset();
  p.revision.clear();
  p.date.clear();
  const std::string text = dmis_program_text(p);
  CHECK(text.find("S(RUBY_2MM)=SNSDEF/") != std::string::npos);
  CHECK(text.find("SNSLCT/S(RUBY_2MM)\r\n") != std::string::npos);
  CHECK(text.find("F(A1)=FEAT/POINT") != std::string::npos);
  CHECK(text.find("FEDRAT/POSVEL,MMPS,80.000000\r\n") != std::string::npos);
  CHECK(text.find("FEDRAT/MESVEL,MMPS,2.500000\r\n") != std::string::npos);
  CHECK(text.find("TOL/PROFP") == std::string::npos);
  CHECK(text.find(",TA(") == std::string::npos);
  CHECK(text.find("PARTRV") == std::string::npos);
  CHECK(text.find("revision: not stated; date: not stated") != std::string::npos);
  const ProbeProgram back = parse_dmis_program(text, "u.dmi");
  CHECK(back.steps[0].point.id == "A1");
  CHECK(back.move_speed == 80);
  CHECK(back.measure_speed == 2.5);
  CHECK_FALSE(back.tolerance.has_value());
  const ProbeProgram ipp = parse_ippdme_program(ippdme_program_text(p), "u.prg");
  CHECK(ipp.probe.name == "ruby_2mm");  // the tool name the I++ server knows, as given
  CHECK(ipp.move_speed == 80);
  CHECK(ipp.measure_speed == 2.5);
  // Two ids that are one DMIS label are refused, not merged.
  p.steps[1].point.id = "A1";
  CHECK_THROWS_AS(dmis_program_text(p), InputError);
}

TEST_CASE("program settings: dates, revisions, head length and zones are checked") {
  ProgramSettings s;
  for (const char* good : {"2026-03-14", "2024-02-29", "2000-02-29", "1999-12-31"}) {
    s.date = good;
    CHECK_NOTHROW(validate(s, 20));
  }
  for (const char* bad : {"2026-3-14", "2023-02-29", "1900-02-29", "2026-13-01", "2026-04-31", "14.03.2026", "today"}) {
    s.date = bad;
    CHECK_THROWS_AS(validate(s, 20), InputError);
  }
  s.date.clear();
  s.revision = "it's";
  CHECK_THROWS_AS(validate(s, 20), InputError);
  s.revision = "B.2";
  CHECK_NOTHROW(validate(s, 20));
  s.head_length = 19.5;
  CHECK_THROWS_AS(validate(s, 20), InputError);
  s.head_length = 20;
  CHECK_NOTHROW(validate(s, 20));
  s.tolerance = PointProfileTolerance{0.01, 0.05};
  CHECK_THROWS_AS(validate(s, 20), InputError);
  s.tolerance = PointProfileTolerance{0, 0.05};
  CHECK_NOTHROW(validate(s, 20));
}

TEST_CASE("I++ DME command file of the tiny part matches its golden file and reads back") {
  const ProbeProgram p = test::tiny_program();
  const std::string text = ippdme_program_text(p);
  CHECK(text == golden("tiny.prg"));
  check_same_program(parse_ippdme_program(text, "tiny.prg"), p, false, 0);
}

TEST_CASE("the measurement reader finds our labels and nominals in a results file") {
  const ProbeProgram p = test::tiny_program();
  // A CMM's results file: the program's statements and an actual per label.
  std::string results = dmis_program_text(p);
  results = replace(results, "ENDFIL", "FA(P0002)=FEAT/POINT,CART,15.01,5,5.02,0,0,1\r\nFA(P0001)=FEAT/POINT,CART,5,5,4.99,0,0,1\r\nENDFIL");
  const MeasurementSet set = parse_measurements(results, "tiny.dmo", MeasurementFormat::dmis, {});
  REQUIRE(set.points.size() == 2);
  CHECK(set.points[0].id == "P0002");
  REQUIRE(set.points[0].nominal.has_value());
  CHECK(*set.points[0].nominal == p.steps[1].point.xyz);
  CHECK(*set.points[1].nominal == p.steps[0].point.xyz);
  CHECK(set.points[1].xyz.z() == 4.99);
}

TEST_CASE("random programs round-trip to 1e-6 mm through both readers") {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> c(-400, 400), d(-1, 1);
  ProbeProgram p = test::tiny_program();
  p.steps.clear();
  for (int k = 0; k < 200; ++k) {
    ProgramStep s;
    s.point.id = "Q" + std::to_string(k);
    s.point.xyz = {c(rng), c(rng), c(rng)};
    s.point.ijk = Eigen::Vector3d(d(rng), d(rng), d(rng) + 2).normalized();
    for (int m = 0; m < k % 4; ++m) s.moves_before.emplace_back(c(rng), c(rng), c(rng));
    s.moves_before.push_back(s.point.xyz + 4 * s.point.ijk);
    p.steps.push_back(s);
  }
  check_same_program(parse_dmis_program(dmis_program_text(p), "r.dmi"), p, true, 5e-7);
  check_same_program(parse_ippdme_program(ippdme_program_text(p), "r.prg"), p, false, 5e-7);
}

TEST_CASE("the strict DMIS reader refuses what Furrow does not write") {
  const std::string ok = dmis_program_text(test::tiny_program());
  auto refused = [&](const std::string& text, const std::string& why) {
    try {
      parse_dmis_program(text, "x.dmi");
      FAIL("accepted: " << why);
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).rfind("x.dmi:", 0) == 0);
    }
  };
  refused(replace(ok, "PTMEAS/CART,15.000000", "PTMEAS/CART,15.100000"), "PTMEAS off the nominal");
  refused(replace(ok, "ENDFIL\r\n", ""), "no ENDFIL");
  refused(replace(ok, "MODE/PROG,MAN\r\n", "MODE/PROG,MAN\r\nCALL/EXTERN,DME,'x'\r\n"), "unknown statement");
  refused(replace(ok, "ENDMES\r\nOUTPUT/FA(P0001)", "OUTPUT/FA(P0001)"), "missing ENDMES");
  refused(replace(ok, "F(P0002)=FEAT", "F(P0001)=FEAT"), "label defined twice");
  refused(replace(ok, "UNITS/MM,ANGDEC", "UNITS/INCH,ANGDEC"), "inch");
  refused(replace(ok, "SNSLCT/S(PROBE1)", "SNSLCT/S(OTHER)"), "another sensor");
  refused(replace(ok, "F(P0002)=FEAT", "F(p0002)=FEAT"), "lower-case label");
  refused(replace(ok, "OUTPUT/FA(P0002),TA(PROFILE)", "OUTPUT/FA(P0002)"), "a point without its tolerance");
  refused(replace(ok, "FEDRAT/MESVEL,MMPS,4.000000\r\n", ""), "no measuring speed");
  refused(replace(ok, "PL(PROGRAM)=PLANID/'tiny'", "PL(PROGRAM)=PLANID/'other'"), "PLANID of another program");
  refused(replace(ok, "GOTO/5.000000,5.000000,9.000000", "GOTO/5.0e0,5.000000,9.000000"), "exponent");
}

TEST_CASE("the strict I++ DME reader enforces the spec's layout and the session rules") {
  const std::string ok = ippdme_program_text(test::tiny_program());
  auto refused = [&](const std::string& text, const std::string& why) {
    try {
      parse_ippdme_program(text, "x.prg");
      FAIL("accepted: " << why);
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).rfind("x.prg:", 0) == 0);
    }
  };
  std::string lf = ok;
  for (std::size_t at; (at = lf.find("\r\n")) != std::string::npos;) lf.erase(at, 1);
  refused(lf, "LF line ends");
  refused(replace(ok, "00002 Home()", "00003 Home()"), "tag out of sequence");
  refused(replace(ok, "00002 Home()\r\n\\\\\r\n", "00002 Home()\r\n"), "missing \\\\ line");
  refused(replace(ok, "00002 Home()", "0002 Home()"), "four-digit tag");
  refused(replace(ok, "00002 Home()", "00002Home()"), "no space after the tag");
  refused(replace(ok, "X(5.000000), Y(5.000000), Z(9.000000)", "X(5.0000000000000000), Y(5.000000), Z(9.000000)"),
          "17 digits");
  refused(replace(ok, "X(5.000000), Y(5.000000), Z(9.000000)", "X(5 .000000), Y(5.000000), Z(9.000000)"),
          "space inside a number");
  refused(replace(ok, "IJK(0.000000000, 0.600000000, 0.800000000)", "IJK(0, 0, 0)"), "zero direction");
  refused(replace(ok, "00002 Home()", "00002 EnumTools()"), "not homed before motion");
  refused(replace(ok, ":\r\n:\r\n", ""), "no closing colon line");
  refused(replace(ok, "00004 ChangeTool(\"Probe1\")", "00004 ChangeTool(\"Pro\tbe1\")"), "control character in a string");
  // Spaces next to parentheses and commas are allowed.
  CHECK_NOTHROW(parse_ippdme_program(replace(ok, "GoTo(X(5.000000), Y(5.000000), Z(9.000000))",
                                             "GoTo( X(5.000000) , Y (5.000000),Z(9.000000) )"),
                                     "x.prg"));
}

TEST_CASE("I++ DME numbers follow the spec's grammar") {
  for (const char* good : {"1", "-1.5", "+.5", "1.", "1e5", "1E-123", "1234567890123456", "-0.000001"})
    CHECK(is_ippdme_number(good));
  for (const char* bad : {"12345678901234567", "1e1234", "1.2.3", "e5", "-", ".", "1e", "1x", ""})
    CHECK_FALSE(is_ippdme_number(bad));
}

TEST_CASE("I++ DME tags wrap from 99999 to 00001 and still read back") {
  ProbeProgram p = test::tiny_program();
  p.steps.clear();
  for (int k = 0; k < 50000; ++k) {
    ProgramStep s;
    s.point.xyz = {k * 0.001, 1, 2};
    s.moves_before = {s.point.xyz + Eigen::Vector3d(0, 0, 4)};
    p.steps.push_back(s);
    p.steps.back().point.id = "P" + std::to_string(k);
  }
  const std::string text = ippdme_program_text(p);
  CHECK(text.find("\r\n99999 ") != std::string::npos);
  CHECK(text.find("\r\n00001 PtMeas") != std::string::npos);
  CHECK(parse_ippdme_program(text, "big.prg").steps.size() == 50000);
}

TEST_CASE("programs refuse names, labels and numbers they cannot carry") {
  ProbeProgram p = test::tiny_program();
  p.name = "two words";
  CHECK_THROWS_AS(dmis_program_text(p), InputError);
  p = test::tiny_program();
  p.probe.name = "Probe\"1";
  CHECK_THROWS_AS(ippdme_program_text(p), InputError);
  p = test::tiny_program();
  p.steps[0].point.xyz.x() = std::nan("");
  CHECK_THROWS_AS(dmis_program_text(p), InputError);
  CHECK(fixed_number(-1e-9, 6) == "0.000000");
  CHECK(fixed_number(-2.5, 3) == "-2.500");
}

TEST_CASE("fuzz: a very long line is refused before any pattern is matched, not a stack overflow") {
  // fuzz_ippdme_program and fuzz_dmis_program under ASan: std::regex
  // recursed once per character of a 300 000-character line or statement and
  // overflowed the stack. Both readers now refuse lines no writer emits.
  const std::string ipp = "00001 StartSession(" + std::string(300000, 'X') + ")\r\n\\\\\r\n";
  try {
    parse_ippdme_program(ipp, "x.prg");
    FAIL("accepted a 300 000-character command");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "x.prg:1: line longer than 1000 characters");
  }
  const std::string dmis = "DMISMN/'" + std::string(300000, 'A') + "',05.2\r\n";
  try {
    parse_dmis_program(dmis, "x.dmi");
    FAIL("accepted a 300 000-character statement");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "x.dmi:1: statement longer than 1000 characters");
  }
  // The written programs stay well inside the bound.
  for (const std::string& text :
       {ippdme_program_text(test::tiny_program()), dmis_program_text(test::tiny_program())}) {
    std::size_t longest = 0, start = 0;
    for (std::size_t lf; (lf = text.find('\n', start)) != std::string::npos; start = lf + 1)
      longest = std::max(longest, lf - start);
    CHECK(longest < 200);
  }
}
