#pragma once
// The compensation stage (`furrow compensate`): a measured part's error
// field taken off the G-code program that cut it (docs/compensation.md).
// One function for the command and for later callers (a job's stage).
//
// Steps: the error field from the comparison (with the prediction removed
// when the comparison has one), the program's tips located on the part and
// offset by -gain x field (clipped to max_offset, cut back where the moved
// surface would gouge locally), the program written again with only those
// words changed (io/machining/gcode_rewrite.hpp), and the written program
// read back and checked with a z-map against the original
// (docs/compensation.md "Writing the program": the z-map check). `safe`
// false means the caller must write nothing.
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/comparison_error_field.hpp"
#include "io/machining/gcode_rewrite.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/cutter/path_tools.hpp"
#include "stage/compensate_options.hpp"

namespace furrow {

// The written program cut against the original, node by node of a z-map
// over where tips moved: a node the compensated program cuts lower than the
// original by more than the offset of the move that cuts it (along the
// surface's normal, so divided by its n_z) plus `tolerance` is a gouge the
// compensation would add. Nodes at the rim of the swept region or where
// the machined surface is steeper than n_z = 0.2 are not judged (counted).
struct CompensationGougeCheck {
  double resolution = 0;        // z-map node spacing [mm]
  double tolerance = 0;         // allowed beyond the offset [mm]
  std::size_t nodes = 0;        // nodes both programs cut
  std::size_t not_judged = 0;   // of those: at the rim or too steep
  std::size_t deeper = 0;       // nodes beyond the allowance
  double worst_excess = 0;      // [mm] the largest excess (0 when none)
  Eigen::Vector3d worst = Eigen::Vector3d::Zero();  // where [mm]
  int worst_line = 0;           // line of the compensated program cutting it there
  bool safe() const { return deeper == 0; }
};

struct CompensatedProgram {
  ComparisonErrorField field;
  PathOffset offset;
  GcodeRewrite program;
  CompensationGougeCheck check;
  std::string json;  // COMP.json's text
};

struct CompensationSources {
  std::string part, comparison, toolpath, out;
};

// `program_text` is the G-code of `tools`' path as read with `read`. Throws
// InputError for a program that changes tools, a comparison of another
// part, or options out of range (naming them).
CompensatedProgram compensate_stage(const Part& part, const PathTools& tools, const std::string& program_text,
                                    const ToolpathReadOptions& read, const ComparisonDocument& comparison,
                                    const CompensateOptions& options, const CompensationSources& names);

}  // namespace furrow
