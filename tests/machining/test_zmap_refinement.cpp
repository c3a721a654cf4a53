// The z-map error map converges as the path is refined (zmap.hpp height_at,
// error_map.hpp "Boundary samples"): the same arcs cut into G1 chords of
// 1e-6 mm and of 1e-7 mm sag give, sample by sample, the same status and
// errors within 0.1 um, except samples flagged as boundary samples; and the
// errors are those of the exact lower envelope of all moves (brute force).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "io/part_file.hpp"
#include "machining/prediction/error_map.hpp"
#include "machining/prediction/normal_error.hpp"
#include "machining/prediction/zmap.hpp"

using namespace furrow;

namespace {

std::string example(const std::string& name) { return std::string(FURROW_SOURCE_DIR) + "/examples/parts/" + name; }

// Full circles of the given radii about `centre`, in the plane through it
// tilted by `tilt` radians about the y axis (so the tool climbs and descends
// along each circle), one pass per circle, cut into chords of sag `sag`
// (sag = rho (1 - cos(theta / 2)) for a chord of angle theta).
std::vector<ZMapMove> tilted_circles(const Eigen::Vector3d& centre, double tilt, const std::vector<double>& radii,
                                     double sag) {
  const Eigen::Vector3d e1(std::cos(tilt), 0, std::sin(tilt)), e2(0, 1, 0);
  std::vector<ZMapMove> moves;
  for (std::size_t c = 0; c < radii.size(); ++c) {
    const double rho = radii[c];
    const int n = static_cast<int>(std::ceil(M_PI / std::acos(1 - sag / rho)));
    auto at = [&](int k) {
      const double a = 2 * M_PI * k / n;
      return Eigen::Vector3d(centre + rho * (std::cos(a) * e1 + std::sin(a) * e2));
    };
    for (int k = 0; k < n; ++k) moves.push_back({at(k), at(k + 1), static_cast<int>(c), k});
  }
  return moves;
}

// The machined height by brute force: the lowest swept envelope of every
// move whose shadow holds (x, y), found through 1 mm buckets of the moves'
// shadow boxes (the bucket only narrows the candidates; each candidate is
// evaluated exactly).
class BruteForceHeight {
 public:
  BruteForceHeight(const Cutter& cutter, const std::vector<ZMapMove>& moves, const Eigen::AlignedBox2d& extent)
      : origin_(extent.min() - Eigen::Vector2d(5, 5)) {
    nx_ = static_cast<int>(std::ceil(extent.sizes().x() + 10)) + 1;
    ny_ = static_cast<int>(std::ceil(extent.sizes().y() + 10)) + 1;
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (const ZMapMove& m : moves) {
      envelopes_.emplace_back(cutter, m.from, m.to);
      const Eigen::AlignedBox2d box = envelopes_.back().shadow_box();
      const Eigen::Vector2i lo = cell(box.min()), hi = cell(box.max());
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int i = lo.x(); i <= hi.x(); ++i) buckets_[static_cast<std::size_t>(j) * nx_ + i].push_back(envelopes_.size() - 1);
    }
  }
  double operator()(double x, double y) const {
    double best = std::numeric_limits<double>::infinity();
    const Eigen::Vector2i c = cell({x, y});
    for (std::size_t m : buckets_[static_cast<std::size_t>(c.y()) * nx_ + c.x()])
      best = std::min(best, envelopes_[m].height_at(x, y));
    return best;
  }

 private:
  Eigen::Vector2i cell(const Eigen::Vector2d& p) const {
    return {std::clamp(static_cast<int>(std::floor(p.x() - origin_.x())), 0, nx_ - 1),
            std::clamp(static_cast<int>(std::floor(p.y() - origin_.y())), 0, ny_ - 1)};
  }
  Eigen::Vector2d origin_;
  int nx_ = 0, ny_ = 0;
  std::vector<SweptEnvelope> envelopes_;
  std::vector<std::vector<std::size_t>> buckets_;
};

struct Setup {
  std::string part;
  Eigen::Vector3d centre;
  std::vector<double> radii;
};

}  // namespace

