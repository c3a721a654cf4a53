#pragma once
// The inspection record (`--record record.json`, or the `record` section of
// a job file; docs/formats.md "Inspection record"): who and what the QA
// report is about - part number, revision, serial and lot, customer,
// operator, CMM, probe, probe qualification date, temperature, CMM program,
// notes - and the sign-off (prepared / checked / approved, each a name and a
// date). Nothing of it is computed; the report shows it in its header, in
// report.json ("record") and in results.qif (InspectionTraceability).
//
// Checked up front so that nothing a report vouches for is garbage: unknown
// members are refused with the field named (a misspelt "serail" must not
// vanish silently), every text is a single line of at most 200 characters
// (notes: 2000, line breaks allowed) without control characters, dates are
// ISO 8601 calendar dates (2026-11-25, optionally with a time
// 2026-11-25T14:30[:00][Z|+01:00]) that exist, the temperature a finite
// number with its unit (C, F or K) within -50..100 degC. Every failure is an
// InputError naming the file and the member (exit 2). Empty strings count
// as absent, so the report never shows an empty placeholder. Text is stored
// as given; the HTML writer escapes it.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace furrow {

struct RecordTemperature {
  double value = 0;      // as given, in `unit`
  std::string unit;      // "C", "F" or "K"
  double celsius() const;
};

struct SignOff {
  std::string name;  // may be empty: signed by hand on the print-out
  std::string date;  // ISO 8601 as given, may be empty
};

struct InspectionRecord {
  std::string part_number, revision, serial, lot, customer, operator_name, cmm, probe, qualification_date, program,
      notes;
  std::optional<RecordTemperature> temperature;
  SignOff prepared, checked, approved;

  // The filled fields in display order as (member name in the file, label
  // for people, value): the header shows exactly these.
  struct Field {
    const char* key;
    const char* label;
    std::string value;
  };
  std::vector<Field> fields() const;
  bool has_sign_off() const;
};

// Parses record JSON text; `name` stands for the source in messages.
InspectionRecord parse_inspection_record(const std::string& text, const std::string& name);
// Reads and checks a record file.
InspectionRecord read_inspection_record(const std::string& path);

// True for an existing ISO 8601 calendar date, optionally with a time
// (hh:mm or hh:mm:ss, then nothing, Z or an offset +hh:mm / -hh:mm).
bool is_iso8601_date(const std::string& text);

// "20.1 degC" (the unit as given, with its degree name).
std::string temperature_text(const RecordTemperature& t);

}  // namespace furrow
