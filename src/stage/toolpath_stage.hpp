#pragma once
// The tool-path stage (`furrow toolpath`, and `furrow run` when the job
// generates its path): contact points planned on the part, written as the
// G-code of the tool tips and a CSV of the contact points. One function for
// both callers, so the G-code a job generates is the command's, byte for
// byte (the header included).
#include <cstddef>
#include <functional>
#include <string>

#include "machining/toolpath/contact_planning.hpp"
#include "machining/toolpath/toolpath_generation.hpp"

namespace furrow {

// Options of a generated finishing path.
struct ToolpathGeneration {
  PassDirectionSpec direction;
  ContactPlanOptions contacts;  // tolerance, rule, max step, scallop
  ToolpathWriteOptions write;   // clearance, feed
};

struct GeneratedToolpath {
  ContactPlan plan;
  std::string gcode;         // tool tips; its header names the part file and the options
  std::string contacts_csv;  // contact points with normals
};

// `part_path` is the part file as the user named it (only its file name goes
// into the G-code header). Throws InputError for options the planner refuses.
GeneratedToolpath generate_toolpath(const Part& part, const std::string& part_path, const Cutter& cutter,
                                    const ToolpathGeneration& options,
                                    const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace furrow
