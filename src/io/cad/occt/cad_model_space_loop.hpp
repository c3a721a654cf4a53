#pragma once
// A face's outer loop on a periodic surface built from its boundary's 3-D
// curves, for IGES boundaries given in model space only (type 142 without a
// parameter-space curve; docs/formats.md "CAD import", "IGES boundaries").
//
// Why: OpenCASCADE projects such curves itself, and on a periodic surface
// (a type 120 surface of revolution: sphere, cylinder, torus; a periodic
// B-spline) it may put pieces of the loop in different periods or route its
// pole edges around the other side; a CATIA file whose quarter spheres all
// came in 1.25 to 3.3 times too large had only such boundaries.
//
// model_space_loop() replaces the outer wire's curves by the projections of
// its edges' 3-D curves (cad_projected_curve.hpp), each continuous, and
// joins them: where two pieces meet at a point that is not a pole the next
// piece is put in the period that continues the previous one; where they
// meet at a pole (on a sphere of revolution), the periodic parameter jumps
// by whatever the loop needs, and every jump by whole periods is tried. A
// candidate loop must close in the parameter plane (a loop that winds around
// the surface is not one) and span at most one period. The region is the
// one the candidate encloses in the plane. A face holds its holes: where
// several candidates close, only those whose region holds a point of every
// hole (`holes`, in the surface's (u,v), any period) are kept, when any is
// (a lune from pole to pole with a hole in it is the lune, wherever its
// meridians lie). Of those, the candidate is:
// 1. the only one, when there is one (every loop that does not run from
//    pole to pole: zones, caps, bands, patches across the seam);
// 2. else (a lune from pole to pole, which encloses one side of the sphere
//    or the other) the only one lying within the file's own parameter
//    rectangle, the surface's angles from start to terminate (an IGES
//    trimmed surface is the region its boundary encloses in that rectangle,
//    IGES 5.3 type 144);
// 3. else (a lune with a meridian on the seam, or across it) the one the
//    file's loop runs counterclockwise around in the surface's (u,v): the
//    region on its left seen from the side the surface's normal points to,
//    as B-rep faces have it. The file's direction is all that tells such a
//    lune from the rest of the sphere.
// Pole edges run straight along the pole line between their neighbours.
//
// `turned` says the chosen loop runs clockwise (as walked on the face):
// the face encloses its region on the other side than OpenCASCADE's face,
// whose boundary runs counterclockwise around its region seen from its
// normal, so the face's normal must be turned for its edges to run as its
// neighbours' do in a sewn shell.
//
// Returns false (the wire untouched) when the wire gives no such loop: more
// than 5 pole passages, no edge with a 3-D curve, or no candidate closes.
#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <Eigen/Core>
#include <vector>

#include "io/cad/occt/cad_face_trims.hpp"
#include "io/cad/occt/cad_iges_boundary.hpp"

namespace furrow::cad {

// `wire.edges` carry each edge's `projected` curve (degenerate edges none);
// `face_reversed`: the face is REVERSED (its wires are walked against the file's loop);
// `holes`: one point on each of the face's other wires, in (u,v).
bool model_space_loop(WireUse& wire, const Handle(Geom_Surface)& surface, const Periods& periods,
                      const FileBoundary& file, bool face_reversed, const std::vector<Eigen::Vector2d>& holes,
                      bool& turned);

}  // namespace furrow::cad
