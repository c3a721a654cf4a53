#pragma once
// plan.qif: the inspection plan as a QIF 3.0 document (docs/qif.md "Plan"):
// every planned point as a PointFeatureNominal (Location = the nominal
// contact point, Normal = its unit normal) with its PointFeatureItem named
// by the point id, and the surface profile characteristic over all of them
// (Definition with the zone width as ToleranceValue and, for a zone that is
// not bilateral, OuterDisposition = the part of the zone on the + side;
// Nominal; Item listing every point's feature item). The probing sequence
// itself stays in the DMIS and I++ DME programs next to it.
#include <string>

#include "io/plan_file.hpp"

namespace furrow {

// `tolerance` is the zone width [mm] (> 0), `outside` the part of it on the
// material-added side [mm], 0..tolerance (docs/verification.md).
std::string plan_to_qif(const InspectionPlan& plan, const std::string& part_name, double tolerance,
                        double outside);

}  // namespace furrow
