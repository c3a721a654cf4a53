#pragma once
// How report.html prints (a browser's Print, and `furrow report --pdf`
// through headless Chromium, pdf_print.hpp): A4 pages by default, a running
// header on every page naming the part and the report (its title: the job's
// name or the report folder's; report.html adds the part number and the
// serial or lot of the inspection record when it has them), "Page
// N of M" at the foot, table rows never cut between pages (a row moves to
// the next page whole) with the column heads repeated, figures and the
// verdict kept on one page, navigation and interactive parts hidden (the
// 3D view prints its static view).
//
// CSS paged media margin boxes (@top-left, @bottom-right with
// counter(page)/counter(pages)), which Chromium prints since version 131.
// The texts are escaped for a CSS string inside <style> (no "</style>" can
// occur). Deterministic.
#include <string>

namespace furrow {

// A <style> element for the page's <head>.
std::string print_style(const std::string& part, const std::string& title);

// The paper sizes `furrow report --pdf` offers: "a4" and "letter".
// Returns the CSS @page size value ("A4", "letter"); throws InputError
// naming `option` for anything else.
std::string paper_size_css(const std::string& paper, const std::string& option);

}  // namespace furrow
