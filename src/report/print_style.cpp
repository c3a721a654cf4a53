#include "report/print_style.hpp"

#include <cstdio>

#include "base/error.hpp"

namespace furrow {

namespace {

// A CSS string literal: quotes, backslashes, "<" and control characters as
// CSS escapes (a hex escape ends with a space).
std::string css_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\' || c == '<' || c == '>' || u < 0x20) {
      char buf[12];
      std::snprintf(buf, sizeof buf, "\\%x ", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::string print_style(const std::string& part, const std::string& title) {
  const std::string font = "font-family:\"DejaVu Sans\",Helvetica,Arial,sans-serif;font-size:8pt;color:#444";
  return "<style>\n@page{size:A4;margin:16mm 11mm 14mm 11mm;"
         "@top-left{content:" + css_string("Part " + part) + ";" + font + "}"
         "@top-right{content:" + css_string("QA report: " + title) + ";" + font + "}"
         "@bottom-right{content:\"Page \" counter(page) \" of \" counter(pages);" + font + "}}\n"
         "@media print{body{max-width:none;padding:0;margin:0;font-size:9.5pt}"
         "nav,.view3d-live{display:none!important}.view3d-static{display:block!important}"
         "thead{display:table-header-group}tr,figure,.verdict,table.kv,table.matrix{break-inside:avoid}"
         "h2,h3{break-after:avoid}table.points{font-size:6.5pt}table.points td,table.points th{padding:1px 3px}"
         "table{font-size:8pt}figure svg,figure img{max-width:100%;height:auto}"
         "figure{display:block}.hash{font-size:6.5pt}pre{white-space:pre-wrap}}\n</style>\n";
}

std::string paper_size_css(const std::string& paper, const std::string& option) {
  if (paper == "a4" || paper == "A4") return "A4";
  if (paper == "letter") return "letter";
  throw InputError(option + ": expected a4 or letter, got \"" + paper + "\"");
}

}  // namespace furrow
