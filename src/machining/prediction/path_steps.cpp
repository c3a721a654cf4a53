#include "machining/prediction/path_steps.hpp"

#include <omp.h>

#include <atomic>

namespace furrow {

const char* to_string(StepStatus status) {
  switch (status) {
    case StepStatus::evaluated: return "evaluated";
    case StepStatus::in_air: return "in_air";
    case StepStatus::no_contact: return "no_contact";
    case StepStatus::unreachable: return "unreachable";
  }
  return "unknown";
}

std::vector<StepPrediction> predict_steps(const VerticalProjector& projector, const Cutter& cutter,
                                          const PathGeometry& geometry, const FurrowStepOptions& options,
                                          const std::function<void(std::size_t, std::size_t)>& progress,
                                          const StripStepOptions& strip) {
  std::vector<StepPrediction> steps;
  for (std::size_t p = 0; p < geometry.passes.size(); ++p)
    for (std::size_t k = 0; k + 1 < geometry.passes[p].size(); ++k) {
      StepPrediction s;
      s.pass = static_cast<int>(p);
      s.step = static_cast<int>(k);
      steps.push_back(s);
    }
  std::atomic<std::size_t> done{0};
#pragma omp parallel for schedule(dynamic, 8)
  for (std::size_t k = 0; k < steps.size(); ++k) {
    StepPrediction& s = steps[k];
    const PathPoint& a = geometry.passes[s.pass][s.step];
    const PathPoint& b = geometry.passes[s.pass][s.step + 1];
    if (a.in_air || b.in_air) {
      s.status = StepStatus::in_air;
    } else if (!a.contact.valid || !b.contact.valid) {
      s.status = StepStatus::no_contact;
    } else {
      s.length = (b.contact.at.point - a.contact.at.point).norm();
      // One remembering curve: the error and the chord deviation sample it
      // on the same grid.
      const SurfaceCurve curve = remembering_curve(vertical_section_curve(projector, a.contact.at, b.contact.at));
      s.error = furrow_step_error(cutter, a.tip, b.tip, curve, options);
      s.status = s.error.valid ? StepStatus::evaluated : StepStatus::unreachable;
      if (s.error.valid) s.chord = chord_deviation(curve, options);
      const StripStepResult beside = strip_step_error(projector.part(), cutter, curve, s.error, options, strip);
      if (beside.valid) {
        s.error.overcut = {beside.overcut.error, beside.overcut.lambda, beside.overcut.at};
        s.error.undercut = {beside.undercut.error, beside.undercut.lambda, beside.undercut.at};
        s.error.converged = s.error.converged && beside.converged;
      }
    }
    const std::size_t d = ++done;
    if (progress && omp_get_thread_num() == 0 && d % 64 == 0) progress(d, steps.size());
  }
  if (progress) progress(steps.size(), steps.size());
  return steps;
}

}  // namespace furrow
