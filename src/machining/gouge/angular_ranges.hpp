#pragma once
// Arcs of tangent directions on the circle of angles, and the little
// arithmetic local gouge checks need (clip to a window, union).
//
// An arc is [start, start + width] counter-clockwise, start in [0, 2 pi),
// width in [0, 2 pi] (radians; 0 = a single direction, 2 pi = all). The set
// holds at most kCapacity arcs, without heap allocation, because a gouge
// check runs millions of times: one comparison gives at most two arcs (a
// direction and its opposite), each clipped to at most two window pieces,
// and a check combines at most two surfaces times two cutter pieces
// (compound_border.hpp, cutter_curvature.hpp), normalising in between.
// Exceeding the capacity is a programming error (std::logic_error).
#include <cmath>
#include <cstddef>

#include "base/numbers.hpp"

namespace furrow {

// No default member initialisers: AngularRanges keeps uninitialised spare
// slots (zero-filling them cost a fifth of a gouge check).
struct AngularRange {
  double start;  // [rad], in [0, 2 pi)
  double width;  // [rad], in [0, 2 pi]
  double end() const { return start + width; }  // may exceed 2 pi
  bool contains(double angle) const;            // any angle; wraps
  // The same in degrees, as reports give them.
  double start_deg() const { return start * (180 / kPi); }
  double end_deg() const { return end() * (180 / kPi); }
};

// Angle reduced to [0, 2 pi).
double wrap_angle(double angle);

class AngularRanges {
 public:
  static constexpr std::size_t kCapacity = 16;

  AngularRanges() = default;
  // Copies only the arcs in use (the spare slots are never read).
  AngularRanges(const AngularRanges& other) : count_(other.count_) {
    for (std::size_t i = 0; i < count_; ++i) arcs_[i] = other.arcs_[i];
  }
  AngularRanges& operator=(const AngularRanges& other) {
    count_ = other.count_;
    for (std::size_t i = 0; i < count_; ++i) arcs_[i] = other.arcs_[i];
    return *this;
  }

  bool empty() const { return count_ == 0; }
  std::size_t size() const { return count_; }
  const AngularRange& operator[](std::size_t i) const { return arcs_[i]; }
  const AngularRange* begin() const { return arcs_; }
  const AngularRange* end() const { return arcs_ + count_; }

  // Adds an arc (start any angle, wrapped; width clamped to [0, 2 pi]).
  void add(double start, double width);
  // Parts of `arc` inside `window` (at most two pieces), appended to this.
  // A zero-width arc (a single direction) is kept when it lies in the window
  // (ends included); other pieces only when they have positive width.
  void add_clipped(const AngularRange& arc, const AngularRange& window);
  // Sorts by start and merges overlapping or touching arcs (also across 0;
  // arcs within 1e-12 rad of each other touch: rounding at window edges).
  void normalize();
  bool contains(double angle) const;

 private:
  AngularRange arcs_[kCapacity];  // the first count_ are set
  std::size_t count_ = 0;
};

}  // namespace furrow
