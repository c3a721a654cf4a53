#include "stage/toolpath_stage.hpp"

#include <cstdio>
#include <filesystem>

namespace furrow {

GeneratedToolpath generate_toolpath(const Part& part, const std::string& part_path, const Cutter& cutter,
                                    const ToolpathGeneration& options,
                                    const std::function<void(std::size_t, std::size_t)>& progress) {
  GeneratedToolpath out;
  out.plan = plan_contact_points(part, cutter, options.direction, options.contacts, progress);
  char header[256];
  std::snprintf(header, sizeof header, "furrow toolpath %s: direction %s, %s steps, tolerance %g mm, scallop %g mm",
                std::filesystem::path(part_path).filename().c_str(), to_string(options.direction).c_str(),
                to_string(options.contacts.forward.rule), options.contacts.forward.tolerance, options.contacts.scallop);
  out.gcode = plan_gcode(out.plan, cutter, header, options.write);
  out.contacts_csv = plan_contact_csv(part, out.plan);
  return out;
}

}  // namespace furrow
