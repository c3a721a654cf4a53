#include "report/inspection_record_html.hpp"

#include "report/html.hpp"

namespace furrow {

using html::escape;

const char* inspection_record_css() {
  return ".record{display:grid;grid-template-columns:repeat(auto-fill,minmax(220px,1fr));gap:2px 16px;"
         "margin:8px 0;padding:8px 12px;border:1px solid #ccc;border-radius:6px;background:#fafafa}"
         ".record div{overflow-wrap:anywhere}.record .label{color:#555;font-size:0.85em;display:block}"
         ".record .notes{grid-column:1/-1;white-space:pre-wrap}"
         "table.kv td,table.files td{overflow-wrap:anywhere;word-break:break-word}"
         "pre.options{white-space:pre-wrap;overflow-wrap:anywhere;word-break:break-word}"
         "table.signoff{width:100%;margin-top:1em}table.signoff td{height:2.6em;text-align:left;vertical-align:bottom}"
         "table.signoff td.sign{width:40%}"
         "@media print{section#signoff{break-inside:avoid;page-break-inside:avoid}}\n";
}

std::string record_header_html(const std::optional<InspectionRecord>& record) {
  if (!record || record->fields().empty())
    return "<p class=\"meta\" id=\"record-absent\">No inspection record was given (part number, serial, operator, "
           "CMM: <code>--record</code>, docs/report.md).</p>\n";
  std::string out = "<div class=\"record\" id=\"record\">\n";
  for (const InspectionRecord::Field& f : record->fields())
    out += std::string("<div") + (std::string(f.key) == "notes" ? " class=\"notes\"" : "") + " data-field=\"" +
           f.key + "\"><span class=\"label\">" + f.label + "</span>" + escape(f.value) + "</div>\n";
  return out + "</div>\n";
}

std::string sign_off_html(const std::optional<InspectionRecord>& record) {
  const SignOff none;
  std::string out = "<section id=\"signoff\"><h2>Sign-off</h2>\n<table class=\"signoff\"><thead><tr><th></th><th>Name"
                    "</th><th>Date</th><th>Signature</th></tr></thead><tbody>\n";
  const std::pair<const char*, const SignOff*> roles[] = {
      {"Prepared", record ? &record->prepared : &none},
      {"Checked", record ? &record->checked : &none},
      {"Approved", record ? &record->approved : &none}};
  for (const auto& [role, s] : roles)
    out += std::string("<tr><th>") + role + "</th><td>" + escape(s->name) + "</td><td>" + escape(s->date) +
           "</td><td class=\"sign\"></td></tr>\n";
  return out + "</tbody></table>\n</section>\n";
}

}  // namespace furrow
