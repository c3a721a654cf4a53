// `furrow compensate --rework` through the commands: the mould's example
// program (6 mm ball), measured near a planted bump of +80 um of material
// left (radius 15 mm, a raised cosine), compared, and a rework program
// asked for. Oracles: the planted bump (its radius bounds where the rework
// may cut; its height, sampled along the original moves by brute force,
// says which of them must be re-cut; a z-map of the original cut and the
// rework cut, both on a machine that leaves the bump, gives the part after
// rework), the original program's clearance (its highest rapid, read from
// the file) and the G-code rework for the APT one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/numbers.hpp"
#include "io/machining/apt_reader.hpp"
#include "io/machining/gcode_reader.hpp"
#include "io/part_file.hpp"
#include "machining/cutter/cutter.hpp"
#include "machining/prediction/zmap.hpp"
#include "mould_bump_fixture.hpp"
#include "support/run_cli.hpp"

using namespace furrow;
using furrow::test::run_furrow;
using furrow::test::slurp;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double kRadius = 15;     // [mm] of the bump
constexpr double kHeight = 0.08;   // [mm], material left
constexpr double kKept = 30;       // [mm] plan points kept within this of the centre
constexpr double kBall = 3;        // [mm] the example tool's radius

using Setup = test::MouldBump;
using test::as_apt;
using test::lines_of;

using test::bump_at;

const Setup& setup() {
  static const Setup made = test::measured_mould_bump("cli-rework", kRadius, kHeight, kKept, 5);
  return made;
}


double highest_rapid(const Toolpath& path) {
  double z = -1e300;
  for (const RapidMove& r : path.rapids)
    if (r.known) z = std::max({z, r.from.z(), r.to.z()});
  return z;
}

double segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}


}  // namespace

