// Per-step exact furrow predictor: steps per second,
// single thread, on the steps of a generated finishing path of the mould
// (ball 6 mm, tolerance 0.01 mm), for a ball and for a bull-nose on the same
// contact points; then the number of contact points the exact rule needs
// against chord-deviation placement at equal real tolerance (the chord
// tolerance shrunk until no step's real error exceeds it) over every pass.
// Prints figures; it does not pass or fail.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "io/part_file.hpp"
#include "machining/toolpath/contact_planning.hpp"

using namespace furrow;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Points and worst real error of a rule over the given pass curves.
void place_all(const Part& part, const Cutter& cutter, const std::vector<PassCurve>& passes,
               const ForwardStepOptions& options, std::size_t& points, double& worst) {
  points = 0;
  worst = 0;
  std::vector<std::size_t> counts(passes.size());
  std::vector<double> worsts(passes.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t p = 0; p < passes.size(); ++p) {
    const ForwardSteps s = place_contact_points(part, passes[p], cutter, options);
    counts[p] = s.params.size();
    for (std::size_t k = 1; k < s.params.size(); ++k)
      worsts[p] = std::max(worsts[p], step_error(part, cutter, passes[p].between(s.params[k - 1], s.params[k]), StepRule::exact));
  }
  for (std::size_t p = 0; p < passes.size(); ++p) points += counts[p], worst = std::max(worst, worsts[p]);
}

}  // namespace

int main() {
  const Part part = read_part(FURROW_SOURCE_DIR "/examples/parts/mould.json");
  const Cutter ball("BALL-D6", 3, 3), bull("BULL-D10-R2", 5, 2);
  ContactPlanOptions options;
  options.forward.tolerance = 0.01;
  options.scallop = 0.005;
  const ContactPlan plan = plan_contact_points(part, ball, {PassDirection::along_u, 0}, options);
  std::vector<std::pair<SurfacePoint, SurfacePoint>> steps;
  for (const PlannedPass& p : plan.passes)
    for (std::size_t k = 1; k < p.points.size(); ++k) steps.emplace_back(p.points[k - 1].at, p.points[k].at);
  for (const Cutter* cutter : {&ball, &bull}) {
    double checksum = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& [a, b] : steps)
      checksum += furrow_step_error(*cutter, iso_parametric_curve(part, a.face, a.uv, b.uv)).magnitude();
    const double s = seconds_since(t0);
    std::printf("per-step predictor, %-12s %zu steps: %.0f steps/s single thread (checksum %.6f)\n",
                cutter->name().c_str(), steps.size(), steps.size() / s, checksum);
  }

  // Exact against chord deviation at equal real tolerance, every pass of the plan.
  std::vector<PassCurve> passes;
  for (const PlannedPass& p : plan.passes)
    passes.push_back(iso_parametric_pass(part, p.face, true, p.level, 0.0, 1.0));
  const double e = options.forward.tolerance;
  std::size_t exact_points = 0, chord_points = 0, arc_points = 0;
  double exact_worst = 0, chord_worst = 0, arc_worst = 0;
  place_all(part, ball, passes, options.forward, exact_points, exact_worst);
  ForwardStepOptions chord = options.forward;
  chord.rule = StepRule::chord;
  place_all(part, ball, passes, chord, chord_points, chord_worst);
  std::printf("chord rule at its nominal %.3g mm: %zu points, real error up to %.2f um\n", e, chord_points,
              chord_worst * 1000);
  while (chord_worst > e) {
    chord.tolerance *= std::min(0.98, e / chord_worst);
    place_all(part, ball, passes, chord, chord_points, chord_worst);
  }
  ForwardStepOptions arc = options.forward;
  arc.rule = StepRule::circular_arc;
  place_all(part, ball, passes, arc, arc_points, arc_worst);
  std::printf("contact points over %zu passes at real tolerance %.3g mm: exact %zu (worst %.3f um), chord %zu "
              "(chord tolerance %.4f mm, worst %.3f um)\n",
              passes.size(), e, exact_points, exact_worst * 1000, chord_points, chord.tolerance, chord_worst * 1000);
  std::printf("circular-arc estimate at %.3g mm: %zu points, real error up to %.2f um\n", e, arc_points,
              arc_worst * 1000);
  return 0;
}
