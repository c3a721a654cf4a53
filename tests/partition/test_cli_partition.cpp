// furrow partition end to end: outputs, and bad input refused with one line,
// exit status 2 and no output file.
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/part_file.hpp"
#include "partition/regions_file.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using namespace furrow::test;

namespace {

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23).
std::pair<unsigned, unsigned> png_size(const std::string& bytes) {
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  return {be32(16), be32(20)};
}

}  // namespace

TEST_CASE("furrow partition writes regions.json and a PNG, and summarises the regions") {
  const std::string dir = scratch_dir("cli-partition");
  const std::string part = source_path("examples/parts/mould.json");
  const CliResult r = run_furrow({"partition", part, "--out", dir + "/regions.json", "--image",
                                  dir + "/regions.png", "--grid", "200x160"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("1 face, 7 regions") != std::string::npos);
  CHECK(r.out.find("grid 200x160") != std::string::npos);

  const RegionMap map = read_regions(dir + "/regions.json");
  CHECK(map.regions.size() == 7);
  CHECK_NOTHROW(map.check_belongs_to(read_part(part), "regions.json", "mould.json"));
  const auto doc = nlohmann::json::parse(slurp(dir + "/regions.json"));
  CHECK(doc["format"] == "furrow-regions");
  CHECK(doc["faces"][0]["eps_source"] == "default");

  const std::string png = slurp(dir + "/regions.png");
  REQUIRE(png.size() > 24);
  CHECK(png.compare(1, 3, "PNG") == 0);
  const auto [w, h] = png_size(png);
  CHECK(w >= 760);
  CHECK(h > 400);
  // No temporary files are left next to the outputs.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 2);

  // Options reach the library: an explicit eps is recorded as such.
  const CliResult e = run_furrow({"partition", part, "--out", dir + "/e.json", "--eps", "0.002",
                                  "--spacing", "1", "--min-area", "10"});
  REQUIRE(e.status == 0);
  const RegionMap m2 = read_regions(dir + "/e.json");
  CHECK(m2.faces[0].eps == 0.002);
  CHECK(m2.faces[0].eps_from_user);
  CHECK(m2.faces[0].min_area == 10.0);
  // 1 mm cells: the mould spans 100 x 80 mm in plan, a little more on the
  // surface over the dome.
  CHECK(m2.faces[0].nu >= 100);
  CHECK(m2.faces[0].nu <= 106);
  CHECK(m2.faces[0].nv >= 80);
  CHECK(m2.faces[0].nv <= 86);
}

TEST_CASE("furrow partition: bad input gives one line, exit 2 and no output file") {
  const std::string dir = scratch_dir("cli-partition-bad");
  const std::string part = source_path("examples/parts/mould.json");
  const std::string out = dir + "/regions.json";
  write_text(dir + "/garbage.json", "not json at all\n");
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"partition", part, "--out", out, "--grid", "0"}, "--grid: expected COUNTUxCOUNTV"},
      {{"partition", part, "--out", out, "--grid", "-3"}, "--grid: expected"},
      {{"partition", part, "--out", out, "--grid", "0x10"}, "--grid: expected"},
      {{"partition", part, "--out", out, "--grid", "9000x10"}, "is too fine"},
      {{"partition", part, "--out", out, "--spacing", "0"}, "--spacing: must be positive"},
      {{"partition", part, "--out", out, "--spacing", "-1"}, "--spacing: must be positive"},
      {{"partition", part, "--out", out, "--spacing", "0.0001"}, "use a coarser spacing"},
      {{"partition", part, "--out", out, "--grid", "10", "--spacing", "1"}, "exclude each other"},
      {{"partition", part, "--out", out, "--eps", "-1"}, "--eps: must not be negative"},
      {{"partition", part, "--out", out, "--eps", "nan"}, "--eps expects a number"},
      {{"partition", part, "--out", out, "--min-area", "-5"}, "--min-area: must not be negative"},
      {{"partition", dir + "/missing.json", "--out", out}, "missing.json: cannot open the file"},
      {{"partition", dir + "/garbage.json", "--out", out}, "garbage.json: line 1"},
      {{"partition", part}, "--out is required"},
      {{"partition", "--out", out}, "missing PART"},
      {{"partition", part, "--out", dir + "/regions.txt"}, "expected a .json file name"},
      {{"partition", part, "--out", out, "--image", dir + "/r.jpg"}, "expected a .png file name"},
      {{"partition", part, "--out", out, "--bogus"}, "unknown option --bogus"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.expected);
    const CliResult r = run_furrow(c.args);
    CHECK(r.status == 2);
    CHECK(line_count(r.err) == 1);
    CHECK(r.err.find(c.expected) != std::string::npos);
    CHECK(r.out.empty());
    CHECK(!std::filesystem::exists(out));
  }
  // The part itself is never overwritten.
  const std::string copy = dir + "/part.json";
  std::filesystem::copy_file(part, copy);
  const CliResult r = run_furrow({"partition", copy, "--out", copy});
  CHECK(r.status == 2);
  CHECK(slurp(copy) == slurp(part));
}
