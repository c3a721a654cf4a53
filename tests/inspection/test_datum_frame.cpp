// Datum frames (furrow compare --align cmm|datums): the 3-2-1 frame from
// measured datum points, deviations at a fixed transform, and the best-fit
// profile beside the frame's. Oracles: the simulated placement and surface
// offsets put into the data (analytic), a brute-force search over plane
// normals for the least-squares plane, and residuals recomputed here.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>

#include <Eigen/SVD>

#include "base/error.hpp"
#include "geometry/closest_point.hpp"
#include "geometry/primitives.hpp"
#include "inspection/comparison.hpp"
#include "inspection/datum_frame.hpp"
#include "inspection/comparison_file.hpp"
#include "inspection/measurement_simulation.hpp"
#include "io/cmm/measurement_csv.hpp"
#include "io/part_file.hpp"
#include "io/plan_file.hpp"
#include "stage/compare_stage.hpp"
#include "datum_fixture.hpp"
#include "support/run_cli.hpp"

using namespace furrow;

using namespace furrow::test;

TEST_CASE("datum frame: least-squares plane beats every nearby normal, flatness is its residual spread") {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.003);
  std::uniform_real_distribution<double> at(-40, 40);
  const Eigen::Vector3d n0 = Eigen::Vector3d(0.1, -0.2, 1).normalized();
  const Eigen::Vector3d e1 = n0.unitOrthogonal(), e2 = n0.cross(e1);
  std::vector<Eigen::Vector3d> pts;
  for (int k = 0; k < 12; ++k) pts.push_back(Eigen::Vector3d(5, 6, 7) + at(rng) * e1 + at(rng) * e2 + noise(rng) * n0);
  const PlaneFit fit = fit_plane(pts, n0, "test");
  CHECK(fit.normal.dot(n0) > 0.999);
  auto ssr = [&](const Eigen::Vector3d& n) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& p : pts) c += p;
    c /= static_cast<double>(pts.size());
    double s = 0;
    for (const auto& p : pts) s += std::pow((p - c).dot(n), 2);
    return s;
  };
  // Brute force: no normal on a fine grid around the fit does better.
  const double best = ssr(fit.normal);
  const Eigen::Vector3d f1 = fit.normal.unitOrthogonal(), f2 = fit.normal.cross(f1);
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j) {
      const Eigen::Vector3d n = (fit.normal + 1e-4 * i * f1 + 1e-4 * j * f2).normalized();
      CHECK(ssr(n) >= best - 1e-12);
    }
  double lo = 1e9, hi = -1e9;
  for (const auto& p : pts) {
    lo = std::min(lo, (p - fit.centroid).dot(fit.normal));
    hi = std::max(hi, (p - fit.centroid).dot(fit.normal));
  }
  CHECK(fit.flatness == doctest::Approx(hi - lo).epsilon(1e-12));
  CHECK(fit.flatness > 0);
  // Collinear points fix no plane.
  CHECK_THROWS_AS(fit_plane({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}}, n0, "line"), DatumFrameError);
}

TEST_CASE("datums: a known placement is recovered and the deviations are the surface offsets") {
  const Part part = datum_part();
  const InspectionPlan plan = datum_plan(part);
  const Eigen::Isometry3d m = placement();
  const MeasurementSet measured = measure(plan, m, 1.0, [](const PlannedPoint& p) {
    return p.face == "F" ? form(p) : 0.0;
  });
  MeasurementSet compared;
  const Comparison c = run(part, plan, measured, AlignMethod::datums, &compared);
  REQUIRE(c.datum_frame);
  // The transform CMM -> part is the placement's inverse.
  const Eigen::Matrix4d e = (c.datum_frame->transform * m).matrix() - Eigen::Matrix4d::Identity();
  CHECK(e.cwiseAbs().maxCoeff() < 1e-9);
  CHECK(c.datum_frame->datums[0].form_error < 1e-9);
  CHECK(c.datum_frame->datums[1].form_error < 1e-9);
  // Only the free-form points are compared, each at its planted offset.
  REQUIRE(compared.points.size() == plan.points.size());
  REQUIRE(c.registration.points.size() == plan.points.size());
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    CHECK(c.registration.points[i].evaluated);
    CHECK(std::abs(c.registration.points[i].deviation - (form(plan.points[i]))) < 1e-6);
  }
  CHECK(c.summary.alignment == "ok");
  REQUIRE(c.bestfit_profile);
  double worst = 0;
  for (const PlannedPoint& p : plan.points) worst = std::max(worst, std::abs(form(p)));
  CHECK(c.summary.profile == doctest::Approx(2 * worst).epsilon(1e-4).scale(0));
  // The best fit may absorb a little of the form; it cannot exceed it by much.
  CHECK(*c.bestfit_profile <= 2 * worst + 1e-3);
}

