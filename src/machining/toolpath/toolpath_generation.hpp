#pragma once
// A contact plan (contact_planning.hpp) as files: G-code of the tool tips
// (toolpath_file.hpp's writer: a rapid to a safe height between passes,
// G1 along each pass) and the contact points as CSV, one row per point with
// its pass, position, unit normal, face and (u, v), readable by
// read_toolpath() (docs/formats.md "Contact-point CSV"). Face names with
// commas, '#', line breaks or surrounding blanks cannot be written (InputError).
#include <string>

#include "io/machining/toolpath_file.hpp"
#include "machining/toolpath/contact_planning.hpp"

namespace furrow {

struct ToolpathWriteOptions {
  double clearance = 5.0;  // [mm] safe height above the highest tip for rapids
  double feed = 1000;      // [mm/min]
};

// The plan's tips as a tool path (one pass per planned pass, in order).
Toolpath plan_tips(const ContactPlan& plan);

std::string plan_gcode(const ContactPlan& plan, const Cutter& cutter, const std::string& header,
                       const ToolpathWriteOptions& options = {});
std::string plan_contact_csv(const Part& part, const ContactPlan& plan);

}  // namespace furrow
