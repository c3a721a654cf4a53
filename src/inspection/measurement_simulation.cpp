#include "inspection/measurement_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include "base/error.hpp"
#include "inspection/surface_sampling.hpp"
#include "base/numbers.hpp"

namespace furrow {

Eigen::Isometry3d Misalignment::part_to_cmm() const {
  const Eigen::Vector3d r = rotation_deg * (kPi / 180);
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = (Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  m.translation() = translation;
  return m;
}

double SurfaceBump::offset_at(const Eigen::Vector3d& point) const {
  const double rho = (point - centre).norm();
  return rho < radius ? height * (1 + std::cos(kPi * rho / radius)) / 2 : 0.0;
}

PredictedSurfaceOffsets predicted_surface_offsets(const InspectionPlan& plan,
                                                  const Prediction& prediction) {
  PredictedSurfaceOffsets out;
  for (const PlannedPoint& p : plan.points) {
    PredictedError e;
    if (prediction.find_face(p.face)) e = prediction.predicted_error_at(p.face, p.uv.x(), p.uv.y());
    out.offset.push_back(e.reached() ? e.value : 0.0);
    ++(e.reached() ? out.reached : out.not_reached);
  }
  return out;
}

SurfaceOffset PredictedSurfaceOffsets::lookup(const InspectionPlan& plan) const {
  return [index = plan.index_by_id(), offsets = offset](const PlannedPoint& p) {
    return offsets.at(index.at(p.id));
  };
}

SimulatedMeasurement simulate_measurement(const InspectionPlan& plan, const SimulationOptions& o,
                                          const std::string& name) {
  const std::size_t n = plan.points.size();
  if (!(o.noise_sigma >= 0) || !std::isfinite(o.noise_sigma))
    throw InputError(name + ": the noise must be a non-negative number of mm");
  if (o.blunders < 0 || static_cast<std::size_t>(o.blunders) > n)
    throw InputError(name + ": " + std::to_string(o.blunders) + " blunders but the plan has " +
                     std::to_string(n) + " points");
  if (!(o.blunder_min > 0) || !(o.blunder_max >= o.blunder_min) || !std::isfinite(o.blunder_max))
    throw InputError(name + ": the blunder size range must satisfy 0 < min <= max");
  for (const SurfaceBump& b : o.bumps)
    if (!(b.radius > 0) || !std::isfinite(b.radius) || !b.centre.allFinite() || !std::isfinite(b.height))
      throw InputError(name + ": a bump needs a finite centre and height and a positive radius");
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> size(o.blunder_min, o.blunder_max);
  std::bernoulli_distribution sign(0.5);

  // Draw everything in plan order first, so that the anonymous (shuffled)
  // variant of the same seed carries exactly the same measurements.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::size_t> pick = order;
  std::shuffle(pick.begin(), pick.end(), rng);
  std::vector<bool> is_blunder(n, false);
  for (int k = 0; k < o.blunders; ++k) is_blunder[pick[k]] = true;
  std::vector<double> deviation(n);
  std::vector<std::size_t> bump_points(o.bumps.size(), 0);
  for (std::size_t k = 0; k < n; ++k) {
    double d = o.surface_offset ? o.surface_offset(plan.points[k]) : 0.0;
    for (std::size_t b = 0; b < o.bumps.size(); ++b) {
      const double h = o.bumps[b].offset_at(plan.points[k].xyz);
      d += h;
      bump_points[b] += h != 0;
    }
    d += o.noise_sigma * noise(rng);
    if (is_blunder[k]) d += (sign(rng) ? 1 : -1) * size(rng);
    deviation[k] = d;
  }
  if (o.anonymous) std::shuffle(order.begin(), order.end(), rng);

  const Eigen::Isometry3d m = o.misalignment.part_to_cmm();
  const double r = o.kind == ProbePointKind::probe_centre ? plan.probe.radius() : 0.0;
  SimulatedMeasurement out;
  out.bump_points = bump_points;
  out.set.source = name;
  out.set.kind = o.kind;
  out.set.probe_radius = r;
  out.set.ids_from_file = !o.anonymous;
  for (std::size_t idx = 0; idx < n; ++idx) {
    const std::size_t k = order[idx];
    const PlannedPoint& p = plan.points[k];
    MeasuredPoint mp;
    mp.id = o.anonymous ? std::to_string(idx + 1) : p.id;
    mp.line = static_cast<int>(idx) + 1;
    mp.xyz = m * (p.xyz + (deviation[k] + r) * p.ijk);
    mp.ijk = m.linear() * p.ijk;
    out.set.points.push_back(mp);
    out.plan_ids.push_back(p.id);
    out.blunder.push_back(is_blunder[k]);
    out.true_deviation.push_back(deviation[k]);
  }
  return out;
}

InspectionPlan grid_plan(const Part& part, int nu, int nv, const ProbeDefinition& probe,
                         double clearance) {
  InspectionPlan plan;
  plan.probe = probe;
  int order = 0;
  for (std::size_t f = 0; f < part.faces.size(); ++f) {
    for (const SurfaceSample& s : sample_face_grid(part, f, nu, nv)) {
      PlannedPoint p;
      p.order = ++order;
      char id[32];
      std::snprintf(id, sizeof id, "P%05d", p.order);
      p.id = id;
      p.face = part.faces[f].name();
      p.face_index = f;
      p.uv = s.uv;
      p.xyz = s.point;
      p.ijk = s.normal;
      p.approach = p.retract = s.point + (probe.radius() + clearance) * s.normal;
      plan.points.push_back(p);
    }
  }
  return plan;
}

}  // namespace furrow
