// Closest-point projection throughput and accuracy, side by side with
// OpenCASCADE's GeomAPI_ProjectPointOnSurf on the same surface (the mould
// example's bicubic 21 x 17 patch, rebuilt in OCCT as a Geom_BSplineSurface
// from our control net) and the same points (target: >= 10x faster,
// accuracy no worse). Prints figures; it does not pass or fail.
//
// Four point sets: "near" = typical CMM points (a surface point moved up to
// +-3 mm along its normal) in random order, "far" = the same up to +-20 mm,
// "box" = uniform in the part's box grown by 10 mm (far points, points beyond
// the edges, points past the dimple's centre of curvature), and "scan" = near
// points in the order a CMM measures them (lines of points 1 mm apart). The
// "in order" row projects each set as one sequence, each search hinted by
// the previous foot (ClosestPointFinder::project_in_order): on random order
// it shows what a useless hint costs, on the scan what a real one saves. Accuracy columns:
//   tangential  max |component of (q - foot) along the surface| at interior
//               feet [mm] (0 for an exact foot point);
//   vs oracle   max (distance - oracle distance) on a 400-point subset, the
//               oracle being a 600 x 600 sampling refined by a compass search;
//   worse       points where the other method found a nearer foot by > 1e-9 mm;
//   no answer   points where OCCT returned nothing or furrow did not converge;
//   on edge     of the "worse" points, those whose foot lies on the patch's
//               parameter boundary (u or v at 0 or 1).
//
// OpenCASCADE is run at its best too: the Tree algorithm restricted to minima
// (Extrema_ExtFlag_MIN), and its seeded local solver Extrema_GenLocateExtPS.
// The seeded rows give both libraries the same seed: for "near" and "far" points the
// (u,v) the point was generated from (what a CMM program's nominal point
// gives), for "box" points the nearest of 21 x 21 samples. Furrow's seeded
// row is ClosestPointFinder::project with that seed as hint: still a global
// search, the hint only orders the work. OCCT's seeded solver is local: it
// returns the extremum its iteration reaches from the seed.
#include <Extrema_GenLocateExtPS.hxx>
#include <Extrema_POnSurf.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "geometry/closest_point.hpp"
#include "io/part_file.hpp"

using namespace furrow;

namespace {

using Clock = std::chrono::steady_clock;

// Knot vector -> distinct values and multiplicities (OCCT's form).
void knots_and_mults(const std::vector<double>& knots, std::vector<double>& values,
                     std::vector<int>& mults) {
  for (double k : knots) {
    if (!values.empty() && k == values.back()) {
      ++mults.back();
    } else {
      values.push_back(k);
      mults.push_back(1);
    }
  }
}

Handle(Geom_BSplineSurface) to_occt(const NurbsSurface& s) {
  TColgp_Array2OfPnt poles(1, s.num_u(), 1, s.num_v());
  TColStd_Array2OfReal weights(1, s.num_u(), 1, s.num_v());
  for (int i = 0; i < s.num_u(); ++i)
    for (int j = 0; j < s.num_v(); ++j) {
      const Eigen::Vector3d& p = s.control_point(i, j);
      poles.SetValue(i + 1, j + 1, gp_Pnt(p.x(), p.y(), p.z()));
      weights.SetValue(i + 1, j + 1, s.weight(i, j));
    }
  std::vector<double> ku, kv;
  std::vector<int> mu, mv;
  knots_and_mults(s.knots_u(), ku, mu);
  knots_and_mults(s.knots_v(), kv, mv);
  TColStd_Array1OfReal aku(1, static_cast<int>(ku.size())), akv(1, static_cast<int>(kv.size()));
  TColStd_Array1OfInteger amu(1, static_cast<int>(mu.size())), amv(1, static_cast<int>(mv.size()));
  for (std::size_t k = 0; k < ku.size(); ++k) {
    aku.SetValue(static_cast<int>(k) + 1, ku[k]);
    amu.SetValue(static_cast<int>(k) + 1, mu[k]);
  }
  for (std::size_t k = 0; k < kv.size(); ++k) {
    akv.SetValue(static_cast<int>(k) + 1, kv[k]);
    amv.SetValue(static_cast<int>(k) + 1, mv[k]);
  }
  return new Geom_BSplineSurface(poles, weights, aku, akv, amu, amv, s.degree_u(), s.degree_v());
}

struct Foot {
  bool found = false;
  double distance = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

// Oracle: dense sampling, then a compass search from the best sample.
double oracle_distance(const NurbsSurface& s, const std::vector<Eigen::Vector3d>& grid, int n,
                       const Eigen::Vector3d& q) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < grid.size(); ++k)
    if ((grid[k] - q).squaredNorm() < (grid[best] - q).squaredNorm()) best = k;
  Eigen::Vector2d uv(static_cast<double>(best / (n + 1)) / n,
                     static_cast<double>(best % (n + 1)) / n);
  double f = (grid[best] - q).squaredNorm();
  for (double step = 1.0 / n; step > 1e-15;) {
    bool moved = false;
    for (const Eigen::Vector2d& d : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-1, 0),
                                     Eigen::Vector2d(0, 1), Eigen::Vector2d(0, -1)}) {
      const Eigen::Vector2d p = (uv + step * d).cwiseMax(0.0).cwiseMin(1.0);
      const double fp = (s.point(p.x(), p.y()) - q).squaredNorm();
      if (fp < f) {
        f = fp;
        uv = p;
        moved = true;
      }
    }
    if (!moved) step *= 0.5;
  }
  return std::sqrt(f);
}

