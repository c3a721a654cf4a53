#pragma once
// The measured mould of the compensation tests: the mould's example program
// (a 6 mm ball, `furrow toolpath`) cut with a raised-cosine bump of material
// left at the middle of its face (u = v = 0.5; simulate-measurement --bump,
// 1 um noise, no blunders), measured at the points of a 600-point plan that
// lie within `kept` mm of the bump's centre, and compared in the CMM's frame
// with every point kept: the bump is the subject, not the registration (a
// best fit to points around one bump would take part of it off as a
// translation).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/numbers.hpp"
#include "io/part_file.hpp"
#include "io/machining/toolpath_file.hpp"
#include "support/run_cli.hpp"

namespace furrow::test {

struct MouldBump {
  std::string dir, part, tool, comparison;
  std::string program;  // a copy of the example program in `dir`: a test may write over it
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0, height = 0;                    // of the bump [mm]
  std::map<std::string, Eigen::Vector3d> nominal;  // the kept plan points by id
};

// The planted bump's height at `p` [mm]: the raised cosine
// simulate-measurement --bump plants (docs/formats.md), the tests' oracle.
inline double bump_at(const MouldBump& m, const Eigen::Vector3d& p) {
  const double rho = (p - m.centre).norm();
  return rho < m.radius ? m.height * (1 + std::cos(kPi * rho / m.radius)) / 2 : 0.0;
}

// Runs partition, plan, simulate-measurement and compare in a fresh scratch
// folder `name` (doctest REQUIREs each step).
inline MouldBump measured_mould_bump(const std::string& name, double radius, double height, double kept, int seed) {
  using nlohmann::json;
  MouldBump m;
  m.dir = scratch_dir(name);
  m.part = source_path("examples/parts/mould.json");
  m.program = m.dir + "/path.nc";
  std::filesystem::copy_file(source_path("examples/toolpaths/mould_ball6.nc"), m.program);
  m.tool = source_path("examples/tools/ball_d6.json");
  m.centre = read_part(m.part).faces[0].surface().point(0.5, 0.5);
  m.radius = radius;
  m.height = height;
  REQUIRE(run_furrow({"partition", m.part, "--out", m.dir + "/regions.json", "--grid", "40x40"}).status == 0);
  REQUIRE(run_furrow({"plan", m.part, "--regions", m.dir + "/regions.json", "--points", "600", "--out",
                      m.dir + "/plan"})
              .status == 0);
  json plan = json::parse(slurp(m.dir + "/plan/plan.json"));
  json near = json::array();
  for (const json& p : plan["points"]) {
    const Eigen::Vector3d at(p["xyz"][0].get<double>(), p["xyz"][1].get<double>(), p["xyz"][2].get<double>());
    if ((at - m.centre).norm() <= kept) {
      near.push_back(p);
      m.nominal[p["id"].get<std::string>()] = at;
    }
  }
  REQUIRE(near.size() >= 40);
  plan["points"] = near;
  write_text(m.dir + "/plan.json", plan.dump(1));
  char bump[160];
  std::snprintf(bump, sizeof bump, "%.6f,%.6f,%.6f,%g,%g", m.centre.x(), m.centre.y(), m.centre.z(), radius, height);
  const auto sim = run_furrow({"simulate-measurement", m.part, "--plan", m.dir + "/plan.json", "--bump", bump,
                               "--noise", "0.001", "--blunders", "0", "--seed", std::to_string(seed), "--misalign",
                               "0,0,0,0,0,0", "--out", m.dir + "/m.csv"});
  INFO(sim.err);
  REQUIRE(sim.status == 0);
  m.comparison = m.dir + "/comparison.json";
  const auto compare = run_furrow({"compare", m.part, "--measurements", m.dir + "/m.csv", "--plan",
                                   m.dir + "/plan.json", "--align", "cmm", "--no-outlier-rejection", "--out",
                                   m.comparison});
  INFO(compare.err);
  REQUIRE(std::filesystem::exists(m.comparison));
  return m;
}

// A tool path as APT CL data, point for point: the same tips (written with
// 4 decimals, as the example program, so read back to the same numbers),
// each pass reached by RAPID GOTOs over `safe` [mm].
inline std::string as_apt(const Toolpath& path, double safe) {
  std::string text = "PARTNO MOULD BALL6\nUNITS/MM\nCUTTER/6.0000,3.0000\nFEDRAT/MMPM,1000.0000\n";
  char line[128];
  auto go_to = [&](const Eigen::Vector3d& p) {
    std::snprintf(line, sizeof line, "GOTO/%.4f,%.4f,%.4f\n", p.x(), p.y(), p.z());
    text += line;
  };
  for (const ToolpathPass& pass : path.passes) {
    const Eigen::Vector3d start = pass.points.front().position;
    text += "RAPID\n";
    go_to({start.x(), start.y(), safe});
    text += "RAPID\n";
    go_to(start);
    for (std::size_t i = 1; i < pass.points.size(); ++i) go_to(pass.points[i].position);
  }
  return text + "FINI\n";
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace furrow::test
