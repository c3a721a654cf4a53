#pragma once
// The exact per-step error (furrow_step.hpp) of every move of a located tool
// path (path_contacts.hpp). The design curve of a step is the vertical
// section between its two contact points (the plane the straight move lies
// in); the move is the path's own pair of tips. A step that overcuts has
// its overcut refined over the strip beside the curve (strip_step.hpp): its
// deepest point on an oblique step lies off the curve.
#include <functional>
#include <vector>

#include "machining/prediction/furrow_step.hpp"
#include "machining/prediction/path_contacts.hpp"
#include "machining/prediction/strip_step.hpp"

namespace furrow {

enum class StepStatus : unsigned char {
  evaluated = 0,
  in_air = 1,      // a tip above the part by more than the air gap: an approach, link or retract
  no_contact = 2,  // a tip has no contact point on the part
  unreachable = 3, // a contact normal has n_z < 0, or the section leaves the part
};
const char* to_string(StepStatus status);

struct StepPrediction {
  int pass = 0, step = 0;  // move `step` of pass `pass` (from point step to step + 1)
  StepStatus status = StepStatus::no_contact;
  FurrowStepResult error;        // when evaluated
  ChordDeviation chord;          // the chord-deviation estimate, for comparison
  double length = 0;             // [mm] between the contact points
};

// Parallel over steps; each depends on its own step only.
std::vector<StepPrediction> predict_steps(const VerticalProjector& projector, const Cutter& cutter,
                                          const PathGeometry& geometry, const FurrowStepOptions& options = {},
                                          const std::function<void(std::size_t, std::size_t)>& progress = {},
                                          const StripStepOptions& strip = {});

}  // namespace furrow