TEST_CASE("compensate --rework: re-cuts only the planted bump, covers it, and leaves the part within tolerance") {
  const Setup& l = setup();
  const std::string out = l.dir + "/rework.nc";
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program, "--tool",
                             l.tool, "--out", out, "--rework"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const json record = json::parse(slurp(l.dir + "/rework.json"));
  const json comparison = json::parse(slurp(l.comparison));
  const double threshold = comparison["tolerance"]["upper"].get<double>();
  REQUIRE(record.contains("rework"));
  const json& rw = record["rework"];
  CHECK(rw["threshold"].get<double>() == threshold);
  CHECK(rw["threshold_from"] == "comparison tolerance");
  CHECK(rw["check"]["safe"] == true);
  CHECK(rw["regions"].size() == 1);

  const Toolpath original = parse_gcode(slurp(l.program), "path.nc");
  const std::string text = slurp(out);
  const Toolpath rework = parse_gcode(text, "rework.nc");
  const double clearance = highest_rapid(original);
  CHECK(rw["clearance"].get<double>() == clearance);
  REQUIRE(!rework.passes.empty());
  CHECK(rework.passes.size() == rw["stretches"].size());

  // The header and the end of the original are kept.
  CHECK(text.rfind("%\n(furrow toolpath mould.json", 0) == 0);
  CHECK(text.find("G21 G90 G17\n") != std::string::npos);
  CHECK(text.size() >= 5);
  CHECK(text.substr(text.size() - 6) == "M30\n%\n");

  // Rapids: every G0 line of the text goes to the clearance height (the
  // first, from wherever the machine is, too); every known one that moves
  // sideways starts there as well (a retract starts at a cut).
  char z_word[32];
  std::snprintf(z_word, sizeof z_word, " Z%.4f", clearance);
  std::size_t g0_lines = 0;
  for (const std::string& line : lines_of(text))
    if (line.rfind("G0", 0) == 0) {
      ++g0_lines;
      CHECK(line.size() >= std::string(z_word).size());
      CHECK(line.substr(line.size() - std::string(z_word).size()) == z_word);
    }
  CHECK(g0_lines == rework.rapids.size());
  for (const RapidMove& m : rework.rapids)
    if (m.known) {
      CHECK(m.to.z() == clearance);
      if ((m.to - m.from).head<2>().norm() > 0) CHECK(m.from.z() == clearance);
    }
  CHECK(rework.rapids.size() >= 2 * rework.passes.size());

  // Within the footprint: every tip cut lies within the bump radius of its
  // centre in xy (the contact is within a ball radius of the tip; material
  // is left only inside the radius, and the threshold keeps the rework well
  // inside it).
  double farthest = 0;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> cuts;
  for (const ToolpathPass& p : rework.passes) {
    // Each pass: its start at the clearance, the plunge, the stretch.
    CHECK(p.points.front().position.z() == clearance);
    for (std::size_t k = 1; k < p.points.size(); ++k) {
      farthest = std::max(farthest, (p.points[k].position - l.centre).head<2>().norm());
      CHECK(p.points[k].feed == 1000);
      if (k >= 2) cuts.emplace_back(p.points[k - 1].position, p.points[k].position);
    }
  }
  CHECK(farthest < kRadius);

  // Covered, by brute force: every point every 0.25 mm along the original's
  // cutting moves where the bump leaves more than the threshold plus a
  // margin (the tip is up to ~1 mm from its contact on the mould's slopes,
  // where the bump changes by up to 8.4 um/mm, and the fitted field's
  // error) is re-cut: a rework move passes within 0.1 mm of it (the
  // compensation moves it by at most 80 um).
  std::size_t must = 0, covered = 0;
  for (const ToolpathPass& p : original.passes)
    for (std::size_t k = 1; k < p.points.size(); ++k) {
      const Eigen::Vector3d a = p.points[k - 1].position, b = p.points[k].position;
      const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.25)));
      for (int i = 0; i <= n; ++i) {
        const Eigen::Vector3d q = a + (b - a) * (static_cast<double>(i) / n);
        if (bump_at(l, q) <= threshold + 0.02) continue;
        ++must;
        double nearest = 1e300;
        for (const auto& [c0, c1] : cuts) nearest = std::min(nearest, segment_distance(q, c0, c1));
        covered += nearest < 0.1;
      }
    }
  MESSAGE("rework: " << rework.passes.size() << " stretches, farthest tip " << farthest << " mm from the centre; "
                     << covered << " of " << must << " points over the bump covered");
  CHECK(must > 100);
  CHECK(covered == must);

  // The part after rework: both cuts on a machine that leaves the bump
  // (along the normal; vertically bump / n_z). Inside the bump it is within
  // the tolerance's upper limit; outside, the rework cuts nowhere deeper
  // than the original did.
  const Cutter ball("ball", kBall, kBall);
  const double cell = 0.05;
  const Eigen::AlignedBox2d box(l.centre.head<2>().array() - (kRadius + 5), l.centre.head<2>().array() + (kRadius + 5));
  ZMap first(box, cell), second(box, cell);
  first.cut(ball, moves_from_toolpath(original));
  second.cut(ball, moves_from_toolpath(rework));
  double worst_inside = 0, worst_outside = 0, sum2 = 0;
  std::size_t inside = 0, outside = 0, high = 0;
  for (int j = 1; j + 1 < first.ny(); ++j)
    for (int i = 1; i + 1 < first.nx(); ++i) {
      const double h0 = first.node_height(i, j);
      const double xm = first.node_height(i - 1, j), xp = first.node_height(i + 1, j);
      const double ym = first.node_height(i, j - 1), yp = first.node_height(i, j + 1);
      if (!std::isfinite(h0) || !std::isfinite(xm + xp + ym + yp)) continue;
      const double sx = (xp - xm) / (2 * cell), sy = (yp - ym) / (2 * cell);
      const double nz = 1 / std::sqrt(1 + sx * sx + sy * sy);
      const Eigen::Vector3d at(first.x(i), first.y(j), h0);
      const double e = bump_at(l, at);
      const double h1 = second.node_height(i, j);
      if (e == 0) {
        ++outside;
        if (std::isfinite(h1)) worst_outside = std::max(worst_outside, h0 - h1);
        continue;
      }
      if (nz < 0.5) continue;
      ++inside;
      const double after = std::min(h0, std::isfinite(h1) ? h1 : h0) + e / nz;  // height of the part made
      const double left = (after - h0) * nz;                                  // along the normal
      worst_inside = std::max(worst_inside, left);
      if (e > threshold + 0.02) ++high, sum2 += left * left;
    }
  const double rms_high = high ? std::sqrt(sum2 / high) : 0;
  MESSAGE("after rework: worst material left inside the bump " << worst_inside * 1000 << " um over " << inside
                                                               << " nodes, RMS " << rms_high * 1000 << " um over "
                                                               << high << " nodes where it left > "
                                                               << (threshold + 0.02) * 1000
                                                               << " um; deepest extra cut outside "
                                                               << worst_outside * 1000 << " um");
  CHECK(inside > 10000);
  CHECK(outside > 1000);
  CHECK(worst_inside <= threshold + 1e-3);
  CHECK(rms_high < 0.01);
  // The written rounding of a 4-decimal program (sqrt 3 half units) and 1 um.
  CHECK(worst_outside <= 1e-3 + std::sqrt(3.0) * 0.5e-4);
}

