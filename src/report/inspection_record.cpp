#include "report/inspection_record.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "base/error.hpp"
#include "base/json_fields.hpp"

namespace furrow {

namespace jf = json_fields;
using jf::json;

namespace {

constexpr std::size_t kMaxText = 200;    // one line of a form
constexpr std::size_t kMaxNotes = 2000;  // a paragraph

bool digits(const std::string& s, std::size_t at, std::size_t n) {
  if (at + n > s.size()) return false;
  for (std::size_t i = at; i < at + n; ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}
int value(const std::string& s, std::size_t at, std::size_t n) { return std::stoi(s.substr(at, n)); }

// UTF-8 code points, so that the limit is what a person counts.
std::size_t characters(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

std::string text_member(const json& v, const std::string& where, bool multiline) {
  const std::string s = jf::string(v, where);
  const std::size_t limit = multiline ? kMaxNotes : kMaxText;
  if (characters(s) > limit)
    throw InputError(where + ": longer than " + std::to_string(limit) + " characters (" +
                     std::to_string(characters(s)) + ")");
  for (unsigned char c : s)
    if ((c < 0x20 && !(multiline && (c == '\n' || c == '\t'))) || c == 0x7F)
      throw InputError(where + (multiline ? ": a control character (only line breaks and tabs are allowed)"
                                          : ": a control character or line break (one line of text expected)"));
  return s;
}

std::string date_member(const json& v, const std::string& where) {
  const std::string s = text_member(v, where, false);
  if (!s.empty() && !is_iso8601_date(s))
    throw InputError(where + ": \"" + s + "\" is not an ISO 8601 date (YYYY-MM-DD, optionally Thh:mm[:ss][Z|+hh:mm])");
  return s;
}

RecordTemperature temperature_member(const json& v, const std::string& where) {
  const json& o = jf::object(v, where);
  for (auto it = o.begin(); it != o.end(); ++it)
    if (it.key() != "value" && it.key() != "unit")
      throw InputError(jf::child(where, it.key()) + ": unknown member (expected value and unit)");
  RecordTemperature t;
  t.value = jf::number(jf::member(o, "value", where), jf::child(where, "value"));
  t.unit = jf::string(jf::member(o, "unit", where), jf::child(where, "unit"));
  if (t.unit != "C" && t.unit != "F" && t.unit != "K")
    throw InputError(jf::child(where, "unit") + ": \"" + t.unit + "\" is not a temperature unit (C, F or K)");
  const double c = t.celsius();
  if (!(c >= -50 && c <= 100))
    throw InputError(jf::child(where, "value") + ": " + temperature_text(t) +
                     " lies outside -50..100 degC (a CMM room; is the unit right?)");
  return t;
}

SignOff sign_off_member(const json& v, const std::string& where) {
  const json& o = jf::object(v, where);
  SignOff s;
  for (auto it = o.begin(); it != o.end(); ++it) {
    const std::string at = jf::child(where, it.key());
    if (it.key() == "name")
      s.name = text_member(it.value(), at, false);
    else if (it.key() == "date")
      s.date = date_member(it.value(), at);
    else
      throw InputError(at + ": unknown member (expected name and date)");
  }
  return s;
}

}  // namespace

double RecordTemperature::celsius() const {
  if (unit == "F") return (value - 32) * 5 / 9;
  if (unit == "K") return value - 273.15;
  return value;
}

std::string temperature_text(const RecordTemperature& t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", t.value);
  return std::string(buf) + (t.unit == "K" ? " K" : t.unit == "F" ? " degF" : " degC");
}

bool is_iso8601_date(const std::string& s) {
  if (s.size() < 10 || !digits(s, 0, 4) || s[4] != '-' || !digits(s, 5, 2) || s[7] != '-' || !digits(s, 8, 2))
    return false;
  const int year = value(s, 0, 4), month = value(s, 5, 2), day = value(s, 8, 2);
  static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12 || day < 1) return false;
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  if (day > kDays[month - 1] + (month == 2 && leap)) return false;
  if (s.size() == 10) return true;
  // Time: Thh:mm[:ss], then end, Z or +hh:mm / -hh:mm.
  if (s[10] != 'T' || !digits(s, 11, 2) || s.size() < 16 || s[13] != ':' || !digits(s, 14, 2)) return false;
  if (value(s, 11, 2) > 23 || value(s, 14, 2) > 59) return false;
  std::size_t at = 16;
  if (at < s.size() && s[at] == ':') {
    if (!digits(s, at + 1, 2) || value(s, at + 1, 2) > 59) return false;
    at += 3;
  }
  if (at == s.size()) return true;
  if (s[at] == 'Z') return at + 1 == s.size();
  if (s[at] != '+' && s[at] != '-') return false;
  return s.size() == at + 6 && digits(s, at + 1, 2) && s[at + 3] == ':' && digits(s, at + 4, 2) &&
         value(s, at + 1, 2) <= 14 && value(s, at + 4, 2) <= 59;
}

std::vector<InspectionRecord::Field> InspectionRecord::fields() const {
  std::vector<Field> all = {{"part_number", "Part number", part_number},
                            {"revision", "Revision", revision},
                            {"serial", "Serial number", serial},
                            {"lot", "Lot", lot},
                            {"customer", "Customer", customer},
                            {"operator", "Operator", operator_name},
                            {"cmm", "CMM", cmm},
                            {"probe", "Probe", probe},
                            {"qualification_date", "Probe qualified", qualification_date},
                            {"temperature", "Temperature", temperature ? temperature_text(*temperature) : ""},
                            {"program", "CMM program", program},
                            {"notes", "Notes", notes}};
  std::vector<Field> filled;
  for (Field& f : all)
    if (!f.value.empty()) filled.push_back(std::move(f));
  return filled;
}

bool InspectionRecord::has_sign_off() const {
  for (const SignOff* s : {&prepared, &checked, &approved})
    if (!s->name.empty() || !s->date.empty()) return true;
  return false;
}

InspectionRecord parse_inspection_record(const std::string& text, const std::string& where) {
  // The document's name without the root's colon ("record.json"), as
  // parse_text puts its own after it.
  const json doc = jf::parse_text(text, !where.empty() && where.back() == ':' ? where.substr(0, where.size() - 1) : where);
  const json& o = jf::object(doc, where);
  InspectionRecord r;
  const std::pair<const char*, std::string*> lines[] = {
      {"part_number", &r.part_number}, {"revision", &r.revision}, {"serial", &r.serial},
      {"lot", &r.lot},                 {"customer", &r.customer}, {"operator", &r.operator_name},
      {"cmm", &r.cmm},                 {"probe", &r.probe},       {"program", &r.program}};
  for (auto it = o.begin(); it != o.end(); ++it) {
    const std::string& key = it.key();
    const std::string at = jf::child(where, key);
    if (it.value().is_null()) continue;  // absent, as an empty string
    bool known = false;
    for (const auto& [name, target] : lines)
      if (key == name) {
        *target = text_member(it.value(), at, false);
        known = true;
      }
    if (known) continue;
    if (key == "notes") {
      r.notes = text_member(it.value(), at, true);
    } else if (key == "qualification_date") {
      r.qualification_date = date_member(it.value(), at);
    } else if (key == "temperature") {
      r.temperature = temperature_member(it.value(), at);
    } else if (key == "sign_off") {
      const json& s = jf::object(it.value(), at);
      for (auto jt = s.begin(); jt != s.end(); ++jt) {
        const std::string sat = jf::child(at, jt.key());
        if (jt.key() == "prepared")
          r.prepared = sign_off_member(jt.value(), sat);
        else if (jt.key() == "checked")
          r.checked = sign_off_member(jt.value(), sat);
        else if (jt.key() == "approved")
          r.approved = sign_off_member(jt.value(), sat);
        else
          throw InputError(sat + ": unknown member (expected prepared, checked, approved)");
      }
    } else {
      throw InputError(at + ": unknown member (see docs/formats.md \"Inspection record\")");
    }
  }
  return r;
}

InspectionRecord read_inspection_record(const std::string& path) {
  return parse_inspection_record(jf::read_text(path), path + ":");
}

}  // namespace furrow
