#include "machining/gouge/angular_ranges.hpp"
#include "base/numbers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace furrow {

namespace {
constexpr double kTwoPi = 2 * kPi;
}

double wrap_angle(double angle) {
  double a = std::fmod(angle, kTwoPi);
  if (a < 0) a += kTwoPi;
  if (a >= kTwoPi) a = 0;  // fmod of -tiny + 2 pi rounds up to 2 pi
  return a;
}

bool AngularRange::contains(double angle) const {
  return wrap_angle(angle - start) <= width;
}

void AngularRanges::add(double start, double width) {
  if (count_ == kCapacity) throw std::logic_error("AngularRanges: capacity exceeded");
  arcs_[count_++] = AngularRange{wrap_angle(start), std::clamp(width, 0.0, kTwoPi)};
}

void AngularRanges::add_clipped(const AngularRange& arc, const AngularRange& window) {
  if (arc.width >= kTwoPi) {  // the whole circle: the window itself
    add(window.start, window.width);
    return;
  }
  // Work in the window's frame: the window is [0, w]; the arc starts at s and
  // also, one turn back, at s - 2 pi.
  const double s = wrap_angle(arc.start - window.start);
  for (const double lo0 : {s, s - kTwoPi}) {
    const double lo = std::max(lo0, 0.0), hi = std::min(lo0 + arc.width, window.width);
    const bool keep = arc.width > 0 ? hi > lo : (lo == lo0 && lo0 <= window.width);
    if (keep) add(window.start + lo, arc.width > 0 ? hi - lo : 0.0);
  }
}

void AngularRanges::normalize() {
  if (count_ <= 1) return;
  std::sort(arcs_, arcs_ + count_,
            [](const AngularRange& a, const AngularRange& b) {
              return a.start < b.start || (a.start == b.start && a.width > b.width);
            });
  AngularRange merged[kCapacity];
  std::size_t m = 0;
  // Arcs that meet at a window edge may miss each other by rounding (an end
  // computed as 2.5 pi - 2 pi is not 0.5 pi to the last bit): closer than
  // this they touch [rad] (reports give degrees to 1e-4).
  constexpr double kTouch = 1e-12;
  for (std::size_t i = 0; i < count_; ++i) {
    const AngularRange& a = arcs_[i];
    if (m > 0 && a.start <= merged[m - 1].end() + kTouch) {
      merged[m - 1].width = std::min(kTwoPi, std::max(merged[m - 1].end(), a.end()) - merged[m - 1].start);
    } else {
      merged[m++] = a;
    }
  }
  // The last arc may run past 2 pi into the first ones.
  while (m > 1 && merged[m - 1].end() + kTouch >= merged[0].start + kTwoPi) {
    AngularRange& last = merged[m - 1];
    const double end = std::max(last.end(), merged[0].end() + kTwoPi);
    last.width = std::min(kTwoPi, end - last.start);
    std::copy(merged + 1, merged + m, merged);
    --m;
  }
  if (m == 1 && merged[0].width >= kTwoPi) merged[0] = AngularRange{0.0, kTwoPi};
  std::copy(merged, merged + m, arcs_);
  count_ = m;
}

bool AngularRanges::contains(double angle) const {
  for (const AngularRange& a : *this)
    if (a.contains(angle)) return true;
  return false;
}

}  // namespace furrow
