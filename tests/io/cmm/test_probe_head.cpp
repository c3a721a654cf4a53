// The indexable head's description file (head.json) and the programs that
// select a tip per point: DMIS sensors per tip with SNSLCT at each change,
// I++ ChangeTool per tip, both read back by the strict readers.
#include <doctest/doctest.h>

#include <string>

#include "base/error.hpp"
#include "io/cmm/dmis_program_reader.hpp"
#include "io/cmm/dmis_writer.hpp"
#include "io/cmm/ippdme_reader.hpp"
#include "io/cmm/ippdme_writer.hpp"
#include "io/cmm/probe_head.hpp"
#include "program_fixtures.hpp"

using namespace furrow;

namespace {

const char* kHeadJson = R"({
  "head": {"type": "PH10M", "a": {"min": 0, "max": 105, "step": 7.5}, "b": {"min": -180, "max": 180, "step": 7.5},
           "length": 40, "diameter": 48},
  "stylus": {"length": 20, "ball_diameter": 2, "stem_diameter": 1},
  "extension": {"length": 10, "diameter": 5},
  "probe_body": {"length": 30, "diameter": 13.2},
  "qualified": [{"a": 0, "b": 0}, {"a": 90, "b": 0}, {"a": 90, "b": -90}, {"a": 52.5, "b": 172.5}]
})";

