#pragma once
// Exact rational NURBS patches of elementary surfaces: circular arcs, planes,
// cylinders, spheres, tori and general surfaces of revolution.
//
// Used by tests as analytic references (every evaluated point lies exactly on
// the primitive up to rounding) and wherever an exact elementary patch is
// needed. Arcs are split into pieces of at most 90 degrees, each a rational
// quadratic with middle weight cos(half angle) (Piegl & Tiller A7.1).
//
// Orientation (which way Su x Sv points) is stated for each builder; a Face
// with `reversed` flips it.
#include <Eigen/Geometry>
#include <vector>

#include "geometry/nurbs_surface.hpp"

namespace furrow {

// Degree-2 rational curve in a plane, parameter range [0, 1].
struct RationalCurve2d {
  int degree = 2;
  std::vector<double> knots;
  std::vector<Eigen::Vector2d> points;
  std::vector<double> weights;
};

// Arc of a circle of `radius` centred at the origin from angle a0 to a1
// (radians, counter-clockwise when a1 > a0); |a1 - a0| <= 2 pi.
RationalCurve2d make_circular_arc(double radius, double a0, double a1);

// Surface of revolution about the z axis: the profile curve's 2-D point
// (r, z) is swept from longitude phi0 to phi1. u runs along the longitude,
// v along the profile. With profile tangent (dr, dz), Su x Sv is along
// dz e_r - dr e_z: away from the axis where the profile goes up in z.
NurbsSurface make_revolution(const RationalCurve2d& profile, double phi0, double phi1);

// Cylinder of `radius` about the y axis, y in [0, length], angle theta in
// [a0, a1] measured in the x-z plane from +x toward +z: points
// (R cos t, y, R sin t). u along theta, v along y. Su x Sv points toward the
// axis, so the unreversed face is the inside of a tube (concave).
NurbsSurface make_cylinder(double radius, double length, double a0, double a1);

// Sphere of `radius` centred at the origin: longitude phi in [phi0, phi1],
// latitude lambda in [lat0, lat1] (radians, -pi/2..pi/2). u along longitude,
// v along latitude. Su x Sv points away from the centre (unreversed = convex).
NurbsSurface make_sphere(double radius, double phi0, double phi1, double lat0, double lat1);

// Torus about the z axis: tube centre circle of radius `major`, tube radius
// `minor`; longitude phi in [phi0, phi1], tube angle psi in [psi0, psi1] with
// psi = 0 on the outer equator and psi = pi/2 on top. Su x Sv points away from
// the tube's centre circle (unreversed = the outside of the ring).
NurbsSurface make_torus(double major, double minor, double phi0, double phi1, double psi0,
                        double psi1);

// Plane patch origin + s e_u + t e_v, s, t in [0, 1]; Su x Sv = e_u x e_v.
NurbsSurface make_plane(const Eigen::Vector3d& origin, const Eigen::Vector3d& e_u,
                        const Eigen::Vector3d& e_v);

// Bilinear patch through four corners p00 (u=0,v=0), p10, p01, p11.
NurbsSurface make_bilinear(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10,
                           const Eigen::Vector3d& p01, const Eigen::Vector3d& p11);

// The same surface moved rigidly (control points transformed, weights kept:
// NURBS are invariant under affine maps).
NurbsSurface transformed(const NurbsSurface& surface, const Eigen::Isometry3d& motion);

}  // namespace furrow
