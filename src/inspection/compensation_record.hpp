#pragma once
// COMP.json read back: what `furrow compensate` (or a job's compensate
// stage) wrote beside its program (docs/formats.md "Compensation record"),
// as far as the QA report shows it (docs/report.md "Compensation"): the
// options, what limited the corrections (clipped, cut back against a gouge,
// unreachable, reduced by the clip-back) and `expected`, the residual the
// written program is expected to leave at every measured point, with its
// statistics per region and overall (inspection/compensation_expectation).
//
// Why the report reads the record rather than compensating again: the
// record describes the program that was written; compensating again could
// only describe another one (other options, another program file).
//
// Every member of the record is known to the reader: the ones the report
// does not show are skipped by name, and an unknown member is refused, so
// a record of another format is not half-read. Errors are InputErrors
// naming the file and the member ("COMP.json: expected.points[3].residual:
// expected a number, found null").
#include <optional>
#include <string>

#include "inspection/comparison_document.hpp"
#include "inspection/compensation_expectation.hpp"

namespace furrow {

struct CompensationRecord {
  std::string comparison, toolpath, program;  // the files as the record names them
  double gain = 1, max_offset = 0;             // max_offset [mm]
  std::optional<double> smoothing;             // [mm]; none: chosen by GCV ("auto")
  bool prediction_removed = false;
  std::size_t samples = 0;
  std::size_t moves_moved = 0, no_contact = 0, in_air = 0;
  double largest_offset = 0;  // [mm]
  // Points whose correction was limited, by cause (each listed in the record).
  std::size_t clipped = 0, gouge_clipped = 0, unreachable = 0;
  std::size_t clip_back_points = 0;  // reduced by the z-map clip-back
  int clip_back_rounds = 0;
  // With --rework: the program written re-cuts only where material is left.
  struct Rework {
    double threshold = 0;  // [mm]
    std::size_t moves = 0, moves_kept = 0, stretches = 0;
  };
  std::optional<Rework> rework;
  CompensationExpectation expected;  // ExpectedPoint::index is not in the file: set by check_record_against
};

// Parses a record; `name` stands for the source in messages.
CompensationRecord parse_compensation_record(const std::string& text, const std::string& name);
CompensationRecord read_compensation_record(const std::string& path);

// Throws InputError (naming `name` and the point) unless the record is of
// `comparison`: every expected point an evaluated point of it with the same
// deviation, and every evaluated point in the record. Sets each expected
// point's `index` into comparison.points.
void check_record_against(CompensationRecord& record, const ComparisonDocument& comparison, const std::string& name);

}  // namespace furrow