TEST_CASE("datums: flatness and straightness of noisy datum points are their residual spreads") {
  const Part part = datum_part();
  const InspectionPlan plan = datum_plan(part);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.004);
  std::map<std::string, double> planted;
  const MeasurementSet measured = measure(plan, placement(), 1.0, [&](const PlannedPoint& p) {
    return planted[p.id] = noise(rng);
  });
  const Comparison c = run(part, plan, measured, AlignMethod::datums);
  REQUIRE(c.datum_frame);
  // Oracle for A: the plane fitted here by SVD of the centred contact
  // points, in the part frame (the placement does not change residuals).
  const DatumFeature& a = plan.alignment->datums[0];
  Eigen::MatrixXd pts(a.points.size(), 3);
  for (std::size_t k = 0; k < a.points.size(); ++k)
    pts.row(k) = (a.points[k].xyz + planted[a.points[k].id] * a.normal).transpose();
  const Eigen::RowVector3d centre = pts.colwise().mean();
  const Eigen::MatrixXd centred = pts.rowwise() - centre;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeFullV);
  const Eigen::VectorXd r = centred * svd.matrixV().col(2);
  CHECK(c.datum_frame->datums[0].form_error == doctest::Approx(r.maxCoeff() - r.minCoeff()).epsilon(1e-6));
  // B has two points: a line through both, straightness zero.
  CHECK(c.datum_frame->datums[1].form_error < 1e-9);

  // Three B points at one height: the straightness is the spread of their
  // residuals across the least-squares line through (x, y) of the contact
  // points, fitted here by SVD (A's tilt by the noise moves all three alike).
  InspectionPlan three = plan;
  DatumFeature& b = three.alignment->datums[1];
  b.points.insert(b.points.begin() + 1, b.points[0]);
  b.points[1].id = "B3";
  b.points[1].xyz = {47, 0, -15};
  planted.clear();
  const Comparison t = run(part, three, measure(three, placement(), 1.0, [&](const PlannedPoint& p) {
                             return planted[p.id] = p.face == "B" ? 10 * noise(rng) : 0.0;
                           }), AlignMethod::datums);
  Eigen::MatrixXd line(b.points.size(), 2);
  for (std::size_t k = 0; k < b.points.size(); ++k) {
    const Eigen::Vector3d q = b.points[k].xyz + planted[b.points[k].id] * b.normal;
    line.row(static_cast<Eigen::Index>(k)) = Eigen::RowVector2d(q.x(), q.y());
  }
  const Eigen::MatrixXd lc = line.rowwise() - line.colwise().mean();
  const Eigen::JacobiSVD<Eigen::MatrixXd> ls(lc, Eigen::ComputeFullV);
  const Eigen::VectorXd across = lc * ls.matrixV().col(1);
  REQUIRE(t.datum_frame);
  CHECK(across.maxCoeff() - across.minCoeff() > 0.005);
  CHECK(std::abs(t.datum_frame->datums[1].form_error - (across.maxCoeff() - across.minCoeff())) < 1e-7);
  // The frame moved by at most the noise over the part (a few microns).
  const Eigen::Isometry3d e = c.datum_frame->transform * placement();
  for (const PlannedPoint& p : plan.points) CHECK((e * p.xyz - p.xyz).norm() < 0.05);
}