std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text) {
  try {
    parse_probe_head(text, "head.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The tiny program's three points with tips: A0B0, then A90B0 twice (the
// second change comes over the clearance plane: three moves).
// What a reader does not recover (comments, or nothing in I++), from the original.
ProbeProgram with_header_of(ProbeProgram got, const ProbeProgram& original) {
  got.stylus_length = original.stylus_length;
  got.head_length = original.head_length;
  got.date = original.date;
  got.part = original.part;
  got.revision = original.revision;
  got.tolerance = original.tolerance;
  got.name = original.name;
  got.probe.diameter = original.probe.diameter;
  for (std::size_t k = 0; k < got.steps.size() && k < original.steps.size(); ++k) {
    got.steps[k].point.region = original.steps[k].point.region;
    got.steps[k].point.face_index = original.steps[k].point.face_index;
    got.steps[k].point.id = original.steps[k].point.id;
  }
  return got;
}

}  // namespace

TEST_CASE("head.json: fields, the grid and the reach") {
  const ProbeHead h = parse_probe_head(kHeadJson, "head.json");
  CHECK(h.type == "PH10M");
  CHECK(h.a.max == 105);
  CHECK(h.b.step == 7.5);
  CHECK(h.reach() == 60);  // stylus 20 + extension 10 + body 30
  CHECK(h.head_diameter == 48);
  REQUIRE(h.qualified.size() == 4);
  CHECK((h.qualified[3] == TipAngles{52.5, 172.5}));
  CHECK(h.a.on_grid(97.5));
  CHECK(!h.a.on_grid(100));
  CHECK(!h.a.on_grid(112.5));
  CHECK(h.b.on_grid(-172.5));
}

TEST_CASE("head.json: every error names the field") {
  CHECK(error_of(with(kHeadJson, R"({"a": 52.5, "b": 172.5})", R"({"a": 50, "b": 172.5})")) ==
        "head.json.qualified[3].a: 50 is not on the head's A grid 0 + k * 7.5 up to 105");
  CHECK(error_of(with(kHeadJson, R"({"a": 90, "b": -90})", R"({"a": 90, "b": -95})")).find("qualified[2].b") !=
        std::string::npos);
  CHECK(error_of(with(kHeadJson, R"("stem_diameter": 1)", R"("stem_diameter": 3)")).find("stylus.stem_diameter") !=
        std::string::npos);
  CHECK(error_of(with(kHeadJson, R"("length": 20,)", R"("length": 0.5,)")).find("stylus.length") != std::string::npos);
  CHECK(error_of(with(kHeadJson, R"("probe_body")", R"("probe_bodi")")).find("probe_bodi: unknown member (see docs/formats.md \"Probe head\")") !=
        std::string::npos);
  CHECK(error_of(with(kHeadJson, R"({"a": 90, "b": 0})", R"({"a": 0, "b": 0})")).find("listed twice") !=
        std::string::npos);
  CHECK(error_of(with(kHeadJson, R"("max": 105)", R"("max": 190)")).find("head.a.max") != std::string::npos);
  CHECK(error_of(with(kHeadJson, R"("step": 7.5}, "b")", R"("step": 0}, "b")")).find("head.a.step") != std::string::npos);
}

TEST_CASE("tip names are DMIS labels and read back to their angles") {
  CHECK((tip_name({30, 90}) == "A30B90"));
  CHECK((tip_name({7.5, -180}) == "A7P5BM180"));
  CHECK((tip_name({0, -0.0}) == "A0B0"));
  for (const TipAngles t : {TipAngles{0, 0}, TipAngles{97.5, -22.5}, TipAngles{105, 180}}) {
    const std::optional<TipSensor> s = split_tip_sensor("PROBE_1_" + tip_name(t));
    REQUIRE(s);
    CHECK(s->base == "PROBE_1");
    CHECK(s->tip == t);
  }
  CHECK(!split_tip_sensor("PROBE1"));
  CHECK(!split_tip_sensor("PROBE1_A030B0"));  // not the canonical spelling
}

TEST_CASE("DMIS: one sensor per tip, SNSLCT at each change, read back and rewritten byte for byte") {
  const ProbeProgram p = test::tipped_program();
  const std::string text = dmis_program_text(p);
  CHECK(count(text, "=SNSDEF/") == 2);
  CHECK(text.find("S(PROBE1_A0B0)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,60.000000,2.000000\r\n") != std::string::npos);
  CHECK(text.find("S(PROBE1_A52P5BM172P5)=SNSDEF/PROBE,INDEX,POL,52.5,-172.5,0,0,-1,60.000000,2.000000\r\n") !=
        std::string::npos);
  CHECK(count(text, "SNSLCT/") == 3);  // the start, then two changes
  // The change comes after the rise to the clearance plane.
  CHECK(text.find("GOTO/5.000000,5.000000,12.000000\r\nSNSLCT/S(PROBE1_A52P5BM172P5)\r\nGOTO/15.000000,5.000000,12.000000") !=
        std::string::npos);
  const ProbeProgram back = parse_dmis_program(text, "tipped.dmi");
  CHECK(back.probe.name == "PROBE1");
  REQUIRE(back.tips.size() == 2);
  CHECK((back.tips[1] == TipAngles{52.5, -172.5}));
  REQUIRE(back.steps.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) CHECK(back.steps[k].point.tip == p.steps[k].point.tip);
  CHECK(dmis_program_text(with_header_of(back, p)) == text);
  // A change placed elsewhere is refused, naming the line.
  const std::string moved =
      with(text, "GOTO/5.000000,5.000000,12.000000\r\nSNSLCT/S(PROBE1_A52P5BM172P5)\r\n",
           "SNSLCT/S(PROBE1_A52P5BM172P5)\r\nGOTO/5.000000,5.000000,12.000000\r\n");
  CHECK_THROWS_WITH_AS(parse_dmis_program(moved, "moved.dmi"), doctest::Contains("tip change belongs"), InputError);
}

TEST_CASE("I++ DME: ChangeTool per tip, read back and rewritten byte for byte") {
  const ProbeProgram p = test::tipped_program();
  const std::string text = ippdme_program_text(p);
  CHECK(count(text, "ChangeTool(") == 3);
  CHECK(text.find("ChangeTool(\"Probe1_A0B0\")") != std::string::npos);
  CHECK(text.find("GoTo(X(5.000000), Y(5.000000), Z(12.000000))\r\n\\\\\r\n00014 ChangeTool(\"Probe1_A52P5BM172P5\")") !=
        std::string::npos);
  const ProbeProgram back = parse_ippdme_program(text, "tipped.prg");
  CHECK(back.probe.name == "Probe1");
  CHECK(back.start_tip == p.start_tip);
  REQUIRE(back.tips.size() == 2);
  for (std::size_t k = 0; k < 3; ++k) CHECK(back.steps[k].point.tip == p.steps[k].point.tip);
  CHECK(ippdme_program_text(with_header_of(back, p)) == text);
}

TEST_CASE("programs without tips are written as for the vertical stylus") {
  const ProbeProgram p = test::tiny_program();
  const std::string dmis = dmis_program_text(p);
  CHECK(dmis.find("S(PROBE1)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,") != std::string::npos);
  CHECK(count(dmis, "SNSLCT/") == 1);
  CHECK(parse_dmis_program(dmis, "tiny.dmi").tips.empty());
  CHECK(!parse_ippdme_program(ippdme_program_text(p), "tiny.prg").start_tip);
  // A step with a tip in a program without tips cannot be written.
  ProbeProgram bad = p;
  bad.steps[0].point.tip = TipAngles{0, 0};
  CHECK_THROWS_AS(dmis_program_text(bad), InputError);
}
