#pragma once
// The compensation stage (`furrow compensate`): a measured part's error
// field taken off the program (G-code or APT CL) that cut it
// (docs/compensation.md).
// One function for the command and for later callers (a job's stage).
//
// Steps: the error field from the comparison (with the prediction removed
// when the comparison has one), the program's tips located on the part and
// offset by -gain x field (clipped to max_offset, cut back where the moved
// surface would gouge locally), the program written again with only those
// values changed (io/machining/gcode_rewrite.hpp, apt_rewrite.hpp), and the
// written program read back and checked with a z-map against the original
// (machining/compensation/zmap_check.hpp). Where the check fails, the
// clip-back: the offsets of both ends of every move it blames are halved
// (recomputed exactly, machining/compensation/path_offset.hpp
// reduce_offset), the program written and checked again, at most
// options.clip_back rounds (docs/compensation.md "Safety"). `safe` false
// at the end means the caller must write nothing.
#include <optional>
#include <string>
#include <vector>

#include "geometry/part.hpp"
#include "inspection/comparison_document.hpp"
#include "inspection/comparison_error_field.hpp"
#include "inspection/compensation_expectation.hpp"
#include "io/machining/program_rewrite.hpp"
#include "machining/compensation/path_offset.hpp"
#include "machining/compensation/rework_check.hpp"
#include "machining/compensation/rework_selection.hpp"
#include "machining/compensation/zmap_check.hpp"
#include "machining/cutter/path_tools.hpp"
#include "stage/compensate_options.hpp"
#include "stage/predict_stage.hpp"

namespace furrow {

// A point whose offset the clip-back reduced: the offset offset_path
// applied and the one written, after `rounds` halvings.
struct ClipBackPoint {
  std::size_t pass = 0, point = 0;
  int line = 0;
  double requested = 0;  // [mm] before the clip-back
  double applied = 0;    // [mm] written
  int rounds = 0;
};

// A rework program (options.rework; docs/compensation.md "Rework"): the
// stretches of the compensated path over material left beyond the
// threshold, written and checked. Empty `text` when nothing needs
// re-cutting (the caller writes nothing and says so).
struct ReworkProgram {
  double threshold = 0;            // [mm] used
  bool threshold_given = false;    // false: the comparison's upper tolerance limit
  ReworkSelection selection;
  std::string text;                // the program; empty when no stretch
  ReworkCheck check;               // of `text` read back
};

// The program formats compensation writes back.
enum class ProgramFormat { gcode, apt };

struct CompensatedProgram {
  ComparisonErrorField field;
  PathOffset offset;          // as written (after the clip-back)
  ProgramRewrite program;     // the last program written (the one to publish when check.safe())
  CompensationGougeCheck check;  // of that program
  int clip_back_rounds = 0;   // rounds the clip-back ran
  std::vector<ClipBackPoint> clip_back;  // points whose offsets it reduced, in path order
  // With options.rework and a safe full program: what to write instead of it.
  std::optional<ReworkProgram> rework;
  // At the measured points: the deviation, the field, the correction
  // written and the residual expected after it (COMP.json `expected`).
  CompensationExpectation expected;
  std::string json;           // COMP.json's text
};

struct CompensationSources {
  std::string part, comparison, toolpath, out;
  std::string prediction;  // the prediction given apart, empty when none
};

// `program_text` is the program (G-code or APT CL, `format`) of `tools`'
// path as read with `read`; a program that changes tools has each pass
// located, offset, clipped back and checked with its own cutter
// (docs/compensation.md "Programs that change tools"). Throws InputError
// for --rework of a program that changes tools, a comparison of another
// part, or options out of range (naming them). When the z-map check still fails after options.clip_back rounds,
// the result's check is not safe: the caller writes nothing (exit 3).
// `prediction` (may be null): a prediction given apart, whose error at each
// measured point is taken off its deviation before the fit instead of the
// comparison's residual (inspection/comparison_error_field.hpp); checked
// against the part here.
CompensatedProgram compensate_stage(const Part& part, const PathTools& tools, const std::string& program_text,
                                    ProgramFormat format, const ToolpathReadOptions& read,
                                    const ComparisonDocument& comparison, const CompensateOptions& options,
                                    const CompensationSources& names, const Prediction* prediction = nullptr);

// The prediction of a compensated program before it is cut
// (docs/compensation.md "Predicted before it is cut"): `program_text` (what
// compensate writes, `format`) read back under the name `names.toolpath`
// exactly as `furrow predict` reads that file, with the tool `tool` (named
// `tool_source`), and predicted with `options` - so the result is, byte for
// byte, what `furrow predict PART --toolpath COMP --tool TOOL` writes for the
// written file (with `table`, a program that changes tools: `furrow predict
// --tools TABLE`). Throws InputError as parsing, tools_for_path and
// predict_stage do.
PredictedPath predict_compensated(const Part& part, const std::optional<ToolSpec>& tool,
                                  const std::string& tool_source,
                                  const std::optional<std::vector<ToolTableEntry>>& table,
                                  const std::string& table_source, const std::string& program_text,
                                  ProgramFormat format, const ToolpathReadOptions& read,
                                  const PathPredictionOptions& options, const PredictionSources& names,
                                  const StageProgress& progress = {});

}  // namespace furrow
