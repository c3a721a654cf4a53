#pragma once
// The work coordinate systems of a G-code program (docs/formats.md "Tool
// paths", "Work offsets"): G54-G59, G59.1-G59.3 and the offsets G10 L2 and
// G10 L20 give them, as LinuxCNC defines them, turned into the one part
// frame the reader's positions are in.
//
// Why a part frame: every later stage compares the path with the part, so
// all positions must be in one frame whatever system each line was written
// in. The part frame is the system in effect at the first move that gives a
// coordinate (G54 unless one was selected before it: the controls' default).
// A coordinate given in system k lands at
//   part = programmed + offset(k) - offset(part frame system when fixed)
// which is known only where the file says both: both offsets set by G10 L2
// (machine coordinates), or system k set by G10 L20 after the position was
// known (relative to where the tool is, so the machine offset need not be).
// Unknown shifts are not guessed: the reader refuses a coordinate that
// needs one. Lengths are millimetres (the reader converts G20 values).
//
// Systems are numbered as G10's P word: 1..9 for G54..G59.3, 0 the active one.
#include <string>

namespace furrow {

class GcodeWorkOffsets {
 public:
  static constexpr int kSystems = 9;

  // 1..9 for G54 G55 G56 G57 G58 G59 G59.1 G59.2 G59.3; 0 for any other code.
  static int system_of(double g);
  // "G54", ..., "G59.3".
  static std::string name(int system);

  void select(int system) { active_ = system; }
  int active() const { return active_; }
  // Fixes the part frame as the active system, the first time only: the
  // reader calls it at the first move with a coordinate.
  void fix_frame();
  bool frame_fixed() const { return fixed_; }
  int frame_system() const { return frame_; }

  // G10 L2: the origin of `system` (1..9) on `axis` is at `value` in machine
  // coordinates [mm].
  void set_absolute(int system, int axis, double value);
  // G10 L20: `system`'s origin on `axis` is placed so that the tool's
  // position there reads `value` [mm]; `position` is that position in the
  // part frame, `position_known` whether it is known at all.
  void set_to_read(int system, int axis, double value, bool position_known, double position);

  // part = programmed + shift on `axis` in the active system; false when the
  // file does not say it.
  bool shift(int axis, double& out) const;

 private:
  struct Axis {
    double value = 0;
    bool known = false;
  };
  Axis machine_[kSystems + 1][3];   // origin in machine coordinates (G10 L2)
  Axis relative_[kSystems + 1][3];  // origin in the part frame, once it is fixed
  Axis frame_origin_[3];            // the part frame's origin in machine coordinates
  int active_ = 1;
  int frame_ = 0;
  bool fixed_ = false;
};

}  // namespace furrow