TEST_CASE("datums: a 0.1 mm shift of the free-form face shows in the datum profile, not in the best fit") {
  const Part part = datum_part();
  const InspectionPlan plan = datum_plan(part);
  const Eigen::Vector3d shift(0, 0, 0.1);  // the face machined 0.1 mm high relative to its datums
  // The probe touches the shifted face at p + shift with the same normal.
  const MeasurementSet measured = measure(plan, placement(), 1.0, [&](const PlannedPoint& p) {
    return p.face == "F" ? shift.dot(p.ijk) : 0.0;
  });
  // The offsets above move each point along its own normal only; the
  // deviation of the shifted face at p is shift . n (exact for the
  // face's tangent plane, second order in 0.1 mm otherwise).
  const Comparison c = run(part, plan, measured, AlignMethod::datums);
  double worst = 0;
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const double expected = shift.dot(plan.points[i].ijk);
    worst = std::max(worst, std::abs(expected));
    CHECK(std::abs(c.registration.points[i].deviation - (expected)) < 1e-5);
  }
  CHECK(c.summary.profile == doctest::Approx(2 * worst).epsilon(1e-4).scale(0));
  CHECK(c.summary.profile > 0.18);
  REQUIRE(c.bestfit_profile);
  CHECK(*c.bestfit_profile < 0.005);  // form alone: the best fit takes the shift away
  CHECK(c.summary.out_of_tolerance > 0);
}

TEST_CASE("cmm: points already in the part frame are evaluated as measured, no fit") {
  const Part part = datum_part();
  const InspectionPlan plan = datum_plan(part);
  const MeasurementSet measured =
      measure(plan, Eigen::Isometry3d::Identity(), 1.0, [](const PlannedPoint& p) { return p.face == "F" ? form(p) : 0.0; });
  const Comparison c = run(part, plan, measured, AlignMethod::cmm);
  CHECK(c.registration.transform.matrix() == Eigen::Matrix4d::Identity());
  CHECK(c.registration.fitted_dof == 0);
  CHECK(c.registration.observability.weak.empty());
  CHECK(c.summary.alignment == "ok");
  REQUIRE(c.registration.points.size() == measured.points.size());
  for (std::size_t i = 0; i < measured.points.size(); ++i) {
    const std::string& id = measured.points[i].id;
    double expected = 0;
    for (const PlannedPoint& p : plan.points)
      if (p.id == id) expected = form(p);
    CHECK(std::abs(c.registration.points[i].deviation - (expected)) < 1e-7);
  }
  REQUIRE(c.bestfit_profile);
}

TEST_CASE("datums: degenerate datum data and a missing datum point are refused with the reason") {
  const Part part = datum_part();
  const InspectionPlan plan = datum_plan(part);
  const auto none = [](const PlannedPoint&) { return 0.0; };
  SUBCASE("missing datum point: an input error naming it") {
    MeasurementSet measured = measure(plan, placement(), 1.0, none);
    measured.points.erase(std::remove_if(measured.points.begin(), measured.points.end(),
                                         [](const MeasuredPoint& p) { return p.id == "B2"; }),
                          measured.points.end());
    try {
      run(part, plan, measured, AlignMethod::datums);
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("B2") != std::string::npos);
    }
  }
  SUBCASE("collinear primary points") {
    InspectionPlan bad = plan;
    auto& a = bad.alignment->datums[0].points;
    a[0].xyz = {5, 5, 0}, a[1].xyz = {35, 15, 0}, a[2].xyz = {65, 25, 0}, a[3].xyz = {95, 35, 0};
    CHECK_THROWS_AS(run(part, bad, measure(bad, placement(), 1.0, none), AlignMethod::datums), DatumFrameError);
  }
  SUBCASE("secondary line along the primary normal") {
    InspectionPlan bad = plan;
    auto& b = bad.alignment->datums[1].points;
    b[0].xyz = {50, 0, -5}, b[1].xyz = {50, 0, -25};
    CHECK_THROWS_AS(run(part, bad, measure(bad, placement(), 1.0, none), AlignMethod::datums), DatumFrameError);
  }
  SUBCASE("--align datums without a datums alignment") {
    InspectionPlan bad = plan;
    const MeasurementSet measured = measure(plan, placement(), 1.0, none);
    bad.alignment.reset();
    CHECK_THROWS_AS(run(part, bad, measured, AlignMethod::datums), InputError);
  }
}

