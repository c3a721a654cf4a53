#pragma once
// Regions merged across faces: a fillet chain, a blend across the patch
// seams of a B-spline surface, a cylinder that CAD splits into two halves
// are one surface to a metrologist, but several faces to the partition.
// Regions on different faces are put in one group when they have the same
// class and meet tangentially (G1) along the edge they share; the groups
// are the transitive closure of that relation (union-find), every region in
// exactly one group (alone when nothing joins it).
//
// How an edge is found and judged: each face's boundary (its trim loops, or
// its parameter rectangle) is sampled about every four partition cells
// along the surface; a sample shares an edge with another face when its
// nearest point on the other faces (ClosestPointFinder, exact) lies within
// `gap`; it is tangent there when the two outward normals differ by at most
// `max_angle`. Two regions join when the tangent part is at least
// `min_tangent_fraction` of the edge they share (and at least two samples
// long), so a corner where they merely touch, or a crease, does not join
// them. The region a boundary sample belongs to is that of the nearest
// labelled cell within two cells of it (cells along a trim are labelled by
// their centre, which can be trimmed away).
//
// Deterministic: groups are numbered by their smallest region id.
#include "geometry/part.hpp"
#include "partition/partition.hpp"

namespace furrow {

struct RegionGroupOptions {
  double gap = 0.01;                  // [mm] faces closer than this share an edge (CAD and sewing tolerances)
  double max_angle = 1.0;             // [degrees] between the faces' normals for a tangent join
  double min_tangent_fraction = 0.25; // of the shared edge that must be tangent
};

// Fills Region::group of every region of `result.map` and result.map.groups.
// Throws InputError for a non-finite or non-positive option.
void group_regions_across_faces(const Part& part, PartitionResult& result, const RegionGroupOptions& options = {});

}  // namespace furrow
