#pragma once
// Evaluation of a NurbsSurface on a tensor grid u_i (i < nu) x v_j (j < nv),
// one grid row (fixed j, every i) at a time.
//
// Why: field computations (curvature field, error map) sample a face on a
// regular grid, millions of points. NurbsSurface::evaluate recomputes both
// basis-function triangles (with their divisions) and the full (p+1)x(q+1)
// contraction at every point. On a grid the u basis only depends on i and the
// v basis only on j, so here
//   - the span and the p+1 basis values and derivatives are computed once per
//     grid column u_i (constructor) and once per grid row v_j (evaluate_row);
//   - a row first contracts every control column c with the v basis,
//     T_c = sum_l N_l(v_j) Pw(c, span_v - q + l) (and its v derivatives), once
//     per row; each point then only contracts p+1 of those with its u basis.
// Inner loops have compile-time lengths for degrees 1 to 5.
//
// Contract: the result at (u_i, v_j) is bit-for-bit what
// NurbsSurface::evaluate(u_i, v_j, order) returns: the same basis routine, the
// same summation order (v first, then u) and the same quotient rule (Piegl &
// Tiller eq. 4.20), so switching a caller to the grid cannot change its output.
// Parameters outside the domain are clamped, as evaluate does. Derivatives are
// exact (analytic), with respect to u and v; entries above `order` stay zero.
// The surface must outlive the grid. evaluate_row allocates nothing per point:
// the caller owns the output row and a scratch object (one per thread).
#include <vector>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

// Per-thread working storage of SurfaceGrid::evaluate_row (reused across rows).
struct SurfaceGridScratch {
  std::vector<Eigen::Vector4d> columns;  // v-contracted control columns
};

class SurfaceGrid {
 public:
  // `order` in {0, 1, 2} (clamped). u and v may have any length >= 1 and need
  // not be sorted or uniform.
  SurfaceGrid(const NurbsSurface& surface, std::vector<double> u, std::vector<double> v,
              int order = 2);

  int nu() const { return static_cast<int>(u_.size()); }
  int nv() const { return static_cast<int>(v_.size()); }
  int order() const { return order_; }
  double u(int i) const { return u_[i]; }
  double v(int j) const { return v_[j]; }

  // Writes the point and derivatives at (u_i, v_j) to out[i] for i < nu().
  // Precondition: 0 <= j < nv(), out has room for nu() entries.
  void evaluate_row(int j, SurfaceDerivatives* out, SurfaceGridScratch& scratch) const;

 private:
  const NurbsSurface* surface_;
  std::vector<double> u_, v_;
  int order_;
  std::vector<Eigen::Vector4d> net_;  // homogeneous control net, i * num_v + j
  std::vector<int> span_u_;       // per grid column
  std::vector<double> basis_u_;   // per grid column: 3 x (p+1), value, 1st, 2nd derivative
  int first_column_ = 0, last_column_ = 0;  // control columns any grid column touches
};

}  // namespace furrow