double tangential(const Face& face, const Eigen::Vector3d& q, const Eigen::Vector2d& uv) {
  const DifferentialGeometry g = face.geometry(uv.x(), uv.y());
  const Eigen::Vector3d r = q - g.point;
  return (r - r.dot(g.normal) * g.normal).norm();
}

template <class F>
double best_seconds(int repeats, F&& run) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    run();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

void report(const char* name, double seconds, std::size_t n, const std::vector<Foot>& feet,
            const std::vector<Foot>& other, const Face& face,
            const std::vector<Eigen::Vector3d>& pts, const std::vector<double>& oracle) {
  double tang = 0, vs_oracle = -1e300;
  int worse = 0, on_edge = 0, missing = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!feet[k].found) {
      ++missing;
      continue;
    }
    const Eigen::Vector2d& uv = feet[k].uv;
    if (uv.x() > 0 && uv.x() < 1 && uv.y() > 0 && uv.y() < 1)
      tang = std::max(tang, tangential(face, pts[k], uv));
    if (other[k].found && other[k].distance < feet[k].distance - 1e-9) {
      ++worse;
      if (uv.x() <= 0 || uv.x() >= 1 || uv.y() <= 0 || uv.y() >= 1) ++on_edge;
    }
    if (k < oracle.size()) vs_oracle = std::max(vs_oracle, feet[k].distance - oracle[k]);
  }
  std::printf(
      "  %-38s %9.0f pts/s  %8.2f us/pt  tangential %.1e  vs oracle %+.1e  worse %5d (on edge "
      "%5d)  no answer %5d\n",
      name, n / seconds, 1e6 * seconds / n, tang, vs_oracle, worse, on_edge, missing);
}

}  // namespace

