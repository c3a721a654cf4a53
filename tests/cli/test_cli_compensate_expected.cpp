// COMP.json `expected`: the residual `furrow compensate` expects at the
// measured points once its program is cut. A mould measured with a planted
// raised-cosine bump (simulate-measurement --bump) and 1 um noise, the
// CMM's frame kept (no best fit takes part of the bump off). Oracles: the
// analytic bump at each planned point's nominal position, computed here;
// the per-region statistics recomputed here from the per-point values.
// And --predict-out: the prediction of the program written, whose oracle is
// `furrow predict` run on the written file (byte for byte).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/numbers.hpp"
#include "io/part_file.hpp"
#include "mould_bump_fixture.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double kRadius = 15;    // [mm]
constexpr double kHeight = 0.05;  // [mm], material left
constexpr double kKept = 25;      // [mm] plan points kept within this of the bump centre
constexpr double kNoise = 0.001;  // [mm] 1-sigma

using Measured = test::MouldBump;

using test::bump_at;

const Measured& measured() {
  static const Measured made = test::measured_mould_bump("cli-compensate-expected", kRadius, kHeight, kKept, 5);
  return made;
}

json compensate(const Measured& m, const std::string& gain) {
  const std::string out = m.dir + "/comp_gain" + gain + ".nc";
  const auto r = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", m.program, "--tool",
                             m.tool, "--out", out, "--gain", gain});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  return json::parse(slurp(m.dir + "/comp_gain" + gain + ".json"));
}

// Statistics of the points of one region (or all), recomputed here.
struct Recomputed {
  std::size_t n = 0;
  double before = 0, after = 0, worst_after = 0;
};

Recomputed recompute(const json& points, const json& region) {
  Recomputed r;
  for (const json& p : points) {
    if (!region.is_null() && p["region"] != region) continue;
    ++r.n;
    r.before += std::pow(p["measured"].get<double>(), 2);
    r.after += std::pow(p["residual"].get<double>(), 2);
    r.worst_after = std::max(r.worst_after, std::abs(p["residual"].get<double>()));
  }
  if (r.n > 0) {
    r.before = std::sqrt(r.before / double(r.n));
    r.after = std::sqrt(r.after / double(r.n));
  }
  return r;
}

void check_statistics(const json& expected) {
  const json& points = expected["points"];
  const Recomputed all = recompute(points, json(nullptr));
  CHECK(expected["overall"]["points"].get<std::size_t>() == all.n);
  CHECK(std::abs(expected["overall"]["rms_before"].get<double>() - all.before) < 1e-12);
  CHECK(std::abs(expected["overall"]["rms_after"].get<double>() - all.after) < 1e-12);
  CHECK(std::abs(std::abs(expected["overall"]["worst_after"]["value"].get<double>()) - all.worst_after) < 1e-12);
  REQUIRE(expected["regions"].size() > 1);
  for (const json& region : expected["regions"]) {
    const Recomputed r = recompute(points, region["region"]);
    CHECK(region["points"].get<std::size_t>() == r.n);
    CHECK(std::abs(region["rms_before"].get<double>() - r.before) < 1e-12);
    CHECK(std::abs(region["rms_after"].get<double>() - r.after) < 1e-12);
    CHECK(std::abs(std::abs(region["worst_after"]["value"].get<double>()) - r.worst_after) < 1e-12);
  }
}

}  // namespace

TEST_CASE("compensate expected: with gain 1 the residual inside a planted bump is the fit error") {
  const Measured& m = measured();
  const json record = compensate(m, "1");
  REQUIRE(record["clipped"].empty());  // the bump is far below --max-offset: no clip changes the oracle
  const json& expected = record["expected"];
  check_statistics(expected);
  std::size_t inside = 0;
  double worst_noise = 0, worst_fit = 0, before = 0, after = 0;
  for (const json& p : expected["points"]) {
    REQUIRE(m.nominal.count(p["id"].get<std::string>()) == 1);
    const double b = bump_at(m, m.nominal.at(p["id"].get<std::string>()));
    const double measured = p["measured"].get<double>(), field = p["field"].get<double>();
    const double residual = p["residual"].get<double>();
    REQUIRE(p["cut"] == true);  // the program covers the whole mould
    // Measured = bump + noise (CMM frame, no best fit): 4.5 sigma.
    CHECK(std::abs(measured - b) < 4.5 * kNoise);
    worst_noise = std::max(worst_noise, std::abs(measured - b));
    if (b < 0.5 * kHeight) continue;  // the core of the bump, where the fit is not fading
    ++inside;
    // The program's correction there is -field (to the nearest contact's
    // value, ~1 um): the residual is the bump minus the fitted field, plus
    // the point's noise and that discretisation.
    CHECK(std::abs(residual - (b - field)) < 4.5 * kNoise + 0.002);
    worst_fit = std::max(worst_fit, std::abs(b - field));
    before += measured * measured;
    after += residual * residual;
  }
  REQUIRE(inside >= 10);
  before = std::sqrt(before / double(inside));
  after = std::sqrt(after / double(inside));
  MESSAGE("inside the bump: " << inside << " points, RMS " << before * 1000 << " um before, " << after * 1000
                              << " um expected after; worst |bump - field| " << worst_fit * 1000
                              << " um, worst |measured - bump| " << worst_noise * 1000 << " um");
  // The fit error of a smooth 50 um bump sampled ~every 4 mm: 15 % of it.
  CHECK(worst_fit < 0.15 * kHeight);
  CHECK(after < 0.2 * before);
}

