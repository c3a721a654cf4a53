#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/run_cli.hpp"

using namespace furrow::test;

TEST_CASE("furrow info describes the mould example in text and JSON") {
  const CliResult text = run_furrow({"info", source_path("examples/parts/mould.json")});
  CHECK(text.status == 0);
  CHECK(text.err.empty());
  CHECK(text.out.find("face 0 \"mould\": degree 3x3, control net 21x17") != std::string::npos);
  CHECK(text.out.find("saddle") != std::string::npos);

  const CliResult js = run_furrow({"info", "--json", "--grid", "100", source_path("examples/parts/mould.json")});
  REQUIRE(js.status == 0);
  const auto doc = nlohmann::json::parse(js.out);
  CHECK(doc["face_count"] == 1);
  CHECK(doc["grid"] == 100);
  double share = 0;
  for (const char* c : {"planar", "convex", "concave", "saddle"}) share += doc["classes"][c]["share"].get<double>();
  CHECK(share == doctest::Approx(1.0).epsilon(1e-12));
  // Every class is present in the mould (that is what it is for).
  for (const char* c : {"convex", "concave", "saddle"}) CHECK(doc["classes"][c]["share"].get<double>() > 0.02);
  CHECK(doc["bounding_box"]["max"][0].get<double>() == doctest::Approx(100.0));
}

TEST_CASE("furrow info: area and classes of the semi-cylinder match the analytic answer") {
  const CliResult js = run_furrow({"info", "--json", source_path("examples/parts/semi_cylinder.json")});
  REQUIRE(js.status == 0);
  const auto doc = nlohmann::json::parse(js.out);
  // Half the lateral area of a cylinder: pi R L; midpoint rule on an exact
  // rational patch converges quadratically, 200 cells gives ~1e-5.
  CHECK(doc["area_mm2"].get<double>() == doctest::Approx(M_PI * 25.4 * 50.8).epsilon(1e-4));
  CHECK(doc["classes"]["convex"]["share"].get<double>() == 1.0);
  const auto& f = doc["faces"][0];
  CHECK(f["k2"][0].get<double>() == doctest::Approx(-1 / 25.4).epsilon(1e-9));
  CHECK(f["k1"][1].get<double>() == doctest::Approx(0.0).scale(1e-9));
}

TEST_CASE("bad part files and options: one clear line on stderr, exit 2, no output file") {
  const std::string dir = scratch_dir("info-bad");
  write_text(dir + "/empty.json", "");
  write_text(dir + "/garbage.json", "this is not json\n");
  write_text(dir + "/nan.json", "{\"units\":\"mm\",\"faces\":[{\"name\":\"a\",\"degree_u\":1,\"degree_v\":1,"
                                "\"knots_u\":[0,0,1,1],\"knots_v\":[0,0,1,1],"
                                "\"control_points\":[[[0,0,0],[0,1,NaN]],[[1,0,0],[1,1,0]]]}]}");
  write_text(dir + "/knots.json", "{\"units\":\"mm\",\"faces\":[{\"name\":\"a\",\"degree_u\":1,\"degree_v\":1,"
                                  "\"knots_u\":[0,1,1],\"knots_v\":[0,0,1,1],"
                                  "\"control_points\":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}]}");
  write_text(dir + "/weight.json", "{\"units\":\"mm\",\"faces\":[{\"name\":\"a\",\"degree_u\":1,\"degree_v\":1,"
                                   "\"knots_u\":[0,0,1,1],\"knots_v\":[0,0,1,1],\"weights\":[[1,1],[1,-1]],"
                                   "\"control_points\":[[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}]}");
  write_text(dir + "/nofaces.json", "{\"units\":\"mm\",\"faces\":[]}");
  write_text(dir + "/missing_field.json", "{\"faces\":[]}");
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"info", dir + "/empty.json"}, "empty.json: the file is empty"},
      {{"info", dir + "/garbage.json"}, "garbage.json: line 1, column 2: not valid JSON"},
      {{"info", dir + "/nan.json"}, "nan.json: line 1"},
      {{"info", dir + "/knots.json"}, "faces[0].knots_u: expected 4 knots"},
      {{"info", dir + "/weight.json"}, "faces[0].weights[1][1]: -1 is not a positive finite weight"},
      {{"info", dir + "/nofaces.json"}, "nofaces.json: faces: the part has no faces"},
      {{"info", dir + "/missing_field.json"}, "missing_field.json: units: missing"},
      {{"info", dir + "/absent.json"}, "absent.json: cannot open the file"},
      {{"info", dir}, "is a folder"},
      {{"info"}, "furrow info: missing PART"},
      {{"info", "--grid", "0", source_path("examples/parts/mould.json")}, "--grid must be at least 2"},
      {{"info", "--eps", "-1", source_path("examples/parts/mould.json")}, "--eps must not be negative"},
      {{"info", "--bogus", source_path("examples/parts/mould.json")}, "unknown option --bogus"},
      {{"info", "--out", dir + "/out.txt", dir + "/knots.json"}, "expected 4 knots"},
      {{"frobnicate"}, "unknown command"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args.back());
    const CliResult r = run_furrow(c.args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(c.expected) != std::string::npos);
  }
  CHECK_FALSE(std::filesystem::exists(dir + "/out.txt"));
}

TEST_CASE("furrow info --out writes the file whole and refuses to overwrite its input") {
  const std::string dir = scratch_dir("info-out");
  const std::string part = dir + "/part.json";
  std::filesystem::copy_file(source_path("examples/parts/two_face.json"), part);
  const std::string before = slurp(part);
  const CliResult r = run_furrow({"info", "--json", "--out", dir + "/info.json", part});
  CHECK(r.status == 0);
  CHECK(nlohmann::json::parse(slurp(dir + "/info.json"))["face_count"] == 2);
  const CliResult clash = run_furrow({"info", "--out", part, part});
  CHECK(clash.status == 2);
  CHECK(slurp(part) == before);
  // No temporary files are left behind.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 2);
}

TEST_CASE("help and version exit 0, no arguments exits 2 with the overview") {
  CHECK(run_furrow({"--version"}).status == 0);
  const CliResult help = run_furrow({"help", "info"});
  CHECK(help.status == 0);
  CHECK(help.out.find("usage: furrow info PART") == 0);
  const CliResult none = run_furrow({});
  CHECK(none.status == 2);
  CHECK(none.err.find("commands:") != std::string::npos);
}
