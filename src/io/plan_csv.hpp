#pragma once
// plan.csv: the points of a plan as a table for spreadsheets and CMM
// software that imports point lists (docs/formats.md "plan.csv").
//
//   # Furrow probe plan: part PART, probe NAME diameter D mm, N points, units mm
//   order,id,face,face_index,region,u,v,x,y,z,i,j,k,approach_x,...,retract_z
//
// One row per point in execution order; numbers in their shortest exact
// text (reading them gives back the plan's doubles); `region` is empty for a
// point without one. Face names are quoted when they hold a comma or a quote.
// A plan with a part alignment lists the alignment points first, in the
// order the programs measure them, and adds a last column `feature`:
// DATUM_A, DATUM_B, DATUM_C (the datum the point belongs to), MANUAL (a
// manual best-fit point) or FREE_FORM; `order` counts within each part, as
// in plan.json.
#include <string>

#include "io/plan_file.hpp"

namespace furrow {

std::string plan_to_csv_text(const InspectionPlan& plan);

}  // namespace furrow
