// `furrow predict` with G-code rapids: a rapid into the part or the stock
// is reported with its line and fails the command; a path without one keeps
// its prediction.json as before.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "geometry/primitives.hpp"
#include "io/part_file.hpp"
#include "support/run_cli.hpp"
#include "support/weak_shapes.hpp"

using namespace furrow;
using namespace furrow::test;
using nlohmann::json;

namespace {

// A 20 x 20 mm plate at z = 0 and a 6 mm ball, in `dir`.
void write_inputs(const std::string& dir) {
  write_part_json(one_face("plate", make_plane({-10, -10, 0}, {20, 0, 0}, {0, 20, 0})), dir + "/plate.json");
  write_text(dir + "/ball.json", "{\"name\":\"B6\",\"type\":\"ball\",\"diameter\":6,\"corner_radius\":3}\n");
}

const char* kHead =
    "G21 G90 G54\n"     // 1
    "G0 X-8 Y0 Z10\n"   // 2 from an unknown position: unchecked
    "G0 Z0\n"           // 3 down onto the plate (touching, not into it)
    "G1 X8 F500\n"      // 4
    "G0 Z10\n";         // 5
const char* kCrash = "G0 X0 Y-5 Z-1.5\n";  // 6 diving 1.5 mm into the plate
const char* kTail = "G28 G91 Z0\nM30\n";

CliResult predict(const std::string& dir, const std::string& path, const std::string& out,
                  const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"predict",  dir + "/plate.json", "--tool", dir + "/ball.json", "--toolpath", path,
                                   "--out", out, "--resolution", "0.25"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_furrow(args);
}

}  // namespace

TEST_CASE("furrow predict: a rapid into the part is a rapid gouge with its line and deepest point, exit 1") {
  const std::string dir = scratch_dir("predict-rapid-gouge");
  write_inputs(dir);
  write_text(dir + "/crash.nc", std::string(kHead) + kCrash + kTail);
  const CliResult r = predict(dir, dir + "/crash.nc", dir + "/p.json");
  CHECK(r.status == 1);
  CHECK(r.err.empty());
  CHECK(r.out.find("rapids: 3 checked against the part, 2 unchecked") != std::string::npos);
  CHECK(r.out.find("RAPID GOUGE line 6: cutter 1.5000 mm into the part at (0.000, -5.000, 0.000) on plate") !=
        std::string::npos);
  const json doc = json::parse(slurp(dir + "/p.json"));
  REQUIRE(doc.contains("rapids"));
  CHECK(doc["rapids"]["checked"] == 3);
  CHECK(doc["rapids"]["unchecked"] == 2);
  CHECK(doc["rapids"]["stock"].is_null());
  REQUIRE(doc["rapids"]["gouges"].size() == 1);
  const json& g = doc["rapids"]["gouges"][0];
  CHECK(g["line"] == 6);
  CHECK(g["kind"] == "part");
  CHECK(g["face"] == "plate");
  // The ball's lowest point is its tip: 1.5 mm below the plate, under the
  // rapid's end.
  CHECK(g["depth"].get<double>() == doctest::Approx(1.5).epsilon(1e-9));
  CHECK(std::fabs(g["xyz"][0].get<double>()) < 1e-4);
  CHECK(g["xyz"][1].get<double>() == doctest::Approx(-5).epsilon(1e-5));
  CHECK(std::fabs(g["xyz"][2].get<double>()) < 1e-9);
}

TEST_CASE("furrow predict: without rapid gouges the prediction is the one of the same passes as CSV") {
  const std::string dir = scratch_dir("predict-rapid-clean");
  write_inputs(dir);
  write_text(dir + "/clean.nc", std::string(kHead) + kTail);
  write_text(dir + "/clean.csv", "x,y,z\n-8,0,0\n8,0,0\n");
  const CliResult g = predict(dir, dir + "/clean.nc", dir + "/g.json");
  const CliResult c = predict(dir, dir + "/clean.csv", dir + "/c.json");
  CHECK(g.status == 0);
  CHECK(c.status == 0);
  CHECK(g.out.find("rapid gouges: 0") != std::string::npos);
  CHECK(c.out.find("rapids:") == std::string::npos);  // a CSV path has none
  json a = json::parse(slurp(dir + "/g.json")), b = json::parse(slurp(dir + "/c.json"));
  CHECK_FALSE(a.contains("rapids"));
  a.erase("toolpath");
  b.erase("toolpath");
  CHECK(a.dump() == b.dump());
}

TEST_CASE("furrow predict --stock: rapids below the stock top are rapid gouges, a bad box is refused") {
  const std::string dir = scratch_dir("predict-rapid-stock");
  write_inputs(dir);
  write_text(dir + "/clean.nc", std::string(kHead) + kTail);
  // The approach (line 3) and retract (line 5) run at rapid down to the
  // plate, 2 mm below the stock top: crashes into the raw stock.
  const CliResult r = predict(dir, dir + "/clean.nc", dir + "/s.json", {"--stock", "-10,-10,-5,10,10,2"});
  CHECK(r.status == 1);
  CHECK(r.out.find("RAPID GOUGE line 3: tip 2.0000 mm below the stock top at (-8.000, 0.000, 0.000)") !=
        std::string::npos);
  const json doc = json::parse(slurp(dir + "/s.json"));
  REQUIRE(doc["rapids"]["gouges"].size() == 2);
  CHECK(doc["rapids"]["gouges"][0]["kind"] == "stock");
  CHECK(doc["rapids"]["gouges"][1]["line"] == 5);
  CHECK(doc["rapids"]["gouges"][1]["depth"].get<double>() == doctest::Approx(2).epsilon(1e-12));
  CHECK(doc["rapids"]["stock"]["max"][2].get<double>() == 2);
  // Above the stock: clear, and the box is still recorded.
  const CliResult high = predict(dir, dir + "/clean.nc", dir + "/h.json", {"--stock", "-10,-10,-5,10,10,-0.5"});
  CHECK(high.status == 0);
  CHECK(json::parse(slurp(dir + "/h.json"))["rapids"]["gouges"].empty());

  const CliResult few = predict(dir, dir + "/clean.nc", dir + "/x.json", {"--stock", "1,2,3"});
  CHECK(few.status == 2);
  CHECK(few.err.find("--stock expects 6") != std::string::npos);
  const CliResult inverted = predict(dir, dir + "/clean.nc", dir + "/x.json", {"--stock", "-10,-10,-5,10,-20,2"});
  CHECK(inverted.status == 2);
  CHECK(inverted.err.find("--stock: each min must be below its max (y)") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/x.json"));
}