TEST_CASE("compensate --rework: with nothing beyond the threshold, nothing is written and the status is 0") {
  const Setup& l = setup();
  const std::string out = l.dir + "/none.nc";
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program, "--tool",
                             l.tool, "--out", out, "--rework", "--rework-threshold", "0.1"});
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("no rework needed") != std::string::npos);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(l.dir + "/none.json"));
}

TEST_CASE("compensate --rework: an APT CL file gives the G-code rework's moves, as APT") {
  const Setup& l = setup();
  const Toolpath gcode = parse_gcode(slurp(l.program), "path.nc");
  const double clearance = highest_rapid(gcode);
  const std::string apt_path = l.dir + "/path.apt";
  test::write_text(apt_path, as_apt(gcode, clearance));
  const std::string out = l.dir + "/rework_apt.apt", out_nc = l.dir + "/rework_g.nc";
  const auto a = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", apt_path, "--tool",
                             l.tool, "--out", out, "--rework"});
  INFO(a.out << a.err);
  REQUIRE(a.status == 0);
  const auto g = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program, "--tool",
                             l.tool, "--out", out_nc, "--rework"});
  REQUIRE(g.status == 0);
  const std::string text = slurp(out);
  CHECK(text.rfind("PARTNO MOULD BALL6\nUNITS/MM\nCUTTER/6.0000,3.0000\nFEDRAT/MMPM,1000.0000\n", 0) == 0);
  CHECK(text.substr(text.size() - 5) == "FINI\n");
  CHECK(text.find("RAPID\nRAPID") == std::string::npos);
  const Toolpath by_apt = parse_apt(text, "rework.apt");
  const Toolpath by_gcode = parse_gcode(slurp(out_nc), "rework.nc");
  REQUIRE(!by_apt.passes.empty());
  REQUIRE(by_apt.passes.size() == by_gcode.passes.size());
  CHECK(by_apt.rapids.size() + 1 == by_gcode.rapids.size());  // G-code's first rise, G0 Z alone
  double worst = 0;
  for (std::size_t p = 0; p < by_apt.passes.size(); ++p) {
    REQUIRE(by_apt.passes[p].points.size() == by_gcode.passes[p].points.size());
    for (std::size_t k = 0; k < by_apt.passes[p].points.size(); ++k) {
      worst = std::max(worst,
                       (by_apt.passes[p].points[k].position - by_gcode.passes[p].points[k].position).cwiseAbs().maxCoeff());
      if (k > 0) CHECK(by_apt.passes[p].points[k].feed == by_gcode.passes[p].points[k].feed);
    }
  }
  CHECK(worst == 0);
  // Every RAPID's GOTO/ goes to the clearance height.
  const std::vector<std::string> lines = lines_of(text);
  char z_value[32];
  std::snprintf(z_value, sizeof z_value, ",%.4f", clearance);
  std::size_t rapid_lines = 0;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i)
    if (lines[i] == "RAPID") {
      ++rapid_lines;
      CHECK(lines[i + 1].rfind("GOTO/", 0) == 0);
      CHECK(lines[i + 1].substr(lines[i + 1].size() - std::string(z_value).size()) == z_value);
    }
  CHECK(rapid_lines == by_apt.rapids.size());
}

