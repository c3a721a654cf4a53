#pragma once
// Scallop height and side step for any end mill of cutter.hpp (ball, flat,
// bull-nose), in the vertical cross-section across two adjacent passes.
//
// Model (the one docs/architecture.md states for the ball, generalised): the design
// surface across the passes is a circle of curvature k (docs/architecture.md sign:
// convex < 0, concave > 0, 0 flat) whose normal at the middle is tilted by
// `tilt` from the vertical within the cross-section; the two contact points
// lie an arc w apart, at sigma = first w and (first + 1) w from the point
// where the tilt is given (arc length toward +x): first = -0.5 centres the
// pair on it, 0 starts the pair there, -1 ends it there. Where the pair sits
// matters for flat-bottomed cutters: across the crest of a convex section
// (tilt 0) the cutter touches with its corner on opposite sides of its flat
// bottom, and a pair on one side of the crest misses that. Each cutter is located at
// its contact (cutter_location.hpp in the plane; at a horizontal contact of
// a flat-bottomed cutter both axes go to the same side, as
// cutter_location's fixed horizontal side puts them), its lower envelope in
// the plane is
// tip.z + height_at(|x - tip.x|), and the scallop is the largest error
// (normal_error.hpp) of the arc between the contacts under the lower of the
// two envelopes.
//
// The ball is rotationally symmetric, so its scallop does not depend on the
// tilt: the exact closed forms of scallop.hpp are used. Other cutters are
// computed numerically (sampling plus Brent on the ridge; bisection on w for
// the inverse), with caps and tolerances in the options.
#include <optional>

#include "machining/cutter/cutter.hpp"
#include "machining/prediction/scallop.hpp"

namespace furrow {

struct CrossSectionOptions {
  int samples = 48;                 // along the arc between the contacts
  double ridge_tolerance = 1e-7;    // [mm] position of the ridge
  double side_step_tolerance = 1e-6;  // [mm] on w
  int max_iterations = 80;          // bisection on w
};

// nullopt when there is no ridge (a concave section tighter than a ball,
// or contacts so far apart that the cutters no longer overlap).
std::optional<double> cutter_scallop_height(const Cutter& cutter, double curvature_across, double tilt,
                                            double side_step, const CrossSectionOptions& options = {},
                                            double first = -0.5);

// Largest w whose scallop does not exceed `height`.
SideStepResult cutter_side_step_for_scallop(const Cutter& cutter, double curvature_across, double tilt,
                                            double height, const CrossSectionOptions& options = {},
                                            double first = -0.5);

}  // namespace furrow
