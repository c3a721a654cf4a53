// A scan of a part built with OpenCASCADE, end to end through both
// commands a user runs: the block (with filleted top edges) written as STEP,
// `furrow simulate-measurement --scan` of it turned 180 degrees into the
// scanner's frame with a planted dent, noise and spray, then `furrow compare
// --scan`. Oracle: the dent's analytic raised cosine at each compared
// point's registered position, and the noise level away from it.
#include <doctest/doctest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <cmath>
#include <string>

#include "base/numbers.hpp"
#include "inspection/scan_simulation.hpp"
#include "io/cad/cad_import.hpp"
#include "io/cad/cad_reference.hpp"
#include "io/scan/scan_preprocess.hpp"
#include "support/deviation_cloud.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

namespace {

// 60 x 40 x 20 mm, its four top edges filleted with 5 mm.
TopoDS_Shape filleted_block() {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(60, 40, 20)).Shape();
  BRepFilletAPI_MakeFillet fillet(block);
  for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    const BRepAdaptor_Curve c(edge);
    const gp_Pnt a = c.Value(c.FirstParameter()), b = c.Value(c.LastParameter());
    if (std::abs(a.Z() - 20) < 1e-9 && std::abs(b.Z() - 20) < 1e-9) fillet.Add(5.0, edge);
  }
  return fillet.Shape();
}

const Eigen::Vector3d kDentCentre(30, 20, 20);
constexpr double kDentRadius = 8, kDentDepth = 0.05, kNoise = 0.005;

double dent_at(const Eigen::Vector3d& p) {
  const double rho = (p - kDentCentre).norm();
  return rho < kDentRadius ? -kDentDepth * (1 + std::cos(kPi * rho / kDentRadius)) / 2 : 0.0;
}

}  // namespace

TEST_CASE("scan of an OpenCASCADE block turned 180 degrees: the dent read to the noise level through both commands") {
  const std::string dir = test::scratch_dir("scan-occt-block");
  const std::string step = dir + "/block.step";
  test::write_step(filleted_block(), step);
  const std::string scan = dir + "/scan.ply";
  const auto sim = test::run_furrow(
      {"simulate-measurement", step, "--scan", "--out", scan, "--view", "0.6,0.5,-1", "--stripe-pitch", "0.4",
       "--point-pitch", "0.4", "--scan-noise", "0.005", "--spray", "0.005", "--misalign", "20,-10,180,150,80,-40",
       "--seed", "11", "--bump", "30,20,20,8,-0.05"});
  INFO(sim.out << sim.err);
  REQUIRE(sim.status == 0);
  const std::size_t points = std::stoul(sim.out);
  const std::size_t planted_spray = std::stoul(sim.out.substr(sim.out.find('(') + 1));
  REQUIRE(points > 10000);
  REQUIRE(planted_spray == static_cast<std::size_t>(std::llround(0.005 * points)));

  const auto r = test::run_furrow({"compare", step, "--scan", scan, "--out", dir + "/c.json", "--deviations",
                                   dir + "/d.ply", "--tolerance", "0.05"});
  INFO(r.out << r.err);
  CHECK(r.status == 1);  // the 50 um dent leaves the +-25 um zone
  const std::vector<test::DeviationPoint> cloud = test::parse_deviation_ply(test::slurp(dir + "/d.ply"));
  REQUIRE(cloud.size() == points);
  std::size_t flagged = 0, floor_points = 0, far_points = 0;
  double floor_error = 0, far_sq = 0, worst_far = 0;
  for (const test::DeviationPoint& p : cloud) {
    if (p.outlier == 1 || p.outlier == 2) ++flagged;
    if (p.outlier != 0) continue;
    const double rho = (p.xyz - kDentCentre).norm();
    if (rho < 2) {
      ++floor_points;
      floor_error += p.deviation - dent_at(p.xyz);
    } else if (rho > kDentRadius + 1) {
      ++far_points;
      far_sq += double(p.deviation) * p.deviation;
      worst_far = std::max(worst_far, std::abs(double(p.deviation)));
    }
  }
  const double far_rms = std::sqrt(far_sq / static_cast<double>(far_points));
  MESSAGE(points << " points, " << planted_spray << " spray planted, " << flagged << " flagged; dent floor "
                 << floor_points << " points, mean error " << 1e3 * floor_error / floor_points << " um; away from it rms "
                 << 1e3 * far_rms << " um, worst " << 1e3 * worst_far << " um");
  // Every planted spray point is flagged, and few good ones (docs/scan.md).
  CHECK(flagged >= planted_spray);
  CHECK(flagged <= planted_spray + points / 100);
  // The dent's floor reads its depth to the noise's standard error (plus
  // 1 um for the registration).
  REQUIRE(floor_points > 30);
  CHECK(std::abs(floor_error / floor_points) < 3 * kNoise / std::sqrt(double(floor_points)) + 0.001);
  // Away from the dent the deviations are the noise's share along the
  // normal: below its sigma, above a fifth of it (the faces are seen at
  // 38-67 degrees), and none beyond 5 sigma.
  CHECK(far_rms < kNoise);
  CHECK(far_rms > kNoise / 5);
  CHECK(worst_far < 5 * kNoise);
}

TEST_CASE("scan spray on a block with sharp edges and fillets: every planted point flagged, few good ones") {
  // The spray rules against the simulation's own record of which points it
  // threw off: a machined part's sharp edges, fillets and the scan's
  // borders are where a neighbourhood rule is tempted to flag good points.
  const std::string dir = test::scratch_dir("scan-occt-spray");
  test::write_step(filleted_block(), dir + "/block.step");
  const Part part = import_cad(dir + "/block.step").part;
  ScannerModel m;
  m.view = {0.6, 0.5, -1};
  m.stripe_pitch = m.point_pitch = 0.4;
  m.spray_share = 0.005;
  m.seed = 5;
  const SimulatedScan sim = simulate_scan(part, m);
  ScanCloud cloud;
  cloud.file = "simulated";
  cloud.points = sim.points;
  cloud.read = sim.points.size();
  const ScanPreprocessed pre = preprocess_scan(cloud, ScanPreprocessOptions{});
  std::size_t planted = 0, caught = 0, good_flagged = 0;
  for (std::size_t k = 0; k < sim.points.size(); ++k) {
    planted += sim.spray[k];
    if (sim.spray[k]) caught += pre.spray[k] != 0;
    else good_flagged += pre.spray[k] != 0;
  }
  MESSAGE(sim.points.size() << " points: " << caught << " of " << planted << " spray flagged, " << good_flagged
                            << " good points flagged (far " << pre.spray_far << ", near " << pre.spray_near << ")");
  REQUIRE(planted > 50);
  CHECK(caught == planted);
  CHECK(good_flagged < sim.points.size() / 100);  // docs/scan.md: at most 1 % of good points
}