TEST_CASE("furrow compare --align: comparison.json records the method, the datums and both profiles, and the exit codes") {
  const Part part = datum_part();
  const InspectionPlan plan = datum_plan(part);
  const std::string dir = test::scratch_dir("compare-align-datums");
  write_part_json(part, dir + "/part.json");
  write_plan(plan, dir + "/plan.json");
  const Eigen::Vector3d shift(0, 0, 0.1);
  auto write = [&](const MeasurementSet& set, const std::string& name) {
    std::ofstream(dir + "/" + name) << measurements_to_csv(set);
    return dir + "/" + name;
  };
  const std::string shifted = write(measure(plan, placement(), 1.0, [&](const PlannedPoint& p) {
    return p.face == "F" ? shift.dot(p.ijk) : 0.0;
  }), "shifted.csv");
  auto compare = [&](const std::string& m, const std::string& align, const std::string& out) {
    return test::run_furrow({"compare", dir + "/part.json", "--measurements", m, "--plan", dir + "/plan.json",
                             "--points", "centre", "--align", align, "--tolerance", "0.05", "--out", dir + "/" + out});
  };
  const auto r = compare(shifted, "datums", "datums.json");
  INFO(r.out);
  INFO(r.err);
  CHECK(r.status == 1);  // 0.1 mm of location is outside a 0.05 mm zone
  const ComparisonDocument doc = read_comparison(dir + "/datums.json");
  CHECK(doc.alignment.method == "datums");
  REQUIRE(doc.alignment.datums.size() == 3);
  CHECK(doc.alignment.datums[0].label == "A");
  CHECK(doc.alignment.datums[0].points.size() == 4);
  CHECK(doc.alignment.datums[0].form_error < 1e-6);
  CHECK(doc.points.size() == plan.points.size());  // the datum points are not evaluated
  double worst = 0;
  for (const PlannedPoint& p : plan.points) worst = std::max(worst, std::abs(shift.dot(p.ijk)));
  CHECK(doc.summary.profile == doctest::Approx(2 * worst).epsilon(1e-3).scale(0));
  REQUIRE(doc.alignment.bestfit_profile);
  CHECK(*doc.alignment.bestfit_profile < 0.005);
  // The transform recorded is the placement's inverse.
  CHECK(((doc.registration.transform * placement().matrix()) - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff() < 1e-6);
  // Same inputs, same bytes.
  const auto again = compare(shifted, "datums", "datums2.json");
  CHECK(again.status == 1);
  CHECK(test::slurp(dir + "/datums.json") == test::slurp(dir + "/datums2.json"));

  // The default records itself too.
  const auto best = compare(shifted, "bestfit", "bestfit.json");
  CHECK((best.status == 0 || best.status == 1 || best.status == 4));
  CHECK(read_comparison(dir + "/bestfit.json").alignment.method == "bestfit");

  // A datum point missing: exit 2 naming it.
  MeasurementSet missing = measure(plan, placement(), 1.0, [](const PlannedPoint&) { return 0.0; });
  missing.points.erase(missing.points.begin() + 5);  // B2: A1..A4, B1, B2, C1, F...
  const auto m = compare(write(missing, "missing.csv"), "datums", "missing.json");
  CHECK(m.status == 2);
  CHECK(m.err.find("B2") != std::string::npos);
  // Collinear datum A points: exit 3 with the reason.
  InspectionPlan bad = plan;
  auto& a = bad.alignment->datums[0].points;
  a[0].xyz = {5, 5, 0}, a[1].xyz = {35, 15, 0}, a[2].xyz = {65, 25, 0}, a[3].xyz = {95, 35, 0};
  for (PlannedPoint& p : a) p.uv = {p.xyz.x() / 100, p.xyz.y() / 60};
  write_plan(bad, dir + "/bad_plan.json");
  const auto d = test::run_furrow({"compare", dir + "/part.json", "--measurements",
                                   write(measure(bad, placement(), 1.0, [](const PlannedPoint&) { return 0.0; }), "bad.csv"),
                                   "--plan", dir + "/bad_plan.json", "--points", "centre", "--align", "datums", "--out",
                                   dir + "/bad.json"});
  CHECK(d.status == 3);
  CHECK(d.err.find("collinear") != std::string::npos);
  // --align datums without a plan: exit 2.
  const auto n = test::run_furrow({"compare", dir + "/part.json", "--measurements", shifted, "--points", "centre",
                                   "--probe-diameter", "2", "--align", "datums", "--out", dir + "/none.json"});
  CHECK(n.status == 2);
  CHECK(n.err.find("--align datums") != std::string::npos);
}
