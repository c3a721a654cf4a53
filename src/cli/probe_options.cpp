#include "cli/probe_options.hpp"

#include "base/error.hpp"

namespace furrow::cli {

void read_probe_motion_options(Args& args, PlannerOptions& o) {
  o.stylus_length = args.number_or("stylus-length", o.stylus_length);
  o.stylus_diameter = args.number_or("stylus-diameter", o.stylus_diameter);
  o.approach = args.number_or("approach", o.approach);
  o.retract = args.number_or("retract", o.retract);
  o.search = args.number("search");
  o.clearance = args.number_or("clearance", o.clearance);
  o.max_tilt_degrees = args.number_or("max-tilt", o.max_tilt_degrees);
}

void read_program_options(Args& args, PlannerOptions& o) {
  o.program.revision = args.option_or("revision", o.program.revision);
  o.program.date = args.option_or("program-date", o.program.date);
  if (const auto h = args.number("head-length")) o.program.head_length = *h;
}

void read_datum_option(Args& args, PlannerOptions& o) {
  if (const auto d = args.option("datums")) {
    try {
      o.datums = parse_datum_choice(*d, "--datums");
    } catch (const InputError& e) {
      args.fail(e.what());
    }
  }
}

}  // namespace furrow::cli
