#include "machining/cutter/cutter.hpp"

#include <sstream>

#include "base/number_text.hpp"
#include "base/error.hpp"
#include "base/numbers.hpp"

namespace furrow {

namespace {

std::string text(double x) { return general(x, 12); }

}  // namespace

Cutter::Cutter(std::string name, double radius, double corner_radius, const std::string& where)
    : name_(std::move(name)), radius_(radius), corner_radius_(corner_radius) {
  if (!std::isfinite(radius) || !(radius > 0))
    throw InputError(where + ": the cutter radius must be positive, got " + text(radius));
  if (!std::isfinite(corner_radius) || corner_radius < 0)
    throw InputError(where + ": the corner radius must not be negative, got " +
                     text(corner_radius));
  if (corner_radius > radius)
    throw InputError(where + ": the corner radius " + text(corner_radius) +
                     " exceeds the cutter radius " + text(radius));
  flat_radius_ = radius - corner_radius;
  corner_ = ProfileArc{flat_radius_, corner_radius, corner_radius, 0.0, 0.5 * kPi};
}

Cutter::Cutter(const ToolSpec& spec)
    : Cutter(spec.name, 0.5 * spec.diameter, spec.corner_radius, "tool \"" + spec.name + "\"") {}

ToolType Cutter::type() const {
  if (corner_radius_ == radius_) return ToolType::ball;
  if (corner_radius_ == 0) return ToolType::flat;
  return ToolType::bull;
}

ToolSpec Cutter::spec() const { return ToolSpec{name_, type(), diameter(), corner_radius_}; }

}  // namespace furrow