TEST_CASE("compensate --rework: a bad threshold, or one without --rework, fails with status 2 and writes nothing") {
  const Setup& l = setup();
  const std::string out = l.dir + "/bad.nc";
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--rework", "--rework-threshold", "-0.01"},
        std::vector<std::string>{"--rework", "--rework-threshold", "abc"},
        std::vector<std::string>{"--rework-threshold", "0.01"}}) {
    std::vector<std::string> args = {"compensate", l.part,  "--comparison", l.comparison, "--toolpath",
                                     l.program,    "--tool", l.tool,        "--out",        out};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_furrow(args);
    INFO(extra.back() << ": " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find("--rework-threshold") != std::string::npos);
  }
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(l.dir + "/bad.json"));
}

TEST_CASE("compensate --rework: a program in inches is refused with status 2, as the rework writes millimetres") {
  const Setup& l = setup();
  // The example program in inches (G20, every coordinate / 25.4 with 5
  // decimals): the full compensation reads it, the rework written in mm
  // after its G20 header would not be where it was written.
  std::string inch;
  for (const std::string& line : lines_of(slurp(l.program))) {
    if (line == "G21 G90 G17") {
      inch += "G20 G90 G17\n";
      continue;
    }
    std::string out;
    for (std::size_t i = 0; i < line.size();) {
      const char c = line[i];
      if ((c == 'X' || c == 'Y' || c == 'Z') && i + 1 < line.size() && line[0] == 'G') {
        std::size_t end = i + 1;
        while (end < line.size() && line[end] != ' ') ++end;
        char value[32];
        std::snprintf(value, sizeof value, "%.5f", std::stod(line.substr(i + 1, end - i - 1)) / 25.4);
        out += c;
        out += value;
        i = end;
      } else {
        out += c;
        ++i;
      }
    }
    inch += out + "\n";
  }
  const std::string program = l.dir + "/inch.nc", out = l.dir + "/inch_rework.nc";
  test::write_text(program, inch);
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", program, "--tool",
                             l.tool, "--out", out, "--rework"});
  INFO(r.out << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.find("units") != std::string::npos);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(l.dir + "/inch_rework.json"));
}

TEST_CASE("compensate --rework: a program whose rapids stay below the part fails the rework check, exit 3, nothing written") {
  // The example program with every retract lowered to 24 mm, just above
  // the highest pass start: a programmer's "safe" plane that the mould
  // rises through inside the bump (its tips there reach about 27 mm). The
  // full compensated program only moves the cutting tips and passes its
  // own check; the rework must go up to the program's highest rapid
  // between stretches, and at 24 mm its moves to and from each stretch
  // run through the part.
  const Setup& l = setup();
  const std::string low = l.dir + "/low_rapids.nc";
  std::string text = slurp(l.program);
  std::size_t replaced = 0;
  for (std::size_t at = text.find("Z34.6326"); at != std::string::npos; at = text.find("Z34.6326", at), ++replaced)
    text.replace(at, 8, "Z24.0000");
  REQUIRE(replaced > 100);
  test::write_text(low, text);
  const Toolpath path = parse_gcode(text, "low_rapids.nc");
  const double clearance = highest_rapid(path);
  REQUIRE(std::abs(clearance - 24.0) < 1e-9);
  // The set-up's oracle: original tips inside the bump stand well above the
  // clearance, so any move at the clearance there cuts the part.
  double highest_in_bump = -1e300;
  for (const ToolpathPass& pass : path.passes)
    for (const ToolpathPoint& p : pass.points)
      if ((p.position.head<2>() - l.centre.head<2>()).norm() < kRadius)
        highest_in_bump = std::max(highest_in_bump, p.position.z());
  REQUIRE(highest_in_bump > clearance + 1.0);

  const std::string out = l.dir + "/low_rework.nc", predicted = l.dir + "/low_rework_prediction.json";
  const auto r = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", low, "--tool", l.tool,
                             "--out", out, "--rework", "--predict-out", predicted});
  INFO(r.out << r.err);
  CHECK(r.status == 3);
  CHECK(r.err.find("nothing written") != std::string::npos);
  CHECK(r.err.find("rework program") != std::string::npos);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(l.dir + "/low_rework.json"));
  CHECK(!fs::exists(predicted));
  // The place named: the compensated program's surface there (the
  // rework's height plus the depth) stands above the clearance - the
  // reason for the failure - and below the highest tip of the program
  // plus a cutter radius, which bounds every height a ball leaves.
  double depth = 0, x = 0, y = 0, z = 0;
  const std::size_t at = r.err.find(" would cut ");
  REQUIRE(at != std::string::npos);
  REQUIRE(std::sscanf(r.err.c_str() + at, " would cut %lf mm", &depth) == 1);
  const std::size_t open = r.err.find('(', at);
  REQUIRE(open != std::string::npos);
  REQUIRE(std::sscanf(r.err.c_str() + open, "(%lf, %lf, %lf)", &x, &y, &z) == 3);
  double highest = -1e300;
  for (const ToolpathPass& pass : path.passes)
    for (const ToolpathPoint& p : pass.points) highest = std::max(highest, p.position.z());
  MESSAGE("rework check: " << depth << " mm at (" << x << ", " << y << ", " << z << "), tips in the bump up to "
                           << highest_in_bump << " mm, clearance " << clearance << " mm");
  CHECK(depth > 0.5);
  CHECK(depth + z > clearance);
  CHECK(depth + z < highest + kBall);
  CHECK((Eigen::Vector2d(x, y) - l.centre.head<2>()).norm() < kRadius + kBall);

  // The control: the program as it was, rapids at 34.6 mm, is written.
  const auto control = run_furrow({"compensate", l.part, "--comparison", l.comparison, "--toolpath", l.program,
                                   "--tool", l.tool, "--out", l.dir + "/control_rework.nc", "--rework"});
  INFO(control.err);
  CHECK(control.status == 0);
  CHECK(fs::exists(l.dir + "/control_rework.nc"));
}