// Ball, flat and bull-nose D8 over one part (one test case per part, so
// that ctest runs them side by side).
static void check_refinement(const Setup& setup) {
  const Cutter cutters[] = {Cutter("BALL-D8", 4, 4), Cutter("FLAT-D8", 4, 0), Cutter("BULL-D8-R1", 4, 1)};
  {
    const Part part = read_part(example(setup.part));
    for (const Cutter& cutter : cutters) {
      CAPTURE(setup.part);
      CAPTURE(cutter.name());
      const double tilt = 0.08;
      std::vector<ZMapMove> paths[2];
      std::vector<ZMap> zmaps;
      std::vector<ErrorMap> maps;
      for (int r = 0; r < 2; ++r) {
        paths[r] = tilted_circles(setup.centre, tilt, setup.radii, r == 0 ? 1e-6 : 1e-7);
        zmaps.emplace_back(part_xy_extent(part), 0.1);
        zmaps.back().cut(cutter, paths[r]);
        maps.push_back(compute_error_map(part, zmaps.back()));
      }
      REQUIRE(paths[1].size() > 2 * paths[0].size());  // the moves really are shorter than a cell
      CHECK(paths[1].size() > 8000);
      const FaceErrorMap& a = maps[0].faces[0];
      const FaceErrorMap& b = maps[1].faces[0];
      REQUIRE(a.error.size() == b.error.size());
      int compared = 0, moved = 0, status_changed = 0, boundary = 0, undercut = 0, overcut = 0;
      double worst = 0;
      for (std::size_t k = 0; k < a.error.size(); ++k) {
        if (a.boundary[k] || b.boundary[k]) {
          ++boundary;
          continue;
        }
        if (a.status[k] != b.status[k]) {
          ++status_changed;
          continue;
        }
        if (a.status[k] != ErrorCellStatus::reached) continue;
        ++compared;
        const double d = std::fabs(double(a.error[k]) - double(b.error[k]));
        worst = std::max(worst, d);
        moved += d >= 1e-4;
        undercut += a.error[k] > 0.01;
        overcut += a.error[k] < -0.01;
      }
      CAPTURE(compared);
      CAPTURE(boundary);
      CAPTURE(worst);
      CHECK(status_changed == 0);
      CHECK(moved == 0);
      // Not vacuous: the path cuts the part (both signs of error) and most
      // of what it reaches is off the boundary.
      CHECK(compared > 10000);
      CHECK(undercut > 1000);
      CHECK(overcut > 1000);
      CHECK(boundary < compared / 4);
      // Flagged samples exist where the cut ends.
      CHECK(boundary > 0);
      CHECK(maps[1].boundary > 0);

      // Independent oracle: the error along the normal to the brute-force
      // envelope of all moves, at a spread of samples off the boundary.
      const BruteForceHeight brute(cutter, paths[1], part_xy_extent(part));
      // The oracle's normal search steps at most 50 um: the geometric
      // bracket alone can step past a thin stretch where the normal is
      // above the machined surface into uncut space beyond it and report
      // nothing (normal_error.hpp "max_step"; the z-map limits its steps to
      // a cell for the same reason).
      NormalErrorOptions fine;
      fine.max_step = 0.05;
      const Face& face = part.faces[0];
      int checked = 0, wrong = 0;
      double worst_oracle = 0;
      // A spread of about 200 reached samples off the boundary.
      std::vector<std::size_t> inside;
      for (std::size_t k = 0; k < b.error.size(); ++k)
        if (b.status[k] == ErrorCellStatus::reached && !b.boundary[k]) inside.push_back(k);
      const std::size_t step = std::max<std::size_t>(1, inside.size() / 200);
      for (std::size_t q = 0; q < inside.size(); q += step) {
        const std::size_t k = inside[q];
        const int i = static_cast<int>(k % b.nu), j = static_cast<int>(k / b.nu);
        Eigen::Vector3d p, n;
        REQUIRE(face_normal(face, b.u(i), b.v(j), p, n));
        const NormalError fast = zmap_error(zmaps[1], p, n);
        const NormalError slow = normal_error(brute, p, n, fine);
        REQUIRE(slow.reached);
        ++checked;
        worst_oracle = std::max(worst_oracle, std::fabs(fast.error - slow.error));
        // Within a nanometre: the walk finds the lowest pass position at the
        // point from the owners of the four nodes around it; a position
        // lower still that no node around sees (a local minimum of a pass
        // narrower than a cell) is missed by up to ~0.3 nm here.
        wrong += !(std::fabs(fast.error - slow.error) <= 1e-6);
      }
      CAPTURE(worst_oracle);
      CHECK(checked > 100);
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("z-map error map on the mould: arcs cut at 1e-6 and 1e-7 mm sag give the same errors off the boundary") {
  check_refinement({"mould.json", {50, 40, 26}, {10}});
}

TEST_CASE("z-map error map on the semi-cylinder: arcs cut at 1e-6 and 1e-7 mm sag give the same errors off the boundary") {
  check_refinement({"semi_cylinder.json", {0, 25.4, 23}, {8}});
}
