#pragma once
// Cells of one face's curvature field grouped into regions.
//
// Each valid cell gets its curvature class (classification.hpp, tolerance
// eps); trimmed and degenerate cells get none and never join a region.
// Regions are the 4-connected components of equal class: two cells that touch
// only at a corner are not connected, so a region's border is a set of simple
// closed loops along cell edges (region_boundary.hpp) and never a single
// point. Labels are numbered by the first cell of each region in raster order
// (i along u outer, j along v inner), independent of how the components were
// found, so labels are deterministic.
#include <vector>

#include "partition/classification.hpp"
#include "partition/curvature_field.hpp"

namespace furrow {

// Codes of cells that belong to no region (class codes are 0..3).
constexpr unsigned char kTrimmedCell = 255;
constexpr unsigned char kDegenerateCell = 254;

struct RegionLabels {
  int nu = 0, nv = 0;
  std::vector<int> label;                    // per cell, i * nv + j; -1 = no region
  std::vector<CurvatureClass> region_class;  // per label
  std::vector<int> components;               // per label: connected components merged into it

  int count() const { return static_cast<int>(region_class.size()); }
  int at(int i, int j) const { return label[static_cast<std::size_t>(i) * nv + j]; }
};

// Class code (CurvatureClass as an integer) per cell, kTrimmedCell or
// kDegenerateCell for cells that are not valid. Precondition: eps >= 0.
std::vector<unsigned char> classify_cells(const CurvatureField& field, double eps);

// Connected components of equal class code (OpenCV on per-class masks).
// Precondition: cell_class.size() == nu * nv.
RegionLabels connected_regions(const std::vector<unsigned char>& cell_class, int nu, int nv);

// Renumbers labels by first occurrence in raster order, dropping unused ones;
// region_class and components follow. Used after every relabelling step.
void renumber_in_raster_order(RegionLabels& labels);

}  // namespace furrow