TEST_CASE("compensate expected: with gain 0.5 the residual inside a planted bump is half of it") {
  const Measured& m = measured();
  const json record = compensate(m, "0.5");
  const json& expected = record["expected"];
  check_statistics(expected);
  std::size_t inside = 0;
  for (const json& p : expected["points"]) {
    const double b = bump_at(m, m.nominal.at(p["id"].get<std::string>()));
    if (b < 0.5 * kHeight) continue;
    ++inside;
    // residual = b + noise - 0.5 (b + fit error): half the bump, to within
    // the noise, half the fit error (< 15 % of the height, as with gain 1)
    // and the nearest-contact discretisation.
    CHECK(std::abs(p["residual"].get<double>() - 0.5 * b) < 4.5 * kNoise + 0.5 * 0.15 * kHeight + 0.002);
  }
  REQUIRE(inside >= 10);
  const double before = expected["overall"]["rms_before"].get<double>();
  const double after = expected["overall"]["rms_after"].get<double>();
  CHECK(after > 0.35 * before);
  CHECK(after < 0.65 * before);
}

TEST_CASE("compensate predict-out: the prediction is furrow predict's of the written program, byte for byte") {
  const Measured& m = measured();
  const std::string out = m.dir + "/predicted.nc", pred = m.dir + "/predicted_prediction.json";
  const auto r = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", m.program, "--tool",
                             m.tool, "--out", out, "--predict-out", pred, "--cell", "2"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  REQUIRE(fs::exists(pred));
  // The oracle: the written file predicted by the prediction command, with
  // the same tool and options.
  const std::string again = m.dir + "/predicted_again.json";
  const auto p = run_furrow({"predict", m.part, "--toolpath", out, "--tool", m.tool, "--cell", "2", "--out", again});
  INFO(p.err);
  REQUIRE(p.status == 0);
  CHECK(slurp(pred) == slurp(again));
  // The uncompensated program: the compensated one moves tips by at most
  // largest_offset, so its scallops (ridges between passes) grow by at
  // most that.
  const std::string before = m.dir + "/uncompensated.json";
  REQUIRE(run_furrow({"predict", m.part, "--toolpath", m.program, "--tool", m.tool, "--cell", "2", "--out", before})
              .status == 0);
  const json a = json::parse(slurp(pred)), b = json::parse(slurp(before));
  const json record = json::parse(slurp(m.dir + "/predicted.json"));
  const double largest = record["largest_offset"].get<double>();
  REQUIRE(largest > 0.5 * kHeight);
  const double scallop = a["summary"]["max_scallop"].get<double>();
  const double scallop_before = b["summary"]["max_scallop"].get<double>();
  MESSAGE("worst scallop " << scallop * 1000 << " um compensated, " << scallop_before * 1000
                           << " um before, largest offset " << largest * 1000 << " um");
  CHECK(scallop <= scallop_before + largest + 1e-9);
  // The compensated program cuts the bump's height deeper than nominal
  // there: its predicted overcut reaches about -largest_offset.
  CHECK(a["summary"]["max_overcut"]["error"].get<double>() < -0.8 * largest);
}

TEST_CASE("compensate predict-out: a name that is not .json, or a prediction option without it, fails with status 2") {
  const Measured& m = measured();
  const std::string out = m.dir + "/refused.nc";
  const auto r = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", m.program, "--tool",
                             m.tool, "--out", out, "--predict-out", m.dir + "/refused.png"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--predict-out") != std::string::npos);
  CHECK(!fs::exists(out));
  const auto alone = run_furrow({"compensate", m.part, "--comparison", m.comparison, "--toolpath", m.program,
                                 "--tool", m.tool, "--out", out, "--resolution", "0.1"});
  CHECK(alone.status == 2);
  CHECK(alone.err.find("--resolution") != std::string::npos);
  CHECK(alone.err.find("--predict-out") != std::string::npos);
  CHECK(!fs::exists(out));
}
