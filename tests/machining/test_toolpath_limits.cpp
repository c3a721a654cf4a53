// Tool-path planning refuses work beyond its caps before doing it
// (docs/formats.md "Limits"): a hostile tool or scallop height answers at
// once with an InputError instead of running for minutes.
#include <doctest/doctest.h>

#include <chrono>
#include <string>

#include "base/error.hpp"
#include "geometry/primitives.hpp"
#include "machining/toolpath/contact_planning.hpp"

using namespace furrow;

namespace {

std::string plan_error(const Part& part, const Cutter& cutter, const ContactPlanOptions& options) {
  try {
    plan_contact_points(part, cutter, {PassDirection::along_u, 0}, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("toolpath limits: a 0.01 mm ball over a 100 x 80 mm plate is refused at once") {
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {100, 0, 0}, {0, 80, 0}));
  // Side step at h = 0.005 mm: 2 sqrt(2 r h - h^2) = 0.01 mm, so 8000 passes.
  const Cutter tiny("tiny", 0.005, 0.005);
  const auto start = std::chrono::steady_clock::now();
  const std::string e = plan_error(part, tiny, {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CAPTURE(e);
  CHECK(e.rfind("toolpath: a scallop height of 0.005 mm", 0) == 0);
  CHECK(e.find("more than the limit of 5000 passes") != std::string::npos);
  CHECK(seconds < 2);
  // The same plate with a 6 mm ball: about 100 passes, planned.
  ContactPlanOptions options;
  options.scallop = 0.05;
  CHECK(plan_error(part, Cutter("ball6", 3, 3), options).empty());
}

TEST_CASE("toolpath limits: tolerance and scallop height outside 1e-4 to 10 mm") {
  Part part;
  part.faces.emplace_back("plate", make_plane({0, 0, 0}, {10, 0, 0}, {0, 10, 0}));
  const Cutter ball("ball6", 3, 3);
  ContactPlanOptions tight;
  tight.forward.tolerance = 1e-300;
  CHECK(plan_error(part, ball, tight).rfind("toolpath: the tolerance 1e-300 mm is outside", 0) == 0);
  ContactPlanOptions coarse;
  coarse.scallop = 1e300;
  CHECK(plan_error(part, ball, coarse).rfind("toolpath: the scallop height 1e+300 mm is outside", 0) == 0);
}
