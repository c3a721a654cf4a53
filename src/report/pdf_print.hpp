#pragma once
// report.pdf: report.html printed to a paginated PDF by headless Chromium
// (`furrow report --pdf`, `"pdf": true` in a job). The page's own print CSS
// (print_style.hpp) sets the header with part and report on every page,
// page numbers and clean table breaks; Chromium's own header and footer
// (date, file URL) are switched off.
//
// Chromium runs as a child process (fork/exec, no shell: paths with any
// characters are safe) with a fresh profile in a temporary folder, no
// sandbox (needed as root), no GPU, and a time limit; its output goes to a
// log whose tail is quoted when it fails.
//
// Failure: InputError when Chromium is missing (the message says which
// package to install) or the paper is not a4/letter; std::runtime_error
// when Chromium fails, times out or writes no PDF. The PDF bytes are not
// reproducible: Chromium writes the creation date into them (the HTML is).
#include <string>

namespace furrow {

struct PdfOptions {
  std::string paper = "a4";                 // "a4" or "letter"
  std::string chromium = "/usr/bin/chromium";
  int timeout_seconds = 180;
};

// Prints the HTML file `html_path` to `pdf_path` (overwritten).
void print_pdf(const std::string& html_path, const std::string& pdf_path, const PdfOptions& options = {});

}  // namespace furrow
