#pragma once
// The volume and centre of mass of the solid a part's faces bound, from the
// faces alone by the divergence theorem (docs/cmm.md "Setups": a part rests
// stably on a face only when its centre of mass stands over that face):
//   V        = (1/3) \oint x . n dA
//   V c_i    = (1/2) \oint x_i^2 n_i dA        (no sum over i)
// with n the outward normal (Face honours `reversed`). Uniform density.
//
// Quadrature: each face's parameter rectangle is cut into 48 x 48
// cells, each integrated by 2 x 2 Gauss-Legendre points (exact for a plane,
// whose integrand is quadratic in u, v); a cell a trim loop crosses is
// integrated instead as 6 x 6 subcells, each kept or not
// by the trim at its centre (and then by 2 x 2 Gauss points). The error is
// the trim's stair step on those subcells: about (cell / 6) x the
// trim's length per face, none where trim edges run along subcell edges.
//
// The result is only a solid's when the faces close: `closed` says that
// the vector area \oint n dA is near zero (within 1e-6 of the total area,
// plus what the quadrature leaves on trimmed cells: 1e-3) and the volume
// positive. For an open shell or faces turned into the material there is no
// centre of mass to speak of, and callers do not use it.
//
// Units: mm, mm^3. Deterministic (a fixed order of summation). Pure.
#include <Eigen/Core>

#include "geometry/part.hpp"

namespace furrow {

struct SolidMass {
  double volume = 0;                                    // [mm^3]
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();   // [mm], part frame
  double area = 0;                                      // the faces' total area [mm^2]
  double vector_area = 0;                               // |\oint n dA| [mm^2]: 0 for a closed surface
  bool closed = false;                                  // the faces bound a solid (see above)
};

SolidMass solid_mass(const Part& part);

}  // namespace furrow
