#pragma once
// Which registered points are blunders and which are real, large form
// deviations (registration.hpp explains the reasons and why the difference
// matters: a gouge must never be explained away as a bad point).
//
// Rule: among points with a usable foot point, d is large when
// |d - median(d)| > max(k * 1.4826 * MAD(d), floor). Neighbours of a large
// point agree with it when they are large too, on the same side and alike:
// their values within the same limit of each other, or their excesses over
// the median within a factor kAlikeRatio (a real gouge is graded from its
// rim to its bottom; neighbours in a deep one differ by far more than the
// limit). Neighbours: the six nearest within `radius`, exact k-d tree over the
// given positions (the foot points on the surface, see registration.cpp). A large point with `confirm` or more agreeing
// neighbours is the core of a real deviation; it and every large point that
// agrees with a core are large_deviation, the rest blunders. (Random blunders
// rarely form a core: three on the same side side by side; a real gouge's
// rim points join through its core.)
#include <Eigen/Core>
#include <vector>

namespace furrow {

enum class OutlierReason;

// Excesses over the median within this factor of each other are alike.
constexpr double kAlikeRatio = 3;

struct OutlierRule {
  double sigmas = 5;
  double floor = 0.025;  // [mm]
  int confirm = 3;
  double radius = 10;  // [mm]
};

struct OutlierVerdict {
  double median = 0;        // of d over usable points [mm]
  double robust_sigma = 0;  // 1.4826 MAD [mm]
  double limit = 0;         // the |d - median| above which d is large [mm]
};

// `usable[i]` false: the point is skipped (no verdict written). Writes
// reasons (none, blunder, large_deviation) for the usable points.
OutlierVerdict classify_deviations(const std::vector<Eigen::Vector3d>& positions,
                                   const std::vector<double>& deviation,
                                   const std::vector<bool>& usable, const OutlierRule& rule,
                                   std::vector<OutlierReason>& reasons);

}  // namespace furrow
