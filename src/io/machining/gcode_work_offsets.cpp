#include "io/machining/gcode_work_offsets.hpp"

namespace furrow {

int GcodeWorkOffsets::system_of(double g) {
  // The codes as written parse to these doubles exactly ("59.1" -> 59.1).
  static const double kCodes[kSystems] = {54, 55, 56, 57, 58, 59, 59.1, 59.2, 59.3};
  for (int k = 0; k < kSystems; ++k)
    if (g == kCodes[k]) return k + 1;
  return 0;
}

std::string GcodeWorkOffsets::name(int system) {
  static const char* kNames[kSystems] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};
  return system >= 1 && system <= kSystems ? kNames[system - 1] : "G5x";
}

void GcodeWorkOffsets::fix_frame() {
  if (fixed_) return;
  fixed_ = true;
  frame_ = active_;
  for (int a = 0; a < 3; ++a) {
    frame_origin_[a] = machine_[frame_][a];
    for (int k = 1; k <= kSystems; ++k) {
      Axis& r = relative_[k][a];
      if (k == frame_) {
        r = {0.0, true};
      } else {
        r.known = machine_[k][a].known && frame_origin_[a].known;
        r.value = r.known ? machine_[k][a].value - frame_origin_[a].value : 0.0;
      }
    }
  }
}

void GcodeWorkOffsets::set_absolute(int system, int axis, double value) {
  machine_[system][axis] = {value, true};
  if (!fixed_) return;
  const Axis& origin = frame_origin_[axis];
  relative_[system][axis] = {origin.known ? value - origin.value : 0.0, origin.known};
}

void GcodeWorkOffsets::set_to_read(int system, int axis, double value, bool position_known, double position) {
  // Before the frame is fixed no position is known (only moves make one
  // known, and the first move fixes the frame).
  if (!fixed_ || !position_known) {
    machine_[system][axis].known = false;
    if (fixed_) relative_[system][axis].known = false;
    return;
  }
  const Axis relative{position - value, true};
  relative_[system][axis] = relative;
  const Axis& origin = frame_origin_[axis];
  machine_[system][axis] = {origin.known ? origin.value + relative.value : 0.0, origin.known};
}

bool GcodeWorkOffsets::shift(int axis, double& out) const {
  // Before the first move there is no frame yet and nothing to shift.
  const Axis r = fixed_ ? relative_[active_][axis] : Axis{0.0, true};
  out = r.value;
  return r.known;
}

}  // namespace furrow