TEST_CASE("compensate --rework: a rework rapid over the part between two bumps fails the check, exit 3, nothing written") {
  // Two bumps of material left in the mould's low ground on either side of
  // its dome (x 5 and x 70 mm, the dome's top at x 20-40 mm, 29.6 mm high),
  // and the program's retracts lowered to 24 mm: the rework's stretches
  // start and end below that clearance (their plunges come down through
  // air), but its rapids from one bump to the other cross the dome.
  // Oracle for the depth named: the original program's cut, a z-map of
  // this test's, at the point named (the compensated program leaves the
  // dome as the original does: no measured point is near it).
  const std::string dir = test::scratch_dir("cli-rework-rapid");
  const std::string part = test::source_path("examples/parts/mould.json");
  const std::string tool = test::source_path("examples/tools/ball_d6.json");
  REQUIRE(run_furrow({"partition", part, "--out", dir + "/regions.json", "--grid", "40x40"}).status == 0);
  REQUIRE(run_furrow({"plan", part, "--regions", dir + "/regions.json", "--points", "600", "--out", dir + "/plan"})
              .status == 0);
  json plan = json::parse(slurp(dir + "/plan/plan.json"));
  // Each bump centred on the plan point nearest to where it is wanted (a
  // point of the surface), radius 8 and 5 mm.
  const std::vector<std::pair<Eigen::Vector2d, double>> wanted = {{{72, 35}, 8.0}, {{4, 35}, 5.0}};
  std::vector<Eigen::Vector3d> centres;
  json kept = json::array();
  for (const auto& [at, radius] : wanted) {
    Eigen::Vector3d best(1e300, 1e300, 0);
    for (const json& p : plan["points"]) {
      const Eigen::Vector3d q(p["xyz"][0].get<double>(), p["xyz"][1].get<double>(), p["xyz"][2].get<double>());
      if ((q.head<2>() - at).norm() < (best.head<2>() - at).norm()) best = q;
    }
    centres.push_back(best);
  }
  for (const json& p : plan["points"]) {
    const Eigen::Vector3d q(p["xyz"][0].get<double>(), p["xyz"][1].get<double>(), p["xyz"][2].get<double>());
    if ((q - centres[0]).norm() < 12 || (q - centres[1]).norm() < 8) kept.push_back(p);
  }
  REQUIRE(kept.size() >= 30);
  plan["points"] = kept;
  test::write_text(dir + "/plan.json", plan.dump(1));
  std::vector<std::string> sim = {"simulate-measurement", part, "--plan", dir + "/plan.json", "--noise", "0.001",
                                  "--blunders", "0", "--seed", "3", "--misalign", "0,0,0,0,0,0", "--out",
                                  dir + "/m.csv"};
  for (std::size_t k = 0; k < 2; ++k) {
    char bump[160];
    std::snprintf(bump, sizeof bump, "%.6f,%.6f,%.6f,%g,0.08", centres[k].x(), centres[k].y(), centres[k].z(),
                  wanted[k].second);
    sim.insert(sim.end(), {"--bump", bump});
  }
  REQUIRE(run_furrow(sim).status == 0);
  const std::string comparison = dir + "/comparison.json";
  run_furrow({"compare", part, "--measurements", dir + "/m.csv", "--plan", dir + "/plan.json", "--align", "cmm",
              "--no-outlier-rejection", "--out", comparison});
  REQUIRE(fs::exists(comparison));

  std::string text = slurp(test::source_path("examples/toolpaths/mould_ball6.nc"));
  for (std::size_t at = text.find("Z34.6326"); at != std::string::npos; at = text.find("Z34.6326", at))
    text.replace(at, 8, "Z24.0000");
  test::write_text(dir + "/low.nc", text);
  const Toolpath low = parse_gcode(text, "low.nc");
  const double clearance = highest_rapid(low);
  REQUIRE(std::abs(clearance - 24.0) < 1e-9);

  const std::string out = dir + "/rework.nc";
  const auto r = run_furrow({"compensate", part, "--comparison", comparison, "--toolpath", dir + "/low.nc", "--tool",
                             tool, "--out", out, "--rework"});
  INFO(r.out << r.err);
  CHECK(r.status == 3);
  CHECK(r.err.find("nothing written: a rapid of the rework program (line ") != std::string::npos);
  CHECK(!fs::exists(out));
  CHECK(!fs::exists(dir + "/rework.json"));
  const std::size_t at = r.err.find(" would cut ");
  REQUIRE(at != std::string::npos);
  double depth = 0, x = 0, y = 0, z = 0;
  REQUIRE(std::sscanf(r.err.c_str() + at, " would cut %lf mm into the part at (%lf, %lf, %lf)", &depth, &x, &y, &z) ==
          4);
  const Cutter ball("ball", kBall, kBall);
  ZMap cut(Eigen::AlignedBox2d(Eigen::Vector2d(x - 5, y - 5), Eigen::Vector2d(x + 5, y + 5)), 0.1);
  cut.cut(ball, moves_from_toolpath(low));
  const double machined = cut.height_at(x, y);
  MESSAGE("rework rapid: " << depth << " mm into the part at (" << x << ", " << y << ", " << z
                           << "); the original's cut there " << machined << " mm");
  CHECK(x > centres[1].x() + wanted[1].second);  // between the bumps: over the dome
  CHECK(x < centres[0].x() - wanted[0].second);
  CHECK(z >= clearance - 1e-3);                   // the rapid's ball, at the clearance
  CHECK(depth > 1.0);
  // The depth is reported beyond the check's tolerance: 1 um and the
  // rounding of both programs (4 decimals, sqrt(3) half units each;
  // docs/compensation.md "Rework"). The rest is the rounding of the
  // printed place (half a micrometre in z, and in x, y times the dome's slope).
  const double tolerance = 1e-3 + std::sqrt(3.0) * (0.5e-4 + 0.5e-4);
  CHECK(std::abs(z + depth + tolerance - machined) < 0.001);  // the part as the original cut it

  // The control: with its rapids as they were, the same rework is written.
  const auto control = run_furrow({"compensate", part, "--comparison", comparison, "--toolpath",
                                   test::source_path("examples/toolpaths/mould_ball6.nc"), "--tool", tool, "--out",
                                   dir + "/control.nc", "--rework"});
  INFO(control.out << control.err);
  CHECK(control.status == 0);
  CHECK(control.out.find("in 2 regions") != std::string::npos);
}