int main() {
  const Part part = read_part(std::string(FURROW_SOURCE_DIR) + "/examples/parts/mould.json");
  const Face& face = part.faces[0];
  const std::size_t count = 20000;
  const int oracle_points = 400, oracle_grid = 600;

  auto t0 = Clock::now();
  const ClosestPointFinder finder(part);
  const double build = std::chrono::duration<double>(Clock::now() - t0).count();
  const Handle(Geom_BSplineSurface) occt = to_occt(face.surface());

  std::vector<Eigen::Vector3d> grid;
  for (int i = 0; i <= oracle_grid; ++i)
    for (int j = 0; j <= oracle_grid; ++j)
      grid.push_back(face.surface().point(static_cast<double>(i) / oracle_grid,
                                          static_cast<double>(j) / oracle_grid));
  // Same surface in both libraries?
  double same = 0;
  for (int k = 0; k < 1000; ++k) {
    const double u = (k % 37) / 36.0, v = (k % 29) / 28.0;
    const gp_Pnt p = occt->Value(u, v);
    same =
        std::max(same, (face.surface().point(u, v) - Eigen::Vector3d(p.X(), p.Y(), p.Z())).norm());
  }
  std::printf("mould.json bicubic 21x17; %zu points per set, single thread, best of 3\n", count);
  std::printf("seed grid: %zu cells, built in %.2f ms; max |S_furrow - S_occt| = %.1e mm\n\n",
              finder.cell_count(), 1e3 * build, same);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1), offset(-3, 3);
  const Eigen::AlignedBox3d box = part.control_box();
  for (const char* set : {"near (+-3 mm along the normal)", "far (+-20 mm along the normal)",
                          "box (part box grown by 10 mm)",
                          "scan (+-3 mm, in measurement order: 100 lines of 200 points)"}) {
    const bool near = set[0] != 'b';
    const bool scan = set[0] == 's';
    const double reach = set[0] == 'f' ? 20.0 / 3.0 : 1.0;  // scales offset (+-3 mm)
    std::vector<Eigen::Vector3d> pts(count);
    std::vector<Eigen::Vector2d> seeds(count);  // for the seeded rows (see the header comment)
    for (std::size_t k = 0; k < count; ++k) {
      Eigen::Vector3d& q = pts[k];
      if (scan) {  // lines along u, the offset drifting smoothly as a real scan's does
        const std::size_t line = k / 200, along = k % 200;
        const double u = (along + 0.5) / 200, v = (line + 0.5) / 100;
        const DifferentialGeometry g = face.geometry(u, v);
        q = g.point + 3.0 * std::sin(0.05 * static_cast<double>(along) + 0.7 * line) * g.normal;
        seeds[k] = Eigen::Vector2d(u, v);
      } else if (near) {
        const double u = unit(rng), v = unit(rng);
        const DifferentialGeometry g = face.geometry(u, v);
        q = g.point + reach * offset(rng) * g.normal;
        seeds[k] = Eigen::Vector2d(u, v);
      } else {
        const Eigen::Vector3d lo = box.min().array() - 10, hi = box.max().array() + 10;
        q = lo + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(hi - lo);
      }
    }
    std::vector<double> oracle(oracle_points);
    for (int k = 0; k < oracle_points; ++k)
      oracle[k] = oracle_distance(face.surface(), grid, oracle_grid, pts[k]);

    if (!near) {  // nearest of 21 x 21 samples
      const int n = 20, stride = oracle_grid / n;
      for (std::size_t k = 0; k < count; ++k) {
        double best = 1e300;
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= n; ++j) {
            const auto at = static_cast<std::size_t>(i * stride * (oracle_grid + 1) + j * stride);
            const double d = (grid[at] - pts[k]).squaredNorm();
            if (d < best) {
              best = d;
              seeds[k] = Eigen::Vector2d(static_cast<double>(i) / n, static_cast<double>(j) / n);
            }
          }
      }
    }

    std::vector<Foot> ours(count), seeded(count), grad(count), tree(count), tree_min(count),
        located(count);
    const double t_ours = best_seconds(3, [&] {
      for (std::size_t k = 0; k < count; ++k) {
        const ClosestPoint c = finder.project(pts[k]);
        ours[k] = {c.converged, c.distance, c.uv};
      }
    });
    // A fresh finder's first pass (each cube's list is built on its second
    // query, so this is mostly the tree walk) and the tree walk alone.
    std::vector<Foot> first(count), walked(count);
    const ClosestPointFinder fresh(part);
    const auto first_start = Clock::now();
    for (std::size_t k = 0; k < count; ++k) {
      const ClosestPoint c = fresh.project(pts[k]);
      first[k] = {c.converged, c.distance, c.uv};
    }
    const double t_first = std::chrono::duration<double>(Clock::now() - first_start).count();
    ClosestPointOptions walk_only;
    walk_only.candidate_voxels = false;
    const ClosestPointFinder walker(part, walk_only);
    const double t_walk = best_seconds(3, [&] {
      for (std::size_t k = 0; k < count; ++k) {
        const ClosestPoint c = walker.project(pts[k]);
        walked[k] = {c.converged, c.distance, c.uv};
      }
    });
    const double t_seeded = best_seconds(3, [&] {
      for (std::size_t k = 0; k < count; ++k) {
        ClosestPoint hint;
        hint.face = 0;
        hint.uv = seeds[k];
        hint.point = face.surface().point(seeds[k].x(), seeds[k].y());
        const ClosestPoint c = finder.project(pts[k], hint);
        seeded[k] = {c.converged, c.distance, c.uv};
      }
    });
    std::vector<Foot> in_order(count);
    const double t_in_order = best_seconds(3, [&] {
      const std::vector<ClosestPoint> feet = finder.project_in_order(pts);
      for (std::size_t k = 0; k < count; ++k) in_order[k] = {feet[k].converged, feet[k].distance, feet[k].uv};
    });
    double t_ours_mt = best_seconds(3, [&] {
#pragma omp parallel for schedule(dynamic, 256) num_threads(2)
      for (std::size_t k = 0; k < count; ++k) finder.project(pts[k]);
    });
    auto run_occt = [&](Extrema_ExtAlgo algo, Extrema_ExtFlag flag, std::vector<Foot>& out) {
      GeomAPI_ProjectPointOnSurf proj;
      proj.Init(occt, 0, 1, 0, 1, algo);
      proj.SetExtremaFlag(flag);
      for (std::size_t k = 0; k < count; ++k) {
        proj.Perform(gp_Pnt(pts[k].x(), pts[k].y(), pts[k].z()));
        Foot f;
        if (proj.IsDone() && proj.NbPoints() > 0) {
          f.found = true;
          f.distance = proj.LowerDistance();
          proj.LowerDistanceParameters(f.uv.x(), f.uv.y());
        }
        out[k] = f;
      }
    };
    const double t_grad =
        best_seconds(3, [&] { run_occt(Extrema_ExtAlgo_Grad, Extrema_ExtFlag_MINMAX, grad); });
    const double t_tree =
        best_seconds(3, [&] { run_occt(Extrema_ExtAlgo_Tree, Extrema_ExtFlag_MINMAX, tree); });
    const double t_tree_min =
        best_seconds(3, [&] { run_occt(Extrema_ExtAlgo_Tree, Extrema_ExtFlag_MIN, tree_min); });
    const GeomAdaptor_Surface adaptor(occt);
    const double t_located = best_seconds(3, [&] {
      Extrema_GenLocateExtPS locate(adaptor);
      for (std::size_t k = 0; k < count; ++k) {
        locate.Perform(gp_Pnt(pts[k].x(), pts[k].y(), pts[k].z()), seeds[k].x(), seeds[k].y());
        Foot f;
        if (locate.IsDone()) {
          f.found = true;
          f.distance = std::sqrt(locate.SquareDistance());
          locate.Point().Parameter(f.uv.x(), f.uv.y());
        }
        located[k] = f;
      }
    });

    std::printf("%s\n", set);
    report("furrow ClosestPointFinder", t_ours, count, ours, tree_min, face, pts, oracle);
    report("furrow, first pass, fresh finder", t_first, count, first, tree_min, face, pts, oracle);
    report("furrow, tree walk only (no voxel lists)", t_walk, count, walked, tree_min, face, pts, oracle);
    report("furrow, seeded (global)", t_seeded, count, seeded, tree_min, face, pts, oracle);
    report("furrow, in order (previous foot hints)", t_in_order, count, in_order, tree_min, face,
           pts, oracle);
    report("OCCT ProjectPointOnSurf (Grad)", t_grad, count, grad, ours, face, pts, oracle);
    report("OCCT ProjectPointOnSurf (Tree)", t_tree, count, tree, ours, face, pts, oracle);
    report("OCCT ProjectPointOnSurf (Tree, MIN)", t_tree_min, count, tree_min, ours, face, pts,
           oracle);
    report("OCCT GenLocateExtPS (seeded, local)", t_located, count, located, ours, face, pts,
           oracle);
    std::printf(
        "  furrow vs OCCT at its best: %.1fx Tree+MIN, seeded %.1fx GenLocateExtPS; furrow on 2 "
        "threads %.0f pts/s\n\n",
        t_tree_min / t_ours, t_located / t_seeded, count / t_ours_mt);
  }

  // A registration's load: a million far points, projected again at every
  // outer iteration. Each pass in full, on a fresh finder; the tree walk
  // alone alongside.
  {
    const std::size_t million = 1000000;
    std::uniform_real_distribution<double> unit(0, 1), offset(-20, 20);
    std::vector<Eigen::Vector3d> pts(million);
    for (Eigen::Vector3d& q : pts) {
      const double u = unit(rng), v = unit(rng);
      const DifferentialGeometry g = face.geometry(u, v);
      q = g.point + offset(rng) * g.normal;
    }
    ClosestPointOptions walk_only;
    walk_only.candidate_voxels = false;
    std::printf("1 000 000 far points (+-20 mm), each pass timed in full on a fresh finder:\n");
    for (const bool lists : {true, false}) {
      const ClosestPointFinder fresh(part, lists ? ClosestPointOptions{} : walk_only);
      std::printf("  %-38s", lists ? "furrow" : "furrow, tree walk only");
      double sum = 0;  // printed: the same answers either way
      for (int pass = 1; pass <= 3; ++pass) {
        const auto start = Clock::now();
        for (const Eigen::Vector3d& q : pts) sum += fresh.project(q).distance;
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        std::printf("  pass %d %8.0f pts/s", pass, million / seconds);
      }
      std::printf("  (sum of distances %.9g mm)\n", sum);
    }
  }
  return 0;
}
